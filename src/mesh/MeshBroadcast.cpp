#include "flowform/mesh/MeshBroadcast.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <vector>

#include "flowform/core/InputError.hpp"
#include "flowform/mesh/MeshPacking.hpp"

namespace flowform {

namespace {

void broadcastBytes(const Teuchos::Comm<int>& comm, std::vector<char>& bytes) {
  long long size = static_cast<long long>(bytes.size());
  Teuchos::broadcast<int, long long>(comm, 0, 1, &size);
  bytes.resize(static_cast<std::size_t>(size));
  const long long chunk = 1 << 30;  // MPI counts are int
  for (long long offset = 0; offset < size; offset += chunk)
    Teuchos::broadcast<int, char>(comm, 0, static_cast<int>(std::min(chunk, size - offset)),
                                  bytes.data() + offset);
}

}  // namespace

Mesh broadcastMesh(const Teuchos::Comm<int>& comm, const std::function<Mesh()>& read, const std::string& context) {
  std::vector<char> bytes;
  if (comm.getRank() == 0) {
    try {
      bytes = packMesh(read());
    } catch (const InputError& e) {
      bytes = packMeshError(true, e.what());
    } catch (const std::exception& e) {
      bytes = packMeshError(false, context + ": " + e.what());
    }
  }
  broadcastBytes(comm, bytes);
  return unpackMesh(bytes);
}

}  // namespace flowform
