// A structured nx × ny test mesh: node (i, j) placed by the caller, cells (i, j) as
// quadrilaterals or as two triangles on alternating diagonals, counter-clockwise, and the
// boundary groups bottom, right, top, left (each directed with the material on its left),
// one region "body". Shared by the unit tests that need a small mesh without gmsh.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "flowform/mesh/Mesh.hpp"

namespace flowform::test {

/// `place(i, j)` gives the coordinates of node (i, j), 0 <= i <= nx, 0 <= j <= ny.
inline Mesh structuredMesh(CellType type, int nx, int ny, const std::string& source,
                           const std::function<std::array<double, 2>(int i, int j)>& place) {
  Mesh mesh;
  mesh.source = source;
  mesh.cellType = type;
  auto id = [&](int i, int j) { return static_cast<GO>(j * (nx + 1) + i); };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.coords.push_back(place(i, j));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const GO a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (type == CellType::Quadrilateral4)
        mesh.cellNodes.insert(mesh.cellNodes.end(), {a, b, c, d});
      else if ((i + j) % 2 == 0)
        mesh.cellNodes.insert(mesh.cellNodes.end(), {a, b, c, a, c, d});
      else
        mesh.cellNodes.insert(mesh.cellNodes.end(), {a, b, d, b, c, d});
    }
  BoundaryGroup bottom{"bottom", {}}, right{"right", {}}, top{"top", {}}, left{"left", {}};
  for (int i = 0; i < nx; ++i) {
    bottom.edges.push_back({id(i, 0), id(i + 1, 0)});
    top.edges.push_back({id(i + 1, ny), id(i, ny)});
  }
  for (int j = 0; j < ny; ++j) {
    right.edges.push_back({id(nx, j), id(nx, j + 1)});
    left.edges.push_back({id(0, j + 1), id(0, j)});
  }
  mesh.boundaries = {bottom, right, top, left};
  RegionGroup body{"body", {}};
  for (GO c = 0; c < mesh.numCells(); ++c) body.cells.push_back(c);
  mesh.regions = {body};
  return mesh;
}

}  // namespace flowform::test
