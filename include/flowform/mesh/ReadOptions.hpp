// The validated Mesh sublist as the reader needs it (MeshOptions.hpp makes it from the case),
// and as it crosses to the mesher process (MesherProcess.hpp) and back: plain data and JSON,
// no Trilinos, so that the mesher program links gmsh alone.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// The validated Mesh sublist.
struct ReadOptions {
  std::string path;  ///< File resolved against baseDir
  bool isGeo = false;
  CellType cellType = CellType::Triangle3;
  double sizeFactor = 1.0;
  int refinements = 0;
  bool verbose = false;
  std::vector<std::pair<std::string, double>> geoParameters;
  /// Mesh/Maximum Cells: a mesh estimated larger (before it is made) is refused.
  long long maxCells = 1000000;
  /// Mesh/Time Limit [s]: the mesher process is stopped after this long.
  double timeLimit = 120.0;
};

/// Memory one cell costs a run, to say in the refusal what a mesh would need: the die swell
/// refined twice (56 224 cells, 86 031 dofs) peaks at 314 MB resident, 5.6 kB a cell, and the
/// direct solver's fill grows faster than the cell count (docs/theory.md §5).
constexpr double kBytesPerCellEstimate = 6.0e3;

/// The mesher process's address-space limit for a mesh of at most `maxCells` cells: gmsh's
/// own libraries and threads' arenas, plus a generous share per cell (docs/theory.md §5).
inline double mesherMemoryLimitBytes(long long maxCells) { return 4.0e9 + 4.0e3 * static_cast<double>(maxCells); }

/// The options as the mesher process reads them (MesherProcess.hpp), and back.
nlohmann::json toJson(const ReadOptions& opt);
ReadOptions readOptionsFromJson(const nlohmann::json& j);

}  // namespace flowform
