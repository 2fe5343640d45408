// Where the dofs of one cell sit, per element type.
//
// The equal-order elements (P1 triangles, Q1 quadrilaterals) carry every registered field
// at every node. A kernel's element vector holds the components it reads, node-major:
// entry (a, i) of a kernel that reads C components is C a + i (NodeMajorLayout<C>). The
// flow kernel reads (u_x, u_y, p): its layout is EqualOrderLayout = NodeMajorLayout<3>.
// A mixed element (e.g. P2/P1, pressure at the vertices only) is a new answer of
// cellNodeCarries() plus its kernel's layout; the DofMap asks componentsAtCellNode().
#pragma once

#include <type_traits>

#include "flowform/core/Types.hpp"
#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// NumComponents components at every node of the cell, node-major.
template <int NumComponents>
struct NodeMajorLayout {
  static constexpr int kFieldsPerNode = NumComponents;
  /// Components carried by local node a of a cell (all of them, for equal order).
  static constexpr int fieldsAtNode(int /*a*/) { return kFieldsPerNode; }
  /// Element-vector index of (local node a, component).
  static constexpr int index(int a, int component) { return kFieldsPerNode * a + component; }
  /// Dofs of a cell with `numNodes` nodes.
  static constexpr int numDofs(int numNodes) { return kFieldsPerNode * numNodes; }
};

/// The flow kernel's element vector: u_x, u_y, p at every node (P1/P1, Q1/Q1).
using EqualOrderLayout = NodeMajorLayout<kNumFlowComponents>;

/// The flow kernel's dof count of a cell of this type (templated loops size their AD types with it).
template <int NumNodes>
constexpr int cellDofCount() {
  return EqualOrderLayout::numDofs(NumNodes);
}

/// Whether local node a of a cell of `type` carries field `field` (every element type today
/// is equal order: every node carries every field).
inline bool cellNodeCarries(CellType /*type*/, int /*a*/, const FieldDescription& /*field*/) { return true; }

/// Components carried by local node a of a cell of `type`, over the case's fields.
inline int componentsAtCellNode(CellType type, int a, const FieldRegistry& fields) {
  int n = 0;
  for (int f = 0; f < fields.numFields(); ++f)
    if (cellNodeCarries(type, a, fields.field(f))) n += fields.field(f).numComponents;
  return n;
}

/// Calls f(std::integral_constant<int, N>{}) with N the node count of `type`: the one place
/// where a cell loop turns the element type into the compile-time size of its AD types.
template <typename F>
void withNodeCount(CellType type, F&& f) {
  if (type == CellType::Triangle3)
    f(std::integral_constant<int, nodesPerCell(CellType::Triangle3)>{});
  else
    f(std::integral_constant<int, nodesPerCell(CellType::Quadrilateral4)>{});
}

}  // namespace flowform
