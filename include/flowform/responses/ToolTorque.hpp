// Tool Torque: the torque about the wall's Rotation Centre c of the force its tool applies to the
// material (counter-clockwise positive, per unit depth in plane strain),
//   T = Σ_k (x_k − c) × (−R_k) = − Σ_k [(x_k − c_x) R_k,y − (y_k − c_y) R_k,x],
// R_k the force the material exerts on the tool at node k (WallPowers.hpp). It is the torque that
// drives a roll: for a rotating tool Tool Power = ω T (v_w = ω e_z × (x − c)). Plane strain only
// (an axisymmetric tool has no torque in the r-z plane).
#pragma once

#include "flowform/responses/WallPowers.hpp"

namespace flowform {

struct ToolTorque {
  static constexpr const char* kName = "Tool Torque";
  static constexpr const char* kDescription =
      "the torque about the wall's Rotation Centre of the force its tool applies to the material (counter-clockwise "
      "positive; a roll's driving torque, Tool Power = omega T)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the contact wall"); }
  explicit ToolTorque(const Teuchos::ParameterList& p) : m_wall(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return sumOverWallNodes(c, m_wall, [&](Scalar& local, const ContactWall& wall, int k,
                                           const FrictionParameters<Scalar>&, const Scalar*, const Scalar* Rk) {
      const auto& x = wall.nodeCoordinates(k);
      const auto& centre = wall.motion().centre;
      local -= (x[0] - centre[0]) * Rk[1] - (x[1] - centre[1]) * Rk[0];
    });
  }

 private:
  std::string m_wall;
};

}  // namespace flowform
