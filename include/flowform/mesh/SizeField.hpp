// A mesh-size field for remeshing: the size wanted at each node of an existing mesh, linear
// in its cells. The reader gives it to gmsh as a background field (a list-data post-processing
// view on triangles, field "PostView"), so gmsh meshes the .geo's own geometry anew — curves
// and physical groups exact — with element sizes from the field alone (sizes from points,
// curvature and boundary extension switched off; the .geo's own Background Field replaced).
#pragma once

#include <vector>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

struct SizeField {
  /// gmsh "ST" list data: per triangle x1 x2 x3 y1 y2 y3 z1 z2 z3 s1 s2 s3.
  std::vector<double> triangles;
  int numTriangles() const { return static_cast<int>(triangles.size() / 12); }
  bool empty() const { return triangles.empty(); }
};

/// The field of `size` (one positive value per node of `mesh`); quadrilaterals are split in two.
SizeField sizeFieldOnMesh(const Mesh& mesh, const std::vector<double>& size);

}  // namespace flowform
