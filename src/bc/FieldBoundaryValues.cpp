#include "flowform/bc/FieldBoundaryValues.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "flowform/bc/ThermalBoundaryConditions.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"

namespace flowform {

void declareFieldBoundaryEntries(Teuchos::ParameterList& valid) {
  ThermalBoundaryConditions::declareGroupParameters(valid);
  valid.set("Strain", 0.0,
            "the equivalent strain held on the group's nodes (a case with Material/Strain Field only): the strain the "
            "material enters with at an inflow (0 for an annealed billet; any finite value is taken, so that a "
            "finite difference about 0 can be formed)",
            finiteNumber());
}

std::string firstGroupWith(const Teuchos::ParameterList& bcList, const std::string& entry) {
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (bcList.isSublist(name) && bcList.sublist(name).isParameter(entry)) return name;
  }
  return "";
}

std::vector<NodeValue> prescribedGroupValues(const Teuchos::ParameterList& bcList, const Mesh& mesh,
                                             const std::string& entry, const std::string& quantity) {
  std::map<GO, std::pair<double, std::string>> values;  // node -> (value, group)
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name) || !bcList.sublist(name).isParameter(entry)) continue;
    const Teuchos::ParameterList& group = bcList.sublist(name);
    if (!group.isType<double>(entry))
      throw InputError("Boundary Conditions/" + name + "/" + entry + " must be of type double");
    const double v = group.get<double>(entry);
    if (!std::isfinite(v)) throw InputError("Boundary Conditions/" + name + "/" + entry + " must be finite");
    if (!mesh.hasBoundary(name))
      throw InputError("Boundary Conditions/" + name + ": mesh '" + mesh.source +
                       "' has no boundary group of that name; it has: " + mesh.boundaryNames());
    for (const auto& edge : mesh.boundary(name).edges)
      for (GO node : edge) {
        const auto [at, inserted] = values.emplace(node, std::make_pair(v, name));
        if (!inserted && std::abs(at->second.first - v) > 1e-12 * (std::abs(v) + std::abs(at->second.first))) {
          std::ostringstream os;
          os << "Boundary Conditions: groups '" << at->second.second << "' and '" << name << "' prescribe different "
             << quantity << " (" << at->second.first << ", " << v << ") at their shared node " << node << " ("
             << mesh.coords[node][0] << ", " << mesh.coords[node][1] << ")";
          throw InputError(os.str());
        }
      }
  }
  std::vector<NodeValue> out;
  for (const auto& [node, value] : values) out.push_back({node, value.first});
  return out;
}

}  // namespace flowform
