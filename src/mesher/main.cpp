// flowform-mesh — the mesher process (MesherProcess.hpp, GmshMesher.hpp), started by flowform
// with a socket as its fd 0 and 3. For each line DIR it reads: reads DIR/request.json (the
// validated Mesh options) and DIR/size_field.bin (optional), meshes with gmsh, writes
// DIR/result.bin — the packed Mesh, or the error that stopped it (MeshPacking.hpp) — and answers
// "done" on fd 3. It leaves at the end of its input. An error gmsh throws inside its OpenMP
// regions ends it after the answer (terminate handler); a crash ends it without one, which the
// parent reports with gmsh's last logged error.
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "flowform/core/Files.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/mesh/ReadOptions.hpp"
#include "flowform/mesh/MeshPacking.hpp"
#include "flowform/mesher/GmshMesher.hpp"

namespace {

std::string g_resultPath;  ///< where the answer goes, also from the terminate handler
constexpr int kAnswerFd = 3;
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

void answer() {
  const char done[] = "done\n";
  if (write(kAnswerFd, done, sizeof done - 1) < 0) _exit(1);
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
  answer();
  _exit(0);
}

/// One request: DIR/request.json in, DIR/result.bin out.
void serve(const std::string& dir) {
  g_resultPath = dir + "/result.bin";
  try {
    std::ifstream in(dir + "/request.json");
    const flowform::ReadOptions opt = flowform::readOptionsFromJson(nlohmann::json::parse(in));
    g_meshPath = opt.path;
    flowform::SizeField field;
    std::string bytes;
    if (flowform::readWholeFile(dir + "/size_field.bin", bytes)) {
      field.triangles.resize(bytes.size() / sizeof(double));
      std::copy(bytes.data(), bytes.data() + field.triangles.size() * sizeof(double),
                reinterpret_cast<char*>(field.triangles.data()));
    }
    // The soft limit only: each request sets its own (this process's footprint so far stays).
    g_memoryLimit = flowform::mesherMemoryLimitBytes(opt.maxCells);
    rlimit limit{};
    getrlimit(RLIMIT_AS, &limit);
    limit.rlim_cur = std::min<rlim_t>(static_cast<rlim_t>(g_memoryLimit), limit.rlim_max);
    setrlimit(RLIMIT_AS, &limit);
    writeResult(flowform::packMesh(flowform::meshWithGmsh(opt, field.empty() ? nullptr : &field)));
  } catch (const flowform::InputError& e) {
    writeResult(flowform::packMeshError(true, e.what()));
  } catch (const std::bad_alloc&) {
    writeResult(flowform::packMeshError(true, outOfMemoryMessage()));
  } catch (const std::string& s) {  // gmsh outside the steps that translate its errors
    writeResult(flowform::packMeshError(true, "mesh file '" + g_meshPath + "': gmsh failed: " + s));
  } catch (const std::exception& e) {
    writeResult(flowform::packMeshError(false, e.what()));
  }
}

}  // namespace

int main(int argc, char* argv[]) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // the run that started us is gone: so are we
  if (argc != 1) {
    std::cerr << "usage: flowform-mesh (started by flowform, which sends it requests)\n";
    return 1;
  }
  std::set_terminate(onTerminate);
  std::string dir;
  while (std::getline(std::cin, dir)) {
    serve(dir);
    answer();
  }
  return 0;
}
