// A mesh, or the error that stopped reading it, as one byte buffer: what the mesher process
// (MesherProcess.hpp) writes back and what rank 0 broadcasts (MeshBroadcast.hpp). Plain
// copies of trivially copyable data; read back only by the same build.
#pragma once

#include <string>
#include <vector>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

std::vector<char> packMesh(const Mesh& mesh);
/// `inputError`: the message is bad input (InputError when unpacked), else another failure.
std::vector<char> packMeshError(bool inputError, const std::string& message);
/// The mesh; throws InputError or std::runtime_error with the packed message for an error.
Mesh unpackMesh(const std::vector<char>& bytes);

}  // namespace flowform
