// Writing a whole file so that a reader never sees it half-written: the text goes to
// <path>.tmp, which is then renamed over <path> (atomic on POSIX file systems).
#pragma once

#include <string>

namespace flowform {

/// Writes `text` to `path` through `path`.tmp. Throws std::runtime_error naming the file
/// (and the system's reason) when it cannot be created, written or renamed; no .tmp is left.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace flowform
