// Linear triangle (P1) and bilinear quadrilateral (Q1) shape functions and the quadrature
// rules the flow kernel uses. Plain double: geometry is never differentiated.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// The most nodes a cell of any element type has (kCellTypes): sizes per-cell arrays.
constexpr int maxNodesPerCell() {
  int n = 0;
  for (CellType type : kCellTypes) n = nodesPerCell(type) > n ? nodesPerCell(type) : n;
  return n;
}
constexpr int kMaxNodesPerCell = maxNodesPerCell();
constexpr int kMaxQuadraturePoints = 4;

/// Values, physical gradients and weights (|det J| × reference weight) of the shape functions
/// at the quadrature points of one cell.
struct CellQuadrature {
  int numNodes = 0;
  int numPoints = 0;
  double N[kMaxQuadraturePoints][kMaxNodesPerCell] = {};
  double dNdx[kMaxQuadraturePoints][kMaxNodesPerCell] = {};
  double dNdy[kMaxQuadraturePoints][kMaxNodesPerCell] = {};
  double x[kMaxQuadraturePoints] = {};  ///< physical coordinates of the points
  double y[kMaxQuadraturePoints] = {};
  double weight[kMaxQuadraturePoints] = {};
  double area = 0.0;
};

/// Reference shape functions and derivatives at (xi, eta): triangle on the unit simplex
/// (N = 1-ξ-η, ξ, η), quadrilateral on [-1,1]² (N = ¼(1±ξ)(1±η), counter-clockwise).
inline void referenceShape(CellType type, double xi, double eta, double* N, double* dNdxi,
                           double* dNdeta) {
  if (type == CellType::Triangle3) {
    N[0] = 1.0 - xi - eta; N[1] = xi; N[2] = eta;
    dNdxi[0] = -1.0; dNdxi[1] = 1.0; dNdxi[2] = 0.0;
    dNdeta[0] = -1.0; dNdeta[1] = 0.0; dNdeta[2] = 1.0;
  } else {
    static constexpr double sx[4] = {-1.0, 1.0, 1.0, -1.0};
    static constexpr double sy[4] = {-1.0, -1.0, 1.0, 1.0};
    for (int a = 0; a < 4; ++a) {
      N[a] = 0.25 * (1.0 + sx[a] * xi) * (1.0 + sy[a] * eta);
      dNdxi[a] = 0.25 * sx[a] * (1.0 + sy[a] * eta);
      dNdeta[a] = 0.25 * sy[a] * (1.0 + sx[a] * xi);
    }
  }
}

/// Quadrature points of a rule: `order` 1 is the centroid (exact for P1 plane-strain
/// terms, which are constant); 2 is the 3-point interior rule on triangles (exact for
/// quadratics) and 2×2 Gauss on quadrilaterals.
inline int referenceRule(CellType type, int order, double* xi, double* eta, double* w) {
  if (type == CellType::Triangle3) {
    if (order <= 1) {
      xi[0] = eta[0] = 1.0 / 3.0; w[0] = 0.5;
      return 1;
    }
    const double a = 1.0 / 6.0, b = 2.0 / 3.0;
    xi[0] = a; eta[0] = a; xi[1] = b; eta[1] = a; xi[2] = a; eta[2] = b;
    w[0] = w[1] = w[2] = 1.0 / 6.0;
    return 3;
  }
  if (order <= 1) {
    xi[0] = eta[0] = 0.0; w[0] = 4.0;
    return 1;
  }
  const double g = 1.0 / std::sqrt(3.0);
  const double gx[4] = {-g, g, g, -g}, gy[4] = {-g, -g, g, g};
  for (int q = 0; q < 4; ++q) { xi[q] = gx[q]; eta[q] = gy[q]; w[q] = 1.0; }
  return 4;
}

/// Fills `cq` for the cell with node coordinates `xy` (counter-clockwise). Returns false
/// when a Jacobian determinant is not positive (inverted or degenerate cell).
inline bool computeCellQuadrature(CellType type, const std::array<double, 2>* xy, int order,
                                  CellQuadrature& cq) {
  double xi[kMaxQuadraturePoints], eta[kMaxQuadraturePoints], w[kMaxQuadraturePoints];
  cq.numNodes = nodesPerCell(type);
  cq.numPoints = referenceRule(type, order, xi, eta, w);
  cq.area = 0.0;
  for (int q = 0; q < cq.numPoints; ++q) {
    double dNdxi[kMaxNodesPerCell], dNdeta[kMaxNodesPerCell];
    referenceShape(type, xi[q], eta[q], cq.N[q], dNdxi, dNdeta);
    double J00 = 0, J01 = 0, J10 = 0, J11 = 0, px = 0, py = 0;
    for (int a = 0; a < cq.numNodes; ++a) {
      J00 += dNdxi[a] * xy[a][0]; J01 += dNdxi[a] * xy[a][1];
      J10 += dNdeta[a] * xy[a][0]; J11 += dNdeta[a] * xy[a][1];
      px += cq.N[q][a] * xy[a][0]; py += cq.N[q][a] * xy[a][1];
    }
    const double det = J00 * J11 - J01 * J10;
    if (!(det > 0.0)) return false;
    for (int a = 0; a < cq.numNodes; ++a) {
      // [dN/dx, dN/dy] = J^{-1} [dN/dξ, dN/dη], J = [[x_ξ, y_ξ], [x_η, y_η]]
      cq.dNdx[q][a] = (J11 * dNdxi[a] - J01 * dNdeta[a]) / det;
      cq.dNdy[q][a] = (-J10 * dNdxi[a] + J00 * dNdeta[a]) / det;
    }
    cq.x[q] = px; cq.y[q] = py;
    cq.weight[q] = w[q] * det;
    cq.area += cq.weight[q];
  }
  return true;
}

/// The element size h_K of the stabilization: the cell's diameter (longest edge of a
/// triangle, longest diagonal of a quadrilateral). A square split into two right
/// triangles and the square itself get the same h_K.
inline double cellDiameter(CellType type, const std::array<double, 2>* xy) {
  auto dist = [&](int a, int b) { return std::hypot(xy[a][0] - xy[b][0], xy[a][1] - xy[b][1]); };
  if (type == CellType::Triangle3) return std::max({dist(0, 1), dist(1, 2), dist(2, 0)});
  return std::max(dist(0, 2), dist(1, 3));
}

}  // namespace flowform
