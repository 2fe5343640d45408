#include "flowform/io/ResultDirectory.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "flowform/core/Files.hpp"
#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

namespace fs = std::filesystem;

/// The names flowform writes; boundary_<group>.csv besides.
const char* const kFixedNames[] = {"summary.json", "solution.h5", "solution.xdmf"};

bool isResultFile(const std::string& name) {
  for (const char* n : kFixedNames)
    if (name == n) return true;
  return name.rfind("boundary_", 0) == 0 && name.size() > 13 && name.compare(name.size() - 4, 4, ".csv") == 0;
}

/// Creating (and removing) a directory in `dir` is the only sure test that we may write
/// there: access() says yes to root on a read-only file system and in /proc.
bool canCreateIn(const fs::path& dir) {
  const std::string probe = makeUniqueDirectory((dir / ".flowform-probe-").string());
  if (probe.empty()) return false;
  rmdir(probe.c_str());
  return true;
}

/// An exclusive flock on a directory, released when it goes.
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::string& dir) : m_fd(open(dir.c_str(), O_RDONLY | O_DIRECTORY)) {
    if (m_fd < 0) throw std::runtime_error("cannot open the output directory '" + dir + "': " + std::strerror(errno));
    while (flock(m_fd, LOCK_EX) != 0)
      if (errno != EINTR) {
        const int err = errno;
        close(m_fd);
        throw std::runtime_error("cannot lock the output directory '" + dir + "': " + std::strerror(err));
      }
  }
  ~DirectoryLock() { close(m_fd); }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int m_fd;
};

}  // namespace

void checkResultDirectory(const std::string& outDir) {
  if (outDir.empty()) throw InputError("-o needs a directory name (it is empty)");
  std::error_code ec;
  fs::path p = fs::absolute(outDir, ec);
  if (ec) throw InputError("-o '" + outDir + "': " + ec.message());
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) throw InputError("-o '" + outDir + "' exists and is not a directory");
    for (const char* name : kFixedNames) {
      const fs::path f = p / name;
      if (fs::exists(fs::symlink_status(f, ec)) && !fs::is_regular_file(fs::symlink_status(f, ec)))
        throw InputError("-o '" + outDir + "': '" + f.string() +
                         "' is not a regular file, so the run's result could not replace it; remove it or "
                         "choose another directory");
    }
    if (!canCreateIn(p)) throw InputError("-o '" + outDir + "': cannot write in it (" + std::strerror(errno) + ")");
    return;
  }
  while (!fs::exists(p, ec) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec))
    throw InputError("-o '" + outDir + "': '" + p.string() + "' is not a directory, so the output directory cannot be created");
  if (!canCreateIn(p))
    throw InputError("-o '" + outDir + "': the output directory cannot be created in '" + p.string() + "' (" +
                     std::strerror(errno) + ")");
}

ResultSet::ResultSet(const std::string& outDir) : m_outDir(outDir) {
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) throw std::runtime_error("cannot create the output directory '" + outDir + "': " + ec.message());
  m_staging = makeUniqueDirectory((fs::path(outDir) / ".flowform-partial-").string());
  if (m_staging.empty())
    throw std::runtime_error("cannot create a staging directory in '" + outDir + "': " + std::strerror(errno));
}

ResultSet::~ResultSet() {
  if (m_published) return;
  std::error_code ec;
  fs::remove_all(m_staging, ec);
}

void ResultSet::publish() {
  DirectoryLock lock(m_outDir);
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(m_outDir, ec))
    if (isResultFile(entry.path().filename().string()) && entry.is_regular_file()) fs::remove(entry.path(), ec);
  for (const auto& entry : fs::directory_iterator(m_staging)) {
    const fs::path target = fs::path(m_outDir) / entry.path().filename();
    fs::rename(entry.path(), target, ec);
    if (ec) throw std::runtime_error("cannot move '" + entry.path().string() + "' to '" + target.string() + "': " + ec.message());
  }
  fs::remove(m_staging, ec);
  m_published = true;
}

}  // namespace flowform
