// One mesh read on rank 0, given to every rank: the Mesh (or the error text) is packed into
// one byte buffer and broadcast, so every rank returns the same mesh or throws the same
// error, and no rank is left waiting in a collective when rank 0 fails.
#pragma once

#include <functional>
#include <string>

#include <Teuchos_Comm.hpp>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// Calls `read` on rank 0 only and returns its Mesh on every rank. When `read` throws, every
/// rank throws: InputError with the same message for an InputError, std::runtime_error with
/// "<context>: <message>" for anything else. Collective.
Mesh broadcastMesh(const Teuchos::Comm<int>& comm, const std::function<Mesh()>& read, const std::string& context);

}  // namespace flowform
