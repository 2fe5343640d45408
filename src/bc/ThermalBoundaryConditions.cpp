#include "flowform/bc/ThermalBoundaryConditions.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/bc/FieldBoundaryValues.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"

namespace flowform {

namespace {

constexpr const char* kThermalEntries[] = {"Temperature", "Heat Transfer Coefficient", "Ambient Temperature",
                                           "Tool Temperature", "Friction Heat Fraction"};

bool isContactWall(const Teuchos::ParameterList& group) {
  return group.isType<std::string>("Type") && group.get<std::string>("Type") == "Contact Wall";
}

double readDouble(const Teuchos::ParameterList& group, const std::string& groupName, const char* entry) {
  if (!group.isType<double>(entry))
    throw InputError("Boundary Conditions/" + groupName + "/" + entry + " must be of type double");
  const double v = group.get<double>(entry);
  if (!std::isfinite(v)) throw InputError("Boundary Conditions/" + groupName + "/" + entry + " must be finite");
  return v;
}

}  // namespace

void ThermalBoundaryConditions::declareGroupParameters(Teuchos::ParameterList& valid) {
  valid.set("Temperature", 0.0,
            "prescribed temperature on the group's nodes (a case with Material/Thermal only; a group without it is "
            "insulated)",
            finiteNumber());
  valid.set("Heat Transfer Coefficient", 0.0,
            "h >= 0: the heat h (T - T_a) per unit area leaves through the group, T_a its Ambient Temperature (Tool "
            "Temperature on a Contact Wall) [power / (area temperature)]; a case with Material/Thermal only",
            nonNegative());
  valid.set("Ambient Temperature", 0.0, "T_a of the Heat Transfer Coefficient (a group that is not a Contact Wall)",
            finiteNumber());
  valid.set("Tool Temperature", 0.0, "T_a of the Heat Transfer Coefficient on a Contact Wall: the tool's temperature",
            finiteNumber());
  valid.set("Friction Heat Fraction", 0.0,
            "beta in [0, 1], a Contact Wall's: the share of its friction power |g (u - v_w).t| that heats the "
            "workpiece at the wall's nodes (the rest goes into the tool); a case with Material/Thermal only",
            inRange(0.0, 1.0));
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
  m_prescribed = prescribedGroupValues(bcList, mesh, "Temperature", "temperatures");

  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name)) continue;
    const Teuchos::ParameterList& group = bcList.sublist(name);
    const bool wall = isContactWall(group);
    const char* ambientName = wall ? "Tool Temperature" : "Ambient Temperature";
    const char* otherName = wall ? "Ambient Temperature" : "Tool Temperature";
    if (group.isParameter(otherName))
      throw InputError("Boundary Conditions/" + name + "/" + otherName + ": a " +
                       (wall ? std::string("Contact Wall") : std::string("group that is not a Contact Wall")) +
                       " names the temperature its heat goes to '" + ambientName + "'");
    const bool hasCoefficient = group.isParameter("Heat Transfer Coefficient");
    if (group.isParameter(ambientName) && !hasCoefficient)
      throw InputError("Boundary Conditions/" + name + "/" + ambientName +
                       " is given without a 'Heat Transfer Coefficient': give one (or drop the temperature)");
    if (group.isParameter("Friction Heat Fraction")) {
      const double beta = readDouble(group, name, "Friction Heat Fraction");
      if (!wall)
        throw InputError("Boundary Conditions/" + name + "/Friction Heat Fraction: only a Contact Wall has friction");
      // [0, 1] is the entry's validator's (the case as given); a finite-difference run shifts it
      // past a bound (the residual is affine in β), which is not refused here.
      if (beta != 0.0) m_frictionHeat[name] = beta;
    }
    if (group.isParameter("Temperature")) m_groups.push_back(name);  // held (read above)
    if (!hasCoefficient) continue;
    const double h = readDouble(group, name, "Heat Transfer Coefficient");
    if (h < 0.0) throw InputError("Boundary Conditions/" + name + "/Heat Transfer Coefficient must be >= 0");
    if (!group.isParameter(ambientName))
      throw InputError("Boundary Conditions/" + name + ": a 'Heat Transfer Coefficient' needs the '" + ambientName +
                       "' the heat goes to");
    if (group.isParameter("Temperature"))
      throw InputError("Boundary Conditions/" + name + ": both a prescribed 'Temperature' and a 'Heat Transfer "
                       "Coefficient'; give one (a held temperature is the limit h -> infinity)");
    if (!mesh.hasBoundary(name))
      throw InputError("Boundary Conditions/" + name + ": mesh '" + mesh.source +
                       "' has no boundary group of that name; it has: " + mesh.boundaryNames());
    if (h > 0.0) {
      m_transfer.push_back({name, h, readDouble(group, name, ambientName)});
      m_groups.push_back(name);
    }
  }
}

double ThermalBoundaryConditions::frictionHeatFraction(const std::string& wall) const {
  const auto it = m_frictionHeat.find(wall);
  return it == m_frictionHeat.end() ? 0.0 : it->second;
}

std::vector<ThermalBoundaryConditions::TransferEdge> ThermalBoundaryConditions::transferEdges(
    const Mesh& mesh, const DofMap& dofMap) const {
  std::vector<TransferEdge> edges;
  if (m_transfer.empty()) return edges;
  const RankEdges myEdges(mesh, dofMap);  // an edge of one of this rank's cells: assembled here
  for (const Transfer& t : m_transfer)
    for (const auto& e : mesh.boundary(t.group).edges)
      if (myEdges.contains(e))
        edges.push_back({{dofMap.overlapIndex(e[0]), dofMap.overlapIndex(e[1])}, t.coefficient, t.ambient});
  return edges;
}

}  // namespace flowform
