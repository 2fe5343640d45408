// Mean Pressure: p̄ = −Σ_i R_i·n_i / A over the group, the mean normal pressure the tool applies
// (n_i the outward nodal normal, A the group's length, or the area ∫ 2πr ds when axisymmetric).
// Linear in the reactions (c = −n/A): an adaptivity target.
#pragma once

#include "flowform/responses/ReactionSums.hpp"

namespace flowform {

struct MeanPressure {
  static constexpr const char* kName = "Mean Pressure";
  static constexpr const char* kDescription =
      "-sum R_i.n_i / A over the group: the mean normal pressure the tool applies (A its length, or area 2 pi r ds "
      "when axisymmetric)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = true, kAdaptivityTarget = true,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the group the tool acts on"); }
  explicit MeanPressure(const Teuchos::ParameterList& p) : m_boundary(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const BoundaryCurve curve = buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary));
    Scalar value = sumOfReactions(c, curve, [&](Scalar& local, size_t k, LO, const Scalar& Rx, const Scalar& Ry) {
      local -= Rx * curve.normals[k][0] + Ry * curve.normals[k][1];
    });
    value /= curveArea(c.mesh, curve, c.geometry());
    return value;
  }

  /// c = −n/A on the group's owned nodes.
  void reactionWeights(const Mesh& mesh, const DofMap& dofMap, Geometry geometry, HostViewRW& view) const {
    const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(m_boundary));
    const double area = curveArea(mesh, curve, geometry);
    for (size_t k = 0; k < curve.nodes.size(); ++k) {
      const LO n = dofMap.overlapIndex(curve.nodes[k]);
      if (!dofMap.ownsNode(n)) continue;  // owned dofs are the overlap's first ones
      view(dofMap.dof(n, kUx), 0) = -curve.normals[k][0] / area;
      view(dofMap.dof(n, kUy), 0) = -curve.normals[k][1] / area;
    }
  }

 private:
  std::string m_boundary;
};

}  // namespace flowform
