// The mesher process's work (src/mesher/main.cpp): everything flowform asks of gmsh. It runs
// in a process of its own (MesherProcess.hpp), so that gmsh's failures — an error thrown
// inside its OpenMP regions aborts the process, a .geo may loop forever, a size may ask for
// more cells than memory holds — end that process and not the run.
#pragma once

#include "flowform/mesh/Mesh.hpp"
#include "flowform/mesh/ReadOptions.hpp"
#include "flowform/mesh/SizeField.hpp"

namespace flowform {

/// Opens (and for a .geo, meshes) opt.path with gmsh, refines, and extracts the Mesh
/// (MeshReader.hpp says what it holds). InputError for every fault of the input: gmsh's own
/// errors with its message, a Geo Parameter the .geo does not define or outside the range
/// (Min, Max, Choices) its DefineConstant declares, a mesh estimated larger than
/// opt.maxCells (MeshOptions.hpp, estimated from the 1-D mesh before the surfaces are
/// meshed), bad cells, two nodes at one point.
Mesh meshWithGmsh(const ReadOptions& opt, const SizeField* sizeField);

}  // namespace flowform
