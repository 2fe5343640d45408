// Boundary Power: P = Σ_i R_i·u_i over the group, the power the tool puts in. The discrete power
// balance Σ_tools Boundary Power = Plastic + Friction + Penalty + Stabilization Power holds to the
// solver's tolerance.
#pragma once

#include "flowform/responses/ReactionSums.hpp"

namespace flowform {

struct BoundaryPower {
  static constexpr const char* kName = "Boundary Power";
  static constexpr const char* kDescription = "sum R_i.u_i over the group: the power the tool puts in";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = true, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the group the tool acts on"); }
  explicit BoundaryPower(const Teuchos::ParameterList& p) : m_boundary(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const BoundaryCurve curve = buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary));
    return sumOfReactions(c, curve, [&](Scalar& local, size_t, LO n, const Scalar& Rx, const Scalar& Ry) {
      local += Rx * c.u(c.x, n, kUx) + Ry * c.u(c.x, n, kUy);
    });
  }

 private:
  std::string m_boundary;
};

}  // namespace flowform
