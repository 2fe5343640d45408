// The mesh as flowform uses it: nodes, cells of one type, and named boundary and region
// groups (gmsh physical groups). Replicated on every rank: a 2-D mesh of 10^6 dofs is a
// few tens of MB, and replication keeps partitioning and output simple. Which cells a
// rank assembles is decided by the partition (Partition.hpp), not here.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "flowform/core/Types.hpp"

namespace flowform {

enum class CellType { Triangle3, Quadrilateral4 };

constexpr int nodesPerCell(CellType type) { return type == CellType::Triangle3 ? 3 : 4; }
/// Every element type flowform reads (the bound of per-cell arrays follows from it).
inline constexpr CellType kCellTypes[] = {CellType::Triangle3, CellType::Quadrilateral4};
inline const char* cellTypeName(CellType type) {
  return type == CellType::Triangle3 ? "Triangle" : "Quadrilateral";
}

/// How a cell lies at given node positions: counter-clockwise or clockwise (every corner
/// Jacobian of that sign), degenerate (a corner with |det J| ≤ 10⁻¹² × the longest edge²,
/// far below any element a mesher makes on purpose, far above the round-off of coordinates
/// of order one), or mixed (a quadrilateral whose corner Jacobians differ in sign: bow-tie
/// or non-convex, its bilinear map not invertible). A triangle has one Jacobian.
struct CellOrientation {
  enum class Kind { CounterClockwise, Clockwise, Degenerate, Mixed };
  Kind kind;
  int corner = -1;  ///< the degenerate corner
};
CellOrientation cellOrientation(CellType type, const std::array<double, 2>* xy);

/// The edges of one gmsh physical group of dimension 1, as node-id pairs.
struct BoundaryGroup {
  std::string name;
  std::vector<std::array<GO, 2>> edges;
  /// The edges turned to run with the material on their left (buildBoundaryCurve), kept for the
  /// topology they were found on: finding them scans every cell, and a moving mesh rebuilds its
  /// curves after every move (copies of the mesh share it; a different topology recomputes).
  struct Orientation {
    std::vector<std::array<GO, 2>> edges;  ///< the group's edges it was found for
    std::vector<GO> cellNodes;             ///< the mesh's connectivity it was found on
    std::vector<std::array<GO, 2>> directed;
  };
  mutable std::shared_ptr<const Orientation> orientation;
};

/// A physical group of dimension 2: the cells it holds.
struct RegionGroup {
  std::string name;
  std::vector<GO> cells;
};

struct Mesh {
  std::string source;                      ///< file it came from, for messages
  CellType cellType = CellType::Triangle3;
  std::vector<std::array<double, 2>> coords;  ///< node id (0-based, contiguous) -> (x, y)
  /// nodesPerCell(cellType) node ids per cell, counter-clockwise (positive area).
  std::vector<GO> cellNodes;
  std::vector<BoundaryGroup> boundaries;
  std::vector<RegionGroup> regions;

  GO numNodes() const { return static_cast<GO>(coords.size()); }
  GO numCells() const { return static_cast<GO>(cellNodes.size()) / nodesPerCell(cellType); }
  const GO* cell(GO c) const { return cellNodes.data() + c * nodesPerCell(cellType); }

  /// Moves the nodes to `newCoords` (one per node). InputError naming the first cell that
  /// would not be positively oriented (inverted or degenerate) at the new positions; the mesh
  /// is then unchanged. What caches geometry must be refreshed by its owner after this
  /// (Simulation::moveNodes does it for a run).
  void setCoordinates(const std::vector<std::array<double, 2>>& newCoords);

  /// The boundary group of that name; InputError naming the mesh and the groups it has otherwise.
  const BoundaryGroup& boundary(const std::string& name) const;
  bool hasBoundary(const std::string& name) const;
  /// Comma-separated names of all boundary groups, for error messages.
  std::string boundaryNames() const;
};

}  // namespace flowform
