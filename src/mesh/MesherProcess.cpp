#include "flowform/mesh/MesherProcess.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "flowform/core/Files.hpp"
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
    const std::string parent = tmp && *tmp ? tmp : "/tmp";
    m_path = makeUniqueDirectory(parent + "/flowform-mesh-");
    if (m_path.empty())
      throw std::runtime_error("cannot create a scratch directory for the mesher in '" + parent + "': " +
                               std::strerror(errno));
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

/// The mesher, started once and kept for the run: gmsh's ~90 shared libraries take a few
/// tenths of a second to load, which an adaptive run would otherwise pay for every mesh. One
/// request at a time over a socket pair (the mesher's fd 0 and 3): the request directory's path
/// out, "done" back. A mesher that crashed, or that was stopped at its time limit, is gone; the
/// next request starts a new one.
class Mesher {
 public:
  ~Mesher() {
    stop(false);
    if (m_logFd >= 0) close(m_logFd);
  }

  /// Sends `dir` and waits up to `seconds` for the answer. False when the mesher died or was
  /// stopped at the limit (`timedOut`); `status` is then its wait status.
  bool request(const std::string& dir, double seconds, bool& timedOut, int& status, std::string& log) {
    if (m_pid > 0 && waitpid(m_pid, &status, WNOHANG) == m_pid) forget();
    if (m_pid <= 0) start();
    const off_t logStart = m_logFd >= 0 ? lseek(m_logFd, 0, SEEK_END) : 0;
    const std::string line = dir + "\n";
    timedOut = false;
    bool answered = send(m_socket, line.data(), line.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(line.size());
    if (answered) answered = awaitAnswer(seconds, timedOut);
    log = logFrom(logStart);
    if (answered) return true;
    stop(timedOut);
    status = m_status;
    return false;
  }

 private:
  void start() {
    const std::string program = mesherProgram();
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
      throw std::runtime_error(std::string("cannot connect to the mesher: ") + std::strerror(errno));
    if (m_logFd < 0) openLog();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 0);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 3);
    posix_spawn_file_actions_adddup2(&actions, m_logFd, 1);
    posix_spawn_file_actions_adddup2(&actions, m_logFd, 2);
    std::vector<char*> argv{const_cast<char*>(program.c_str()), nullptr};
    const int spawned = posix_spawn(&m_pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (spawned != 0) {
      close(fds[0]);
      m_pid = -1;
      throw std::runtime_error("cannot start the mesher '" + program + "': " + std::strerror(spawned));
    }
    m_socket = fds[0];
  }

  /// Waits for the line "done"; false at the deadline or when the mesher is gone.
  bool awaitAnswer(double seconds, bool& timedOut) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    std::string answer;
    while (answer.find('\n') == std::string::npos) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) {
        timedOut = true;
        return false;
      }
      pollfd p{m_socket, POLLIN, 0};
      const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
      if (ready < 0 && errno != EINTR) return false;
      if (ready <= 0) continue;
      char buffer[64];
      const ssize_t n = recv(m_socket, buffer, sizeof buffer, 0);
      if (n <= 0) return false;  // the mesher is gone
      answer.append(buffer, static_cast<std::size_t>(n));
    }
    return true;
  }

  void stop(bool kill9) {
    if (m_pid <= 0) return;
    if (kill9) kill(m_pid, SIGKILL);
    close(m_socket);  // end of its input: it leaves
    m_socket = -1;
    waitpid(m_pid, &m_status, 0);
    m_pid = -1;
  }
  void forget() {
    close(m_socket);
    m_socket = -1;
    m_pid = -1;
  }
  /// The mesher's output (gmsh's log) for all its requests: a file removed from its folder as
  /// soon as it is made, so that nothing is left behind however the run ends (MPI_Abort too).
  void openLog() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/flowform-mesh-log-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    m_logFd = mkostemp(buffer.data(), O_CLOEXEC | O_APPEND);
    if (m_logFd < 0) throw std::runtime_error(std::string("cannot create the mesher's log: ") + std::strerror(errno));
    unlink(buffer.data());
  }
  std::string logFrom(off_t offset) const {
    std::string text;
    char chunk[4096];
    ssize_t n;
    while (m_logFd >= 0 && (n = pread(m_logFd, chunk, sizeof chunk, offset)) > 0) {
      text.append(chunk, static_cast<std::size_t>(n));
      offset += n;
    }
    return text;
  }

  int m_logFd = -1;
  pid_t m_pid = -1;
  int m_socket = -1;
  int m_status = 0;
};

Mesher& mesher() {
  static Mesher instance;
  return instance;
}

}  // namespace

Mesh meshInProcess(const ReadOptions& opt, const SizeField* sizeField) {
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
  bool timedOut = false;
  int status = 0;
  std::string log;
  const bool answered = mesher().request(dir, opt.timeLimit, timedOut, status, log);
  if (opt.verbose) flowform::log() << log;
  std::ostringstream limit;
  limit << opt.timeLimit;
  if (timedOut)
    throw InputError("mesh file '" + opt.path + "': gmsh did not finish within " + limit.str() +
                     " s (Mesh/Time Limit) — a .geo loop that does not end, or a mesh far finer than "
                     "intended? gmsh's last message: " + lastGmshError(log));
  std::string result;
  if (readWholeFile(dir + "/result.bin", result) && !result.empty()) return unpackMesh(std::vector<char>(result.begin(), result.end()));
  const std::string how = !answered && WIFSIGNALED(status)
                              ? "crashed (signal " + std::to_string(WTERMSIG(status)) + ", " + strsignal(WTERMSIG(status)) + ")"
                              : "stopped (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  throw InputError("mesh file '" + opt.path + "': gmsh " + how + " while reading or meshing it; its last message: " +
                   lastGmshError(log));
}

}  // namespace flowform
