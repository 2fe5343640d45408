// JSON output helpers for summary.json (docs/theory.md §5: the full parameter list goes in it).
#include "flowform/io/JsonSummary.hpp"

#include "flowform/io/AtomicFile.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterList.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace flowform {
namespace {

template <class T>
nlohmann::json arrayToJson(const Teuchos::Array<T>& a) {
  nlohmann::json out = nlohmann::json::array();
  for (const T& v : a) out.push_back(v);
  return out;
}

nlohmann::json entryToJson(const Teuchos::ParameterEntry& entry) {
  // getAny(false): a plain read that does not flag the entry as used, so calling this
  // does not hide unused-parameter reports.
  const Teuchos::any& any = entry.getAny(false);
  if (entry.isList()) return parameterListToJson(Teuchos::any_cast<Teuchos::ParameterList>(any));
  if (entry.isType<bool>()) return Teuchos::any_cast<bool>(any);
  if (entry.isType<int>()) return Teuchos::any_cast<int>(any);
  if (entry.isType<long long>()) return Teuchos::any_cast<long long>(any);
  if (entry.isType<double>()) return Teuchos::any_cast<double>(any);
  if (entry.isType<float>()) return Teuchos::any_cast<float>(any);
  if (entry.isType<std::string>()) return Teuchos::any_cast<std::string>(any);
  if (entry.isType<Teuchos::Array<double>>())
    return arrayToJson(Teuchos::any_cast<Teuchos::Array<double>>(any));
  if (entry.isType<Teuchos::Array<int>>())
    return arrayToJson(Teuchos::any_cast<Teuchos::Array<int>>(any));
  if (entry.isType<Teuchos::Array<std::string>>())
    return arrayToJson(Teuchos::any_cast<Teuchos::Array<std::string>>(any));
  std::ostringstream os;
  os << any;
  return os.str();
}

}  // namespace

nlohmann::json parameterListToJson(const Teuchos::ParameterList& list) {
  nlohmann::json out = nlohmann::json::object();
  for (auto it = list.begin(); it != list.end(); ++it)
    out[list.name(it)] = entryToJson(list.entry(it));
  return out;
}

void writeJsonFile(const std::string& path, const nlohmann::json& j) {
  // Serialize before touching the disk: a failure here must leave no file behind.
  const std::string text =
      j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  try {
    writeFileAtomically(path, text);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("writeJsonFile: ") + e.what());
  }
}

}  // namespace flowform
