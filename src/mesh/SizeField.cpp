#include "flowform/mesh/SizeField.hpp"

namespace flowform {

SizeField sizeFieldOnMesh(const Mesh& mesh, const std::vector<double>& size) {
  SizeField field;
  auto add = [&](GO a, GO b, GO c) {
    const GO n[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) field.triangles.push_back(mesh.coords[n[k]][0]);
    for (int k = 0; k < 3; ++k) field.triangles.push_back(mesh.coords[n[k]][1]);
    for (int k = 0; k < 3; ++k) field.triangles.push_back(0.0);
    for (int k = 0; k < 3; ++k) field.triangles.push_back(size[n[k]]);
  };
  for (GO c = 0; c < mesh.numCells(); ++c) {
    const GO* n = mesh.cell(c);
    add(n[0], n[1], n[2]);
    if (mesh.cellType == CellType::Quadrilateral4) add(n[0], n[2], n[3]);
  }
  return field;
}

}  // namespace flowform
