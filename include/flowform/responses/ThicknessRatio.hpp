// Thickness Ratio: r = t / w for the stream leaving through the group: its mean velocity
//   ū = Σ_k u_k ∫N_k ds / ∫ds,
// its thickness normal to ū, w = |Δx × ū| / |ū| (Δx the chord between the group's ends; a chip's
// outlet that the chip crosses at a slant is longer than the chip is thick), t the Reference
// Thickness. Cutting: t/t_c, the chip ratio at the chip's outlet; mass balance makes it the chip's
// speed over the cutting speed for a uniform stream.
#pragma once

#include <cmath>
#include <vector>

#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

/// r = t |ū| / |Δx × ū| of the stream leaving through group `boundary`.
template <typename Scalar>
Scalar streamThicknessRatio(const ResponseContext<Scalar>& c, const std::string& boundary, double referenceThickness) {
  const Mesh& mesh = c.mesh;
  const Comm& comm = *c.dofMap.comm();
  const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(boundary));
  const size_t numNodes = curve.nodes.size();
  std::vector<double> w(numNodes, 0.0);
  for (size_t sgm = 0; sgm < curve.segmentLength.size(); ++sgm) {
    w[sgm] += 0.5 * curve.segmentLength[sgm];
    w[(sgm + 1) % numNodes] += 0.5 * curve.segmentLength[sgm];
  }
  Scalar ux = 0.0, uy = 0.0;
  for (size_t k = 0; k < numNodes; ++k) {
    const LO n = c.dofMap.overlapIndex(curve.nodes[k]);
    if (!c.dofMap.ownsNode(n)) continue;
    ux += w[k] * c.u(c.x, n, kUx);
    uy += w[k] * c.u(c.x, n, kUy);
  }
  ux = sumOverRanks(comm, ux);
  uy = sumOverRanks(comm, uy);
  const auto& a = mesh.coords[curve.nodes.front()];
  const auto& b = mesh.coords[curve.nodes.back()];
  Scalar cross = (b[0] - a[0]) * uy - (b[1] - a[1]) * ux;
  if (cross < 0.0) cross = -cross;
  const Scalar ratio = referenceThickness * std::sqrt(ux * ux + uy * uy) / cross;
  return ratio;
}

/// "Reference Thickness" (Thickness Ratio, Shear Angle).
void declareReferenceThickness(Teuchos::ParameterList& list);

struct ThicknessRatio {
  static constexpr const char* kName = "Thickness Ratio";
  static constexpr const char* kDescription =
      "t / w: t the Reference Thickness, w the thickness of the stream leaving through the group, normal to its "
      "mean velocity (cutting's chip ratio t/t_c at the chip's outlet)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the group a stream leaves through, e.g. a chip's outlet");
    declareReferenceThickness(list);
  }
  explicit ThicknessRatio(const Teuchos::ParameterList& p)
      : m_boundary(p.get<std::string>("Boundary")), m_referenceThickness(p.get<double>("Reference Thickness")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return streamThicknessRatio(c, m_boundary, m_referenceThickness);
  }

 private:
  std::string m_boundary;
  double m_referenceThickness;
};

}  // namespace flowform
