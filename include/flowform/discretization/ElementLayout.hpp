// Where the dofs of one cell sit in its element vector, per element type.
//
// The equal-order elements (P1/P1 triangles, Q1/Q1 quadrilaterals) carry every field
// (u_x, u_y, p) at every node, node-major: dof (a, field) of the cell is 3a + field. A mixed
// element (e.g. P2/P1, pressure at the vertices only) is a new layout here plus its kernel;
// the DofMap asks the layout how many fields each cell node carries.
#pragma once

#include "flowform/core/Types.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

struct EqualOrderLayout {
  static constexpr int kFieldsPerNode = kNumFields;
  /// Fields carried by local node a of a cell (all of them, for equal order).
  static constexpr int fieldsAtNode(int /*a*/) { return kFieldsPerNode; }
  /// Element-vector index of (local node a, field).
  static constexpr int index(int a, int field) { return kFieldsPerNode * a + field; }
  /// Dofs of a cell with `numNodes` nodes.
  static constexpr int numDofs(int numNodes) { return kFieldsPerNode * numNodes; }
};

/// The dof count of a cell of this type (templated loops size their AD types with it).
template <int NumNodes>
constexpr int cellDofCount() {
  return EqualOrderLayout::numDofs(NumNodes);
}

/// Fields carried by local node a of a cell of `type` (every element type today is equal order).
inline int fieldsAtCellNode(CellType /*type*/, int a) { return EqualOrderLayout::fieldsAtNode(a); }

}  // namespace flowform
