// Boundary Force: F = Σ_i R_i·e over the group's nodes, the reaction (the force the tool applies to
// the material) in component e = X or Y. Per unit depth in plane strain (for the modelled half when
// symmetric), total in axisymmetric models. Linear in the reactions: F = c·R_unc(x) with c = e on
// the group's nodes, so its adjoint gives the error indicators of the adaptive loop.
// With Per Area, F / A (A the group's length, or its area ∫ 2πr ds when axisymmetric): the mean
// traction, e.g. the drawing stress of a wire pulled through its outlet (c = e/A).
#pragma once

#include "flowform/responses/ReactionSums.hpp"

namespace flowform {

struct BoundaryForce {
  static constexpr const char* kName = "Boundary Force";
  static constexpr const char* kDescription =
      "the reaction summed over the group's nodes (the force the tool applies to the material), component X or Y";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = true, kAdaptivityTarget = true,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the group the tool acts on");
    declareComponent(list, "the force component");
    list.set("Per Area", false,
             "Boundary Force: divide by the group's length (area 2 pi r ds when axisymmetric): the mean traction");
  }
  explicit BoundaryForce(const Teuchos::ParameterList& p)
      : m_boundary(p.get<std::string>("Boundary")), m_component(componentIndex(p)), m_perArea(p.get<bool>("Per Area")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const BoundaryCurve curve = buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary));
    const Scalar force = sumOfReactions(c, curve, [&](Scalar& local, size_t, LO, const Scalar& Rx, const Scalar& Ry) {
      local += m_component == 0 ? Rx : Ry;
    });
    return m_perArea ? Scalar(force / curveArea(c.mesh, curve, c.geometry())) : force;
  }

  /// c = e (e/A with Per Area) on the group's owned nodes.
  void reactionWeights(const Mesh& mesh, const DofMap& dofMap, Geometry geometry, HostViewRW& view) const {
    const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(m_boundary));
    const double weight = m_perArea ? 1.0 / curveArea(mesh, curve, geometry) : 1.0;
    for (size_t k = 0; k < curve.nodes.size(); ++k) {
      const LO n = dofMap.overlapIndex(curve.nodes[k]);
      if (!dofMap.ownsNode(n)) continue;  // owned dofs are the overlap's first ones
      view(dofMap.dof(n, m_component == 0 ? kUx : kUy), 0) = weight;
    }
  }

 private:
  std::string m_boundary;
  int m_component;
  bool m_perArea;
};

}  // namespace flowform
