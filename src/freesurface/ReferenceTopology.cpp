#include "flowform/freesurface/ReferenceTopology.hpp"

#include <cmath>

#include "flowform/core/InputError.hpp"
#include "flowform/freesurface/MeshMotion.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/mesh/MeshReader.hpp"

namespace flowform {

namespace {

/// The indices of the curve's ends and corners, in order.
std::vector<std::size_t> cornersOf(const Mesh& mesh, const BoundaryCurve& curve) {
  std::vector<std::size_t> corners{0};
  const double limit = std::cos(kCornerAngle * M_PI / 180.0);
  for (std::size_t k = 1; k + 1 < curve.nodes.size(); ++k) {
    const auto& a = mesh.coords[curve.nodes[k - 1]];
    const auto& b = mesh.coords[curve.nodes[k]];
    const auto& c = mesh.coords[curve.nodes[k + 1]];
    const double u[2] = {b[0] - a[0], b[1] - a[1]}, v[2] = {c[0] - b[0], c[1] - b[1]};
    const double cosine = (u[0] * v[0] + u[1] * v[1]) / (std::hypot(u[0], u[1]) * std::hypot(v[0], v[1]));
    if (cosine < limit) corners.push_back(k);
  }
  corners.push_back(curve.nodes.size() - 1);
  return corners;
}

/// The point at arc length s along the target curve's nodes [first, last].
std::array<double, 2> pointAt(const Mesh& mesh, const BoundaryCurve& curve, std::size_t first, std::size_t last,
                              double s) {
  std::size_t k = first;
  while (k + 1 < last && curve.arcLength[k + 1] < s) ++k;
  const double length = curve.arcLength[k + 1] - curve.arcLength[k];
  const double t = length > 0.0 ? std::clamp((s - curve.arcLength[k]) / length, 0.0, 1.0) : 0.0;
  const auto& a = mesh.coords[curve.nodes[k]];
  const auto& b = mesh.coords[curve.nodes[k + 1]];
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
}

}  // namespace

std::vector<std::array<double, 2>> followShape(const Mesh& reference, const Mesh& target) {
  std::vector<std::array<double, 2>> displacement(reference.numNodes(), {0.0, 0.0});
  std::vector<char> prescribed(reference.numNodes(), 0);
  for (const BoundaryGroup& group : reference.boundaries) {
    const std::string where = "Mesh/Reference Geo Parameters: boundary group '" + group.name + "'";
    if (!target.hasBoundary(group.name)) throw InputError(where + " is not in the mesh at the Geo Parameters");
    const BoundaryCurve here = buildBoundaryCurve(reference, group);
    const BoundaryCurve there = buildBoundaryCurve(target, target.boundary(group.name));
    if (here.closed || there.closed)
      throw InputError(where + " is a closed curve: its nodes have no first one to follow from");
    const auto hereCorners = cornersOf(reference, here), thereCorners = cornersOf(target, there);
    if (hereCorners.size() != thereCorners.size())
      throw InputError(where + " has " + std::to_string(hereCorners.size() - 2) + " corner(s) in the reference and " +
                       std::to_string(thereCorners.size() - 2) + " at the Geo Parameters: its nodes cannot follow it");
    for (std::size_t c = 0; c + 1 < hereCorners.size(); ++c) {
      const std::size_t a = hereCorners[c], b = hereCorners[c + 1], A = thereCorners[c], B = thereCorners[c + 1];
      const double length = here.arcLength[b] - here.arcLength[a];
      const double targetLength = there.arcLength[B] - there.arcLength[A];
      for (std::size_t k = a; k <= b; ++k) {
        const double fraction = length > 0.0 ? (here.arcLength[k] - here.arcLength[a]) / length : 0.0;
        const auto to = pointAt(target, there, A, B, there.arcLength[A] + fraction * targetLength);
        const GO n = here.nodes[k];
        displacement[n] = {to[0] - reference.coords[n][0], to[1] - reference.coords[n][1]};
        prescribed[n] = 1;
      }
    }
  }
  return extendBoundaryDisplacement(reference, displacement, prescribed);
}

bool hasReferenceTopology(const Teuchos::ParameterList& meshParams) {
  return meshParams.isSublist(kReferenceGeoParameters) && meshParams.sublist(kReferenceGeoParameters).numParams() > 0;
}

Mesh readMeshOnReference(const Teuchos::ParameterList& meshParams, const std::string& baseDir,
                         const Teuchos::Comm<int>& comm, const SizeField* sizeField) {
  if (!hasReferenceTopology(meshParams)) return readMesh(meshParams, baseDir, comm, sizeField);
  Teuchos::ParameterList referenceParams = meshParams;
  const Teuchos::ParameterList& reference = meshParams.sublist(kReferenceGeoParameters);
  for (auto it = reference.begin(); it != reference.end(); ++it)
    referenceParams.sublist("Geo Parameters").setEntry(reference.name(it), reference.entry(it));
  referenceParams.remove(kReferenceGeoParameters);
  Teuchos::ParameterList targetParams = meshParams;
  targetParams.remove(kReferenceGeoParameters);
  Mesh mesh = readMesh(referenceParams, baseDir, comm, sizeField);
  const Mesh target = readMesh(targetParams, baseDir, comm, sizeField);
  mesh.setCoordinates(followShape(mesh, target));  // InputError if the move inverts a cell
  return mesh;
}

}  // namespace flowform
