// flowform-mesh DIR — the mesher process (MesherProcess.hpp, GmshMesher.hpp). Reads
// DIR/request.json (the validated Mesh options) and DIR/size_field.bin (optional), meshes with
// gmsh and writes DIR/result.bin: the packed Mesh, or the error that stopped it
// (MeshPacking.hpp). Exit 0 when result.bin is written, whatever it says; anything else is a
// crash the parent reports with gmsh's last logged error.
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/mesh/ReadOptions.hpp"
#include "flowform/mesh/MeshPacking.hpp"
#include "flowform/mesher/GmshMesher.hpp"

namespace {

std::string g_resultPath;  ///< where the answer goes, also from the terminate handler
std::string g_meshPath;    ///< the file being meshed, for messages
double g_memoryLimit = 0;  ///< bytes

bool writeResult(const std::vector<char>& bytes) {
  const std::string tmp = g_resultPath + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !ok) return false;
  return std::rename(tmp.c_str(), g_resultPath.c_str()) == 0;
}

std::string outOfMemoryMessage() {
  std::ostringstream os;
  os.precision(3);
  os << "mesh file '" << g_meshPath << "': gmsh ran out of the mesher's memory limit (" << g_memoryLimit / 1e9
     << " GB, set by Mesh/Maximum Cells): the mesh asked for is far larger than intended; coarsen it "
        "(Geo Parameters, Size Factor, Uniform Refinements) or raise Mesh/Maximum Cells";
  return os.str();
}

/// An exception that leaves one of gmsh's OpenMP regions cannot be caught: it ends here. The
/// message still reaches the run.
[[noreturn]] void onTerminate() {
  std::string message = "mesh file '" + g_meshPath + "': gmsh failed";
  if (std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::string& s) {
      message += ": " + s;
    } catch (const std::bad_alloc&) {
      message = outOfMemoryMessage();
    } catch (const std::exception& x) {
      message += ": " + std::string(x.what());
    } catch (...) {
    }
  }
  std::cerr << message << std::endl;
  writeResult(flowform::packMeshError(true, message));
  _exit(0);
}

}  // namespace

int main(int argc, char* argv[]) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // the run that started us is gone: so are we
  if (argc != 2) {
    std::cerr << "usage: flowform-mesh DIR (started by flowform, not by hand)\n";
    return 1;
  }
  const std::string dir = argv[1];
  g_resultPath = dir + "/result.bin";
  std::set_terminate(onTerminate);
  try {
    std::ifstream in(dir + "/request.json");
    const flowform::ReadOptions opt = flowform::readOptionsFromJson(nlohmann::json::parse(in));
    g_meshPath = opt.path;
    flowform::SizeField field;
    std::ifstream sizes(dir + "/size_field.bin", std::ios::binary);
    if (sizes) {
      std::ostringstream os;
      os << sizes.rdbuf();
      const std::string bytes = os.str();
      field.triangles.resize(bytes.size() / sizeof(double));
      std::copy(bytes.data(), bytes.data() + field.triangles.size() * sizeof(double),
                reinterpret_cast<char*>(field.triangles.data()));
    }
    g_memoryLimit = flowform::mesherMemoryLimitBytes(opt.maxCells);
    const rlimit limit{static_cast<rlim_t>(g_memoryLimit), static_cast<rlim_t>(g_memoryLimit)};
    setrlimit(RLIMIT_AS, &limit);
    const flowform::Mesh mesh = flowform::meshWithGmsh(opt, field.empty() ? nullptr : &field);
    return writeResult(flowform::packMesh(mesh)) ? 0 : 1;
  } catch (const flowform::InputError& e) {
    return writeResult(flowform::packMeshError(true, e.what())) ? 0 : 1;
  } catch (const std::bad_alloc&) {
    return writeResult(flowform::packMeshError(true, outOfMemoryMessage())) ? 0 : 1;
  } catch (const std::string& s) {  // gmsh outside the steps that translate its errors
    return writeResult(flowform::packMeshError(true, "mesh file '" + g_meshPath + "': gmsh failed: " + s)) ? 0 : 1;
  } catch (const std::exception& e) {
    return writeResult(flowform::packMeshError(false, e.what())) ? 0 : 1;
  }
}
