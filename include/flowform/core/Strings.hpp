// Small string helpers shared by the input parsers.
#pragma once

#include <string>
#include <vector>

namespace flowform {

/// `s` without leading and trailing blanks (spaces, tabs, newlines).
inline std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\n");
  const size_t b = s.find_last_not_of(" \t\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

/// The strings joined by `separator`.
inline std::string join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string s;
  for (const std::string& p : parts) s += (s.empty() ? "" : separator) + p;
  return s;
}

}  // namespace flowform
