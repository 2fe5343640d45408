// Tool Power: the power a contact wall's moving tool delivers to the material,
//   P_w = ∫ t·v_w ds ≈ − Σ_k R_k·v_w(x_k),
// R_k the wall's part of node k's momentum residual (the force the material exerts on the tool,
// WallPowers.hpp) and −R_k the force the tool applies to the material. 0 for a fixed tool.
// With it the discrete power balance of a case with moving tools reads
//   Σ Boundary Power (velocity-driven groups) + Σ Tool Power = Plastic + Friction + Penalty + Stabilization Power
// to the solver's tolerance (docs/theory.md §2 "Moving tools": R_k·u = R_k·(u − v_w) + R_k·v_w).
// For a rotating tool P_w = ω T, T its Tool Torque.
#pragma once

#include "flowform/responses/WallPowers.hpp"

namespace flowform {

struct ToolPower {
  static constexpr const char* kName = "Tool Power";
  static constexpr const char* kDescription =
      "the power a contact wall's tool delivers to the material, -sum R_k.v_w(x_k) (0 for a fixed tool)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the contact wall"); }
  explicit ToolPower(const Teuchos::ParameterList& p) : m_wall(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return sumOverWallNodes(c, m_wall, [&](Scalar& local, const ContactWall& wall, int k,
                                           const FrictionParameters<Scalar>&, const Scalar*, const Scalar* Rk) {
      const auto& vw = wall.wallVelocity(k);
      local -= Rk[0] * vw[0] + Rk[1] * vw[1];
    });
  }

 private:
  std::string m_wall;
};

}  // namespace flowform
