#include "flowform/bc/ThermalBoundaryConditions.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"

namespace flowform {

namespace {
constexpr const char* kThermalEntries[] = {"Temperature"};
}

void ThermalBoundaryConditions::declareGroupParameters(Teuchos::ParameterList& valid) {
  valid.set("Temperature", 0.0,
            "prescribed temperature on the group's nodes (a case with Material/Thermal only; a group without it is "
            "insulated)",
            finiteNumber());
}

std::string ThermalBoundaryConditions::firstThermalGroup(const Teuchos::ParameterList& bcList) {
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name)) continue;
    for (const char* entry : kThermalEntries)
      if (bcList.sublist(name).isParameter(entry)) return name;
  }
  return "";
}

ThermalBoundaryConditions::ThermalBoundaryConditions(const Teuchos::ParameterList& bcList, const Mesh& mesh) {
  std::map<GO, std::pair<double, std::string>> values;  // node -> (T, group)
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name) || !bcList.sublist(name).isParameter("Temperature")) continue;
    const Teuchos::ParameterList& group = bcList.sublist(name);
    if (!group.isType<double>("Temperature"))
      throw InputError("Boundary Conditions/" + name + "/Temperature must be of type double");
    const double t = group.get<double>("Temperature");
    if (!std::isfinite(t)) throw InputError("Boundary Conditions/" + name + "/Temperature must be finite");
    if (!mesh.hasBoundary(name))
      throw InputError("Boundary Conditions/" + name + ": mesh '" + mesh.source +
                       "' has no boundary group of that name; it has: " + mesh.boundaryNames());
    for (const auto& edge : mesh.boundary(name).edges)
      for (GO node : edge) {
        const auto [at, inserted] = values.emplace(node, std::make_pair(t, name));
        if (!inserted && std::abs(at->second.first - t) > 1e-12 * (std::abs(t) + std::abs(at->second.first))) {
          std::ostringstream os;
          os << "Boundary Conditions: groups '" << at->second.second << "' and '" << name
             << "' prescribe different temperatures (" << at->second.first << ", " << t << ") at their shared node "
             << node << " (" << mesh.coords[node][0] << ", " << mesh.coords[node][1] << ")";
          throw InputError(os.str());
        }
      }
  }
  for (const auto& [node, value] : values) m_prescribed.push_back({node, value.first});
}

}  // namespace flowform
