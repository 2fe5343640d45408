// The mesher's checks of its input, made on the model gmsh holds before the surfaces are
// meshed: the Geo Parameters against what the .geo declares, and the mesh's size estimated from
// the 1-D mesh (or the size field, when one is given) against Mesh/Maximum Cells (GmshMesher.hpp).
#pragma once

#include <string>
#include <vector>

#include "flowform/mesh/Mesh.hpp"
#include "flowform/mesh/ReadOptions.hpp"
#include "flowform/mesh/SizeField.hpp"

namespace flowform {

/// Every Geo Parameter given must be one the .geo defines, inside the range it declares:
/// DefineConstant's Min and Max (gmsh stores ±1e200 when none is given) and Choices are
/// input validation too. InputError otherwise.
void checkGeoParameters(const ReadOptions& opt);

/// Area of every meshed surface from its oriented boundary's 1-D elements (the shoelace
/// formula), and the 1-D elements' lengths.
struct BoundaryMeasure {
  double area = 0.0;
  std::vector<double> lengths;
};

/// The measure of the 1-D mesh gmsh holds.
BoundaryMeasure measureBoundary();

/// The number of cells the 2-D mesh will have, estimated from the 1-D mesh before meshing.
double estimateCells(const BoundaryMeasure& m, CellType type);

/// The number of cells a mesh made to `field` will have: the integral of 1/(c h²) over the
/// field's triangles (c the area of a cell of edge h, as in estimateCells), 1/h² taken as its
/// mean at the corners. The 1-D estimate weighs every boundary edge alike and overcounts a
/// graded mesh many times over: an adaptive cycle's boundary is fine along the die land only.
double estimateCells(const SizeField& field, CellType type);

/// InputError: the mesh would have about `cells` cells, more than opt.maxCells (`how` says
/// how that was found).
[[noreturn]] void refuseTooMany(const ReadOptions& opt, double cells, const std::string& how);

}  // namespace flowform
