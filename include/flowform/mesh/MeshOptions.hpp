// The "Mesh" sublist of a case, validated into what the reader needs (on every rank: the
// checks depend on the parameter list only, so all ranks throw the same InputError without
// talking to each other).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>

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
};

/// Validates `given` (the case's Mesh sublist) and resolves File against `baseDir`.
/// InputError for a missing File, an unknown extension, a non-number Geo Parameter, or a
/// .geo-only option on a .msh.
ReadOptions parseOptions(const Teuchos::ParameterList& given, const std::string& baseDir);

}  // namespace flowform
