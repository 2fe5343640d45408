// Mesh input: rank 0 checks a .geo's commands (GeoScript.hpp) and has the mesher process
// read and mesh the file through gmsh (MesherProcess.hpp); the finished Mesh, or the error,
// reaches every rank through broadcastMesh (MeshBroadcast.hpp).
#include "flowform/mesh/MeshReader.hpp"

#include <filesystem>

#include "flowform/core/InputError.hpp"
#include "flowform/mesh/GeoScript.hpp"
#include "flowform/mesh/MeshBroadcast.hpp"
#include "flowform/mesh/MeshOptions.hpp"
#include "flowform/mesh/MesherProcess.hpp"

namespace flowform {

namespace {

Mesh readOnRoot(const ReadOptions& opt, const SizeField* sizeField) {
  if (!std::filesystem::is_regular_file(opt.path))
    throw InputError("mesh file '" + opt.path + "' (Mesh/File) does not exist");
  if (opt.isGeo) checkGeoScript(opt.path);
  return meshInProcess(opt, sizeField);
}

}  // namespace

Mesh readMesh(const Teuchos::ParameterList& meshParams, const std::string& baseDir,
              const Teuchos::Comm<int>& comm, const SizeField* sizeField) {
  const ReadOptions opt = parseOptions(meshParams, baseDir);
  if (sizeField && !sizeField->empty() && !opt.isGeo)
    throw InputError("mesh file '" + opt.path + "': a size field (Adaptivity) needs a .geo file to mesh anew");
  return broadcastMesh(comm, [&] { return readOnRoot(opt, sizeField); }, "reading mesh file '" + opt.path + "'");
}

}  // namespace flowform
