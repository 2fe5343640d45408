#include "flowform/optimization/DesignParameters.hpp"

#include <cmath>

#include "flowform/core/InputError.hpp"
#include "flowform/freesurface/ReferenceTopology.hpp"

namespace flowform {

using Teuchos::ParameterList;

namespace {

const std::string kGeoPrefix = "Geo Parameter:";

const ParameterList* sublistAt(const ParameterList& root, const std::vector<std::string>& path) {
  const ParameterList* list = &root;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (!list->isSublist(path[i])) return nullptr;
    list = &list->sublist(path[i]);
  }
  return list;
}

std::string joinedPath(const std::vector<std::string>& path) {
  std::string s;
  for (const auto& p : path) s += (s.empty() ? "" : "/") + p;
  return s;
}

/// The case entries that hold parameter `name` (maybe none).
std::vector<std::vector<std::string>> entriesOf(const std::string& name, const ParameterList& caseParams) {
  const std::size_t colon = name.find(':');
  const std::string base = name.substr(0, colon), rest = colon == std::string::npos ? "" : name.substr(colon + 1);
  if (base == "Geo Parameter") return {{"Mesh", "Geo Parameters", rest}};
  if (base == "Thermal") return {{"Material", "Thermal", rest}};
  if (base == "Boundary Value") {
    const std::size_t slash = rest.find('/');
    if (slash == std::string::npos) return {};
    return {{"Boundary Conditions", rest.substr(0, slash), rest.substr(slash + 1)}};
  }
  if (base == "Friction Field") {
    const std::size_t slash = rest.rfind('/');
    if (slash == std::string::npos) return {};
    return {{"Boundary Conditions", rest.substr(0, slash), base}};
  }
  if (base == "Friction Coefficient" || base == "Shear Factor") {
    if (!rest.empty()) return {{"Boundary Conditions", rest, base}};
    std::vector<std::vector<std::string>> walls;
    if (!caseParams.isSublist("Boundary Conditions")) return walls;
    const ParameterList& conditions = caseParams.sublist("Boundary Conditions");
    for (auto it = conditions.begin(); it != conditions.end(); ++it) {
      const std::string& group = conditions.name(it);
      if (conditions.isSublist(group) && conditions.sublist(group).isParameter(base))
        walls.push_back({"Boundary Conditions", group, base});
    }
    return walls;
  }
  return {{"Material", name}};
}

/// The station j of "Friction Field:<wall>/<j>", −1 for another name (or a malformed one, which
/// Sensitivity/Parameters refuses with the allowed names).
int fieldStation(const std::string& name) {
  if (name.rfind("Friction Field:", 0) != 0) return -1;
  const std::size_t slash = name.rfind('/');
  if (slash == std::string::npos) return -1;
  const std::string index = name.substr(slash + 1);
  if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stoi(index);
}

}  // namespace

DesignParameters::DesignParameters(const std::vector<std::string>& names, const ParameterList& caseParams)
    : m_names(names) {
  for (const std::string& name : names) {
    const std::string where = "Optimization/Design Parameters: '" + name + "'";
    const auto paths = entriesOf(name, caseParams);
    if (paths.empty())
      throw InputError(where + ": the case gives no value for it to start from (a friction parameter needs a "
                       "contact wall that sets it; a Boundary Value is 'group/entry')");
    double start = 0.0;
    const int element = fieldStation(name);
    m_elements.push_back(element);
    if (element >= 0) {  // one value of an array entry (a Friction Field's station)
      const ParameterList* list = sublistAt(caseParams, paths[0]);
      if (!list || !list->isType<Teuchos::Array<double>>(paths[0].back()))
        throw InputError(where + ": the case does not set " + joinedPath(paths[0]) + " (the design starts from the "
                         "case's values: give the field there)");
      const auto& values = list->get<Teuchos::Array<double>>(paths[0].back());
      if (element >= static_cast<int>(values.size()))
        throw InputError(where + ": " + joinedPath(paths[0]) + " has " + std::to_string(values.size()) +
                         " values (stations 0 to " + std::to_string(values.size() - 1) + ")");
      m_paths.push_back(paths);
      m_initial.push_back(values[element]);
      continue;
    }
    for (std::size_t i = 0; i < paths.size(); ++i) {
      const ParameterList* list = sublistAt(caseParams, paths[i]);
      if (!list || !list->isType<double>(paths[i].back()))
        throw InputError(where + ": the case does not set " + joinedPath(paths[i]) +
                         " (the design starts from the case's value: give it there)");
      const double value = list->get<double>(paths[i].back());
      if (i == 0) start = value;
      else if (value != start)
        throw InputError(where + " moves every wall's value together, but " + joinedPath(paths[0]) + " = " +
                         std::to_string(start) + " and " + joinedPath(paths[i]) + " = " + std::to_string(value) +
                         ": design each wall's own ('" + name + ":<wall>')");
    }
    m_paths.push_back(paths);
    m_initial.push_back(start);
  }
}

bool DesignParameters::movesShape() const {
  for (const std::string& name : m_names)
    if (name.rfind(kGeoPrefix, 0) == 0) return true;
  return false;
}

ParameterList DesignParameters::onReferenceTopology(ParameterList params, const std::vector<double>& values) const {
  for (std::size_t i = 0; i < m_names.size(); ++i)
    if (m_names[i].rfind(kGeoPrefix, 0) == 0)
      params.sublist("Mesh").sublist(kReferenceGeoParameters).set(m_names[i].substr(kGeoPrefix.size()), values[i]);
  return params;
}

ParameterList DesignParameters::applied(const ParameterList& caseParams, const std::vector<double>& values) const {
  ParameterList copy = caseParams;
  for (std::size_t p = 0; p < m_paths.size(); ++p)
    for (const auto& path : m_paths[p]) {
      ParameterList* list = &copy;
      for (std::size_t i = 0; i + 1 < path.size(); ++i) list = &list->sublist(path[i]);
      if (m_elements[p] >= 0) {
        Teuchos::Array<double> field = list->get<Teuchos::Array<double>>(path.back());
        field[m_elements[p]] = values[p];
        list->set(path.back(), field);
      } else {
        list->set(path.back(), values[p]);
      }
    }
  return copy;
}

}  // namespace flowform
