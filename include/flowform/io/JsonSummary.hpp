// summary.json support: an atomic JSON file writer and the conversion of the validated
// Teuchos parameter list into JSON, so summary.json records every parameter used.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace Teuchos {
class ParameterList;
}

namespace flowform {

/// Writes `j` to `path` with 2-space indent and a final newline, through `path`.tmp and a
/// rename: scripts polling for the file never read half of it. Non-finite doubles are
/// written as null (nlohmann's rule; JSON has no NaN). Strings that are not valid UTF-8 are
/// written with U+FFFD in place of the bad bytes instead of failing. Throws
/// std::runtime_error naming `path` when the file cannot be written.
void writeJsonFile(const std::string& path, const nlohmann::json& j);

/// The list as a JSON object, recursively: sublists become objects; bool, int, long long,
/// double, float and std::string become JSON values; Teuchos::Array<double>, <int> and
/// <std::string> become arrays; any other type becomes its printed (string) form.
/// Reading entries here does not mark them as used. Keys come out sorted (nlohmann::json
/// objects are ordered maps), not in the list's insertion order.
nlohmann::json parameterListToJson(const Teuchos::ParameterList& list);

}  // namespace flowform
