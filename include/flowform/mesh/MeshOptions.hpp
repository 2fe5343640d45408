// The "Mesh" sublist of a case, validated into what the reader needs (on every rank: the
// checks depend on the parameter list only, so all ranks throw the same InputError without
// talking to each other).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>
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

/// Memory one cell costs a run, to say in the refusal what a mesh would need: measured peak
/// resident memory over cells of the cutting scene's refined solve and the extrusion's
/// adaptive runs (docs/theory.md §5).
constexpr double kBytesPerCellEstimate = 4.0e3;

/// The mesher process's address-space limit for a mesh of at most `maxCells` cells: gmsh's
/// own libraries and threads' arenas, plus a generous share per cell (docs/theory.md §5).
double mesherMemoryLimitBytes(long long maxCells);

/// The options as the mesher process reads them (MesherProcess.hpp), and back.
nlohmann::json toJson(const ReadOptions& opt);
ReadOptions readOptionsFromJson(const nlohmann::json& j);

/// Validates `given` (the case's Mesh sublist) and resolves File against `baseDir`.
/// InputError for a missing File, an unknown extension, a non-number Geo Parameter, or a
/// .geo-only option on a .msh.
ReadOptions parseOptions(const Teuchos::ParameterList& given, const std::string& baseDir);

}  // namespace flowform
