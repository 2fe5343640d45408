#include "flowform/mesh/MesherProcess.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/mesh/MeshPacking.hpp"

extern char** environ;

namespace flowform {

namespace {

namespace fs = std::filesystem;

/// A fresh private directory for one mesher run, removed with everything in it.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/flowform-mesh-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!mkdtemp(buffer.data()))
      throw std::runtime_error("cannot create a scratch directory for the mesher in '" +
                               pattern.substr(0, pattern.size() - 21) + "': " + std::strerror(errno));
    m_path = buffer.data();
  }
  ~ScratchDirectory() {
    std::error_code ec;
    fs::remove_all(m_path, ec);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const std::string& path() const { return m_path; }

 private:
  std::string m_path;
};

std::string mesherProgram() {
  if (const char* env = std::getenv("FLOWFORM_MESHER"); env && *env) return env;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = self.parent_path() / "flowform-mesh";
    if (fs::is_regular_file(beside, ec)) return beside.string();
  }
#ifdef FLOWFORM_MESHER_BUILD_PATH
  if (fs::is_regular_file(FLOWFORM_MESHER_BUILD_PATH, ec)) return FLOWFORM_MESHER_BUILD_PATH;
#endif
  throw std::runtime_error("the mesher program flowform-mesh is neither beside '" + self.string() +
                           "' nor where the build put it (set FLOWFORM_MESHER to its path)");
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// gmsh's last "Error" line in its log (or the log's last line), for a mesher that died.
std::string lastGmshError(const std::string& log) {
  std::istringstream is(log);
  std::string line, lastError, lastLine;
  while (std::getline(is, line)) {
    if (line.empty()) continue;
    lastLine = line;
    if (line.rfind("Error", 0) == 0 || line.find("terminate called") != std::string::npos) lastError = line;
  }
  return lastError.empty() ? lastLine : lastError;
}

}  // namespace

Mesh meshInProcess(const ReadOptions& opt, const SizeField* sizeField) {
  const std::string program = mesherProgram();
  ScratchDirectory scratch;
  const std::string dir = scratch.path();
  {
    std::ofstream request(dir + "/request.json");
    request << toJson(opt).dump();
    if (sizeField && !sizeField->empty()) {
      std::ofstream sizes(dir + "/size_field.bin", std::ios::binary);
      sizes.write(reinterpret_cast<const char*>(sizeField->triangles.data()),
                  static_cast<std::streamsize>(sizeField->triangles.size() * sizeof(double)));
    }
    if (!request) throw std::runtime_error("cannot write the mesher's request in '" + dir + "'");
  }
  const std::string logPath = dir + "/gmsh.log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> argv{const_cast<char*>(program.c_str()), const_cast<char*>(dir.c_str()), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    throw std::runtime_error("cannot start the mesher '" + program + "': " + std::strerror(spawned));

  // Wait, polling, until it ends or its time is up.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(opt.timeLimit);
  auto pause = std::chrono::microseconds(200);
  int status = 0;
  bool timedOut = false;
  while (true) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) throw std::runtime_error(std::string("waiting for the mesher: ") + std::strerror(errno));
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      timedOut = true;
      break;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  const std::string log = readFile(logPath);
  if (opt.verbose) flowform::log() << log;
  std::ostringstream limit;
  limit << opt.timeLimit;
  if (timedOut)
    throw InputError("mesh file '" + opt.path + "': gmsh did not finish within " + limit.str() +
                     " s (Mesh/Time Limit) — a .geo loop that does not end, or a mesh far finer than "
                     "intended? gmsh's last message: " + lastGmshError(log));
  const std::string result = readFile(dir + "/result.bin");
  if (!result.empty()) return unpackMesh(std::vector<char>(result.begin(), result.end()));
  const std::string how = WIFSIGNALED(status) ? "crashed (signal " + std::to_string(WTERMSIG(status)) + ", " +
                                                    strsignal(WTERMSIG(status)) + ")"
                                              : "stopped (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  throw InputError("mesh file '" + opt.path + "': gmsh " + how + " while reading or meshing it; its last message: " +
                   lastGmshError(log));
}

}  // namespace flowform
