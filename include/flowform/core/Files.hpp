// Small file-system helpers shared by the readers, the mesher and its parent, and the result
// directory. Header-only: the mesher program (src/mesher/) links no flowform library.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace flowform {

/// The bytes of `path` from `offset` on into `bytes`; false when it cannot be opened or read.
inline bool readWholeFile(const std::string& path, std::string& bytes, std::uintmax_t offset = 0) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  if (offset > 0) in.seekg(static_cast<std::streamoff>(offset));
  std::ostringstream os;
  os << in.rdbuf();
  if (in.bad()) return false;
  bytes = os.str();
  return true;
}

/// Creates a new directory `prefix` + six unique characters (mkdtemp) and returns its path;
/// "" when it cannot be created (errno says why).
inline std::string makeUniqueDirectory(const std::string& prefix) {
  std::string pattern = prefix + "XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  return mkdtemp(buffer.data()) ? std::string(buffer.data()) : std::string();
}

}  // namespace flowform
