// A tiny mesh for the wall tests (ContactWallTest, ResponsesTest).
#pragma once

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// Two triangles over [0,1]×[0,1] with the bottom split at x = 0.5: the wall "bottom" has
/// nodes (0,0), (0.5,0), (1,0), outward normal (0,−1), tangent (1,0); L = 0.5 per segment.
inline Mesh bottomMesh() {
  Mesh m;
  m.source = "test";
  m.cellType = CellType::Triangle3;
  m.coords = {{0.0, 0.0}, {0.5, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  m.cellNodes = {0, 1, 4, 1, 3, 4, 1, 2, 3};
  m.boundaries = {{"bottom", {{0, 1}, {1, 2}}}};
  return m;
}

}  // namespace flowform
