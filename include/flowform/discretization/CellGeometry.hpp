// The geometry of one cell as every cell loop needs it, computed in one place: node
// coordinates, the integration rule of the flow kernel, the one-point centroid rule, the
// diameter h_K, and the measure dΩ (with 2π r when axisymmetric).
//
// Nothing here is cached: the coordinates are read from the mesh on every call, so a mesh
// whose nodes move (Mesh::setCoordinates) is seen at once by every loop.
#pragma once

#include <array>
#include <cmath>

#include "flowform/core/Types.hpp"
#include "flowform/discretization/ShapeFunctions.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// Integration order of the flow kernel (and of the responses, which must integrate the
/// same discrete terms): P1 in plane strain has constant integrands (one point is exact);
/// the axisymmetric terms (u_r/r, 2πr) and Q1 need the 3-point / 2×2 rules.
inline int integrationOrder(CellType type, Geometry geometry) {
  return (type == CellType::Triangle3 && geometry == Geometry::PlaneStrain) ? 1 : 2;
}

/// Integration weight of point q, with the 2π r of the axisymmetric measure.
inline double measureWeight(const CellQuadrature& cq, int q, Geometry geometry) {
  return geometry == Geometry::Axisymmetric ? 2.0 * M_PI * cq.x[q] * cq.weight[q] : cq.weight[q];
}

struct CellGeometry {
  std::array<double, 2> xy[kMaxNodesPerCell];
  CellQuadrature rule;      ///< the kernel's rule (integrationOrder)
  CellQuadrature centroid;  ///< one point at the centroid (μ_K of the stabilization, cell values)
  double diameter = 0.0;    ///< h_K
};

/// Fills `g` for mesh cell `cell`. The mesh reader rejects inverted cells (and moving the
/// nodes is checked where they move), so the determinants are positive here.
inline void computeCellGeometry(const Mesh& mesh, GO cell, Geometry geometry, CellGeometry& g) {
  const int npc = nodesPerCell(mesh.cellType);
  for (int a = 0; a < npc; ++a) g.xy[a] = mesh.coords[mesh.cell(cell)[a]];
  computeCellQuadrature(mesh.cellType, g.xy, integrationOrder(mesh.cellType, geometry), g.rule);
  computeCellQuadrature(mesh.cellType, g.xy, 1, g.centroid);
  g.diameter = cellDiameter(mesh.cellType, g.xy);
}

/// ∫ over the straight segment a→b of f(N_a, N_b) W ds by 2-point Gauss, W = 2π r when
/// axisymmetric (r linear along the segment), 1 in plane strain: exact for integrands of
/// degree ≤ 3 in s, i.e. products of up to three linear functions (N, p_h, r). `f` is called
/// with (N_a, N_b, w) at each point, w = the point's weight × |ab| × W.
template <typename F>
void integrateSegment(const std::array<double, 2>& a, const std::array<double, 2>& b, Geometry geometry, F&& f) {
  const double gp[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
  for (double s : gp) {
    const double Na = 1.0 - s, Nb = s;
    double w = 0.5 * length;
    if (geometry == Geometry::Axisymmetric) w *= 2.0 * M_PI * (Na * a[0] + Nb * b[0]);
    f(Na, Nb, w);
  }
}

/// The same rule on the part [s0, s1] of the segment a–b (s = 0 at a, 1 at b; s0, s1 may be AD
/// types): f(N_a, N_b, w) at the two Gauss points of the part, w = ½ L (s1 − s0) (× 2π r).
template <typename S, typename F>
void integrateSegmentPart(const std::array<double, 2>& a, const std::array<double, 2>& b, const S& s0, const S& s1,
                          Geometry geometry, F&& f) {
  const double gp[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
  for (double xi : gp) {
    const S s = s0 + (s1 - s0) * xi;
    const S Na = 1.0 - s, Nb = s;
    S w = 0.5 * length * (s1 - s0);
    if (geometry == Geometry::Axisymmetric) w *= 2.0 * M_PI * (Na * a[0] + Nb * b[0]);
    f(Na, Nb, w);
  }
}

}  // namespace flowform
