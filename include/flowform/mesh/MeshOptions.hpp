// The "Mesh" sublist of a case, validated into what the reader needs (on every rank: the
// checks depend on the parameter list only, so all ranks throw the same InputError without
// talking to each other).
#pragma once

#include <string>

#include <Teuchos_ParameterList.hpp>

#include "flowform/mesh/ReadOptions.hpp"

namespace flowform {

/// Validates `given` (the case's Mesh sublist) and resolves File against `baseDir`.
/// InputError for a missing File, an unknown extension, a non-number Geo Parameter, or a
/// .geo-only option on a .msh.
ReadOptions parseOptions(const Teuchos::ParameterList& given, const std::string& baseDir);

}  // namespace flowform
