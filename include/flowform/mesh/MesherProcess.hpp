// gmsh runs in a process of its own: the mesher, flowform-mesh (src/mesher/). gmsh keeps
// global state, aborts the whole process when an error is thrown inside its OpenMP regions
// (a zero or negative size does it), runs a .geo's loops as long as they go, and allocates
// whatever a size asks for. In a child process each of these ends the child, under a time
// limit (Mesh/Time Limit) and a memory limit (from Mesh/Maximum Cells), and comes back to the
// run as bad input (exit 2) naming the file and gmsh's own last error. The mesher is started
// at the first mesh and kept for the run's others (a crashed or stopped one is replaced).
#pragma once

#include "flowform/mesh/Mesh.hpp"
#include "flowform/mesh/MeshOptions.hpp"
#include "flowform/mesh/SizeField.hpp"

namespace flowform {

/// Meshes `opt` in the mesher process (GmshMesher.hpp says what it does) and returns the
/// mesh. InputError for everything the mesher reports as bad input, and for a mesher that
/// crashed or ran out of time; std::runtime_error when the mesher cannot be started.
/// Rank 0 only: it is not collective. The mesher program is found as $FLOWFORM_MESHER, else
/// flowform-mesh beside the running program, else where the build put it.
Mesh meshInProcess(const ReadOptions& opt, const SizeField* sizeField);

}  // namespace flowform
