// The output directory of a run (-o) and the result set in it: summary.json, solution.h5,
// solution.xdmf and boundary_<group>.csv. Checked before any work, so that a directory the
// run cannot write costs no solve (exit 2); written whole at the end, so that a reader — or a
// second run writing the same directory at the same time — never finds a set mixed from two
// runs: the files are written into a fresh staging directory inside it, then, under an
// exclusive lock on the output directory (flock), the previous set's files are removed and
// the new ones renamed in. Other files in the directory (a script's log, plots) are left alone.
#pragma once

#include <string>

namespace flowform {

/// InputError (exit 2) unless `outDir` can take a result set: a non-empty name; if it exists,
/// a directory we may write in, whose result-set names (summary.json, solution.h5,
/// solution.xdmf) are regular files where present; otherwise its nearest existing ancestor a
/// directory in which a directory can be created (tried, then removed).
void checkResultDirectory(const std::string& outDir);

/// One result set being written: files go into stagingPath(); publish() puts them in place.
class ResultSet {
 public:
  /// Creates `outDir` (and its parents) and a staging directory in it.
  explicit ResultSet(const std::string& outDir);
  /// Removes the staging directory when publish() was not reached.
  ~ResultSet();
  ResultSet(const ResultSet&) = delete;
  ResultSet& operator=(const ResultSet&) = delete;

  const std::string& stagingPath() const { return m_staging; }
  /// Under an exclusive lock on the output directory: removes the previous result set's files
  /// and renames the staged ones in, then removes the staging directory.
  void publish();

 private:
  std::string m_outDir, m_staging;
  bool m_published = false;
};

}  // namespace flowform
