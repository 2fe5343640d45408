// Which cell of a mesh holds a point, and the cell's shape-function values there: what
// carries a nodal field from one mesh to another (a uniformly refined copy, a remeshed one).
//
// Cells are binned on a uniform grid of about one cell per bin (their bounding boxes); a query
// looks in its bin, then in rings of bins around it. A point no cell holds (round-off on a
// straight boundary, or a curved boundary meshed anew) gets the nearest cell found, with its
// shape-function values clamped to that cell (the closest point of it, for triangles).
#pragma once

#include <array>
#include <vector>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// A point's cell and the values there of the cell's shape functions (P1 barycentric
/// coordinates, or Q1 bilinear functions), in the cell's node order; they sum to 1.
struct CellPoint {
  GO cell = -1;
  std::array<double, 4> weights{};
  bool inside = false;  ///< false: the point lies outside every cell (clamped to the nearest)
};

class PointLocator {
 public:
  explicit PointLocator(const Mesh& mesh);
  CellPoint locate(const std::array<double, 2>& x) const;

 private:
  /// The shape-function values of cell c at x (clamped when x is outside) and how far outside
  /// x lies in reference coordinates (0 inside).
  double weightsIn(GO c, const std::array<double, 2>& x, std::array<double, 4>& w) const;
  int binOf(double v, double lo, double size, int count) const;

  const Mesh& m_mesh;
  double m_x0 = 0, m_y0 = 0, m_dx = 1, m_dy = 1;
  int m_nx = 1, m_ny = 1;
  std::vector<std::vector<GO>> m_bins;  ///< cells whose bounding box touches the bin
};

}  // namespace flowform
