// Flow Rate: Q = ∫_Γ u·n dΓ over the group (n outward; dΓ = 2πr ds when axisymmetric): the volume
// flux leaving through it (negative where material enters). With u linear on each segment,
//   Q = Σ_k u_k·w_k,  w_k = Σ_segments n_s ∫ N_k dΓ   (n_s the segment's outward normal).
#pragma once

#include <array>
#include <vector>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

struct FlowRate {
  static constexpr const char* kName = "Flow Rate";
  static constexpr const char* kDescription =
      "integral of u.n over the group (n outward; 2 pi r axisymmetric): the volume flux leaving through it "
      "(negative where material enters)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the group the flux crosses"); }
  explicit FlowRate(const Teuchos::ParameterList& p) : m_boundary(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return through(c, buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary)));
  }

  /// Q through `curve`, summed over the ranks.
  template <typename Scalar>
  static Scalar through(const ResponseContext<Scalar>& c, const BoundaryCurve& curve) {
    const auto w = fluxWeights(c.mesh, curve, c.geometry());
    Scalar local = 0.0;
    for (size_t k = 0; k < curve.nodes.size(); ++k) {  // each node by its owner
      const LO n = c.dofMap.overlapIndex(curve.nodes[k]);
      if (!c.dofMap.ownsNode(n)) continue;
      local += w[k][0] * c.u(c.x, n, kUx) + w[k][1] * c.u(c.x, n, kUy);
    }
    return sumOverRanks(*c.dofMap.comm(), local);
  }

  /// w_k = Σ_segments n_s ∫ N_k dΓ at each node of `curve`: Q = Σ_k u_k·w_k.
  static std::vector<std::array<double, 2>> fluxWeights(const Mesh& mesh, const BoundaryCurve& curve, Geometry geometry) {
    const size_t numNodes = curve.nodes.size();
    std::vector<std::array<double, 2>> w(numNodes, {0.0, 0.0});
    for (size_t sgm = 0; sgm < curve.segmentLength.size(); ++sgm) {
      const size_t a = sgm, b = (sgm + 1) % numNodes;
      const auto& normal = curve.segmentNormals[sgm];
      integrateSegment(mesh.coords[curve.nodes[a]], mesh.coords[curve.nodes[b]], geometry,
                       [&](double Na, double Nb, double ws) {
        for (int d = 0; d < 2; ++d) {
          w[a][d] += Na * ws * normal[d];
          w[b][d] += Nb * ws * normal[d];
        }
      });
    }
    return w;
  }

 private:
  std::string m_boundary;
};

}  // namespace flowform
