#include "flowform/assembly/SensitivityParameter.hpp"

#include <cmath>

#include "flowform/physics/FlowPhysics.hpp"
#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

struct Known {
  const char* name;
  const char* symbol;
  ParameterKind kind;
};
const Known kFriction[] = {{"Friction Coefficient", "nu", ParameterKind::FrictionCoefficient},
                           {"Shear Factor", "m", ParameterKind::ShearFactor}};

/// The friction parameters (per wall as well), the sensitivity parameters of law `law`, the Geo
/// Parameters, the Boundary Values.
std::string allowedNames(const std::vector<ContactWall>& walls, int law, const GeoParameterValues& geo,
                         const BoundaryValues& boundary) {
  std::string list;
  for (const Known& k : kFriction) {
    list += std::string(list.empty() ? "" : ", ") + "'" + k.name + "'";
    for (const ContactWall& w : walls) list += ", '" + std::string(k.name) + ":" + w.name() + "'";
  }
  for (const ContactWall& w : walls)
    if (w.hasFrictionField())
      list += ", 'Friction Field:" + w.name() + "/<j>' (j = 0 ... " + std::to_string(w.numFieldStations() - 1) + ")";
  for (const MaterialParameterInfo& p : materialLaws()[law].parameters)
    if (p.sensitivity) list += ", '" + std::string(p.name) + "'";
  for (const auto& [name, value] : geo) list += ", 'Geo Parameter:" + name + "'";
  for (const auto& [name, value] : boundary) list += ", 'Boundary Value:" + name + "'";
  for (const char* property : kThermalParameterNames) list += ", 'Thermal:" + std::string(property) + "'";
  if (walls.empty()) list += " (the friction parameters need contact walls; this case has none)";
  if (geo.empty()) list += " (a 'Geo Parameter:<name>' needs the name in Mesh/Geo Parameters; this case gives none)";
  return list;
}

/// The law (other than `law`) that has a sensitivity parameter `name`, or "".
std::string otherLawWith(const std::string& name, int law) {
  const auto& laws = materialLaws();
  for (size_t l = 0; l < laws.size(); ++l)
    for (const MaterialParameterInfo& p : laws[l].parameters)
      if (static_cast<int>(l) != law && p.sensitivity && name == p.name) return laws[l].name;
  return "";
}

}  // namespace

SensitivityParameter parseSensitivityParameter(const std::string& name, const std::vector<ContactWall>& walls,
                                               int law, const GeoParameterValues& geo, const BoundaryValues& boundary) {
  const std::string where = "Sensitivity/Parameters: '" + name + "'";
  const size_t colon = name.find(':');
  const std::string base = name.substr(0, colon);
  SensitivityParameter h;
  h.name = name;
  if (base == "Geo Parameter") {
    const std::string geoName = colon == std::string::npos ? std::string() : name.substr(colon + 1);
    for (const auto& [given, value] : geo)
      if (given == geoName) {
        h.kind = ParameterKind::GeoParameter;
        h.symbol = geoName;
        h.geoName = geoName;
        h.geoValue = value;
        h.relativeStep = true;
        return h;
      }
    throw InputError(where + ": '" + geoName + "' is not given in Mesh/Geo Parameters (a shape parameter must be " +
                     "set there, with the .geo's DefineConstant of that name); allowed: " + allowedNames(walls, law, geo, boundary));
  }
  if (base == "Thermal") {
    const std::string given = colon == std::string::npos ? std::string() : name.substr(colon + 1);
    for (int i = 0; i < kNumThermalParameters; ++i)
      if (given == kThermalParameterNames[i]) {
        h.kind = ParameterKind::Thermal;
        h.thermal = i;
        h.symbol = kThermalParameterSymbols[i];
        h.relativeStep = true;
        return h;
      }
    throw InputError(where + ": '" + given + "' is not a property of Material/Thermal (Conductivity, Density, " +
                     "Specific Heat, Heat Fraction); allowed: " + allowedNames(walls, law, geo, boundary));
  }
  if (base == "Boundary Value") {
    const std::string given = colon == std::string::npos ? std::string() : name.substr(colon + 1);
    for (const auto& [path, value] : boundary)
      if (path == given) {
        const size_t slash = path.rfind('/');
        h.kind = ParameterKind::BoundaryValue;
        h.group = path.substr(0, slash);
        h.entry = path.substr(slash + 1);
        h.boundaryValue = value;
        h.relativeStep = true;
        std::string symbol = path;
        for (char& c : symbol)
          if (c == ' ' || c == '/') c = '_';
        h.symbol = symbol;
        return h;
      }
    throw InputError(where + ": '" + given + "' is not a value the case's Boundary Conditions give (a group's " +
                     "Velocity X, Velocity Y, Temperature, Heat Transfer Coefficient, Ambient or Tool Temperature, " +
                     "Friction Heat Fraction, not of a Rigid Inflow); allowed: " + allowedNames(walls, law, geo, boundary));
  }
  if (base == "Friction Field") {
    const std::string given = colon == std::string::npos ? std::string() : name.substr(colon + 1);
    const size_t slash = given.rfind('/');
    const std::string group = given.substr(0, slash);
    for (size_t w = 0; w < walls.size(); ++w)
      if (walls[w].name() == group && walls[w].hasFrictionField()) h.wall = static_cast<int>(w);
    if (h.wall < 0 || slash == std::string::npos)
      throw InputError(where + ": '" + group + "' is not a contact wall with a Friction Field (the name is " +
                       "'Friction Field:<wall>/<j>'); allowed: " + allowedNames(walls, law, geo, boundary));
    const std::string index = given.substr(slash + 1);
    const int stations = walls[h.wall].numFieldStations();
    size_t used = 0;
    int j = -1;
    try {
      j = std::stoi(index, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != index.size() || index.empty() || j < 0 || j >= stations)
      throw InputError(where + ": the station must be a whole number from 0 to " + std::to_string(stations - 1) +
                       " (wall '" + group + "' has " + std::to_string(stations) + " values), got '" + index + "'");
    h.kind = ParameterKind::FrictionField;
    h.station = j;
    h.symbol = "nu_" + group + "_" + index;
    return h;
  }
  const std::vector<MaterialParameterInfo>& own = materialLaws()[law].parameters;
  for (size_t i = 0; i < own.size(); ++i)
    if (own[i].sensitivity && base == own[i].name) {
      h.kind = ParameterKind::Material;
      h.symbol = own[i].symbol;
      h.material = static_cast<int>(i);
      h.relativeStep = own[i].relativeStep;
    }
  if (h.material >= 0) {
    if (colon != std::string::npos)
      throw InputError(where + ": '" + base + "' is one value for the whole body, not per wall; allowed: " +
                       allowedNames(walls, law, geo, boundary));
    return h;
  }
  const Known* known = nullptr;
  for (const Known& k : kFriction)
    if (base == k.name) known = &k;
  if (!known) {
    const std::string other = otherLawWith(base, law);
    if (!other.empty())
      throw InputError(where + " is a parameter of material law '" + other + "', but the case's Material/Law is '" +
                       materialLaws()[law].name + "'; allowed: " + allowedNames(walls, law, geo, boundary));
    throw InputError(where + " is not a parameter; allowed: " + allowedNames(walls, law, geo, boundary));
  }
  h.symbol = known->symbol;
  h.kind = known->kind;
  if (walls.empty())
    throw InputError(where + " is a friction parameter, but the case has no contact wall; allowed: " +
                     allowedNames(walls, law, geo, boundary));
  if (colon != std::string::npos) {
    const std::string group = name.substr(colon + 1);
    for (size_t w = 0; w < walls.size(); ++w)
      if (walls[w].name() == group) h.wall = static_cast<int>(w);
    if (h.wall < 0)
      throw InputError(where + ": '" + group + "' is not a contact wall; allowed: " + allowedNames(walls, law, geo, boundary));
    h.symbol += "_" + group;
  }
  bool enters = false;
  for (size_t w = 0; w < walls.size(); ++w) {
    enters |= h.entersWall(static_cast<int>(w), walls[w]);
    if (h.kind == ParameterKind::FrictionCoefficient && h.entersWall(static_cast<int>(w), walls[w]) &&
        walls[w].hasFrictionField())
      throw InputError(where + ": wall '" + walls[w].name() + "' has a Friction Field, not one ν: differentiate by "
                       "its values, 'Friction Field:" + walls[w].name() + "/<j>'" +
                       (h.wall < 0 ? ", and name the other walls' ν one by one ('Friction Coefficient:<wall>')" : ""));
  }
  if (!enters)
    throw InputError(where + ": no friction law of " + (h.wall >= 0 ? "that wall" : "the case's walls") + " uses " +
                     (h.kind == ParameterKind::FrictionCoefficient ? "ν (Coulomb, Orowan do)" : "m (Tresca, Orowan do)"));
  return h;
}

double SensitivityParameter::finiteDifferenceStep(double s, const FlowPhysics& physics) const {
  if (isGeo()) return geoValue != 0.0 ? s * std::abs(geoValue) : s;
  if (isBoundaryValue()) return boundaryValue != 0.0 ? s * std::abs(boundaryValue) : s;
  if (isFriction() || !relativeStep) return s;
  const double value = std::abs(kind == ParameterKind::Thermal ? physics.thermal.value(thermal) : physics.material.values[material]);
  return value > 0.0 ? s * value : s;
}

double parameterValue(const SensitivityParameter& h, const FlowPhysics& physics, const std::vector<ContactWall>& walls) {
  if (h.isGeo()) return h.geoValue;
  if (h.isBoundaryValue()) return h.boundaryValue;
  if (h.kind == ParameterKind::Thermal) return physics.thermal.value(h.thermal);
  if (!h.isFriction()) return physics.material.values[h.material];
  if (h.kind == ParameterKind::FrictionField) return walls[h.wall].fieldValue(h.station);
  for (size_t w = 0; w < walls.size(); ++w)
    if (h.entersWall(static_cast<int>(w), walls[w])) {
      const FrictionParameters<double> fp = walls[w].frictionParameters();
      return h.kind == ParameterKind::FrictionCoefficient ? fp.frictionCoefficient : fp.shearFactor;
    }
  return 0.0;
}

void shiftParameter(const SensitivityParameter& h, double delta, FlowPhysics& physics, std::vector<ContactWall>& walls) {
  if (h.partialsFromProblem()) return;  // a shape or a condition: the problem changes (sensitivity/PerturbedSolve)
  if (h.kind == ParameterKind::Thermal) {
    physics.thermal.value(h.thermal) += delta;
    return;
  }
  if (!h.isFriction()) {
    physics.material.values[h.material] += delta;
    return;
  }
  if (h.kind == ParameterKind::FrictionField) {
    walls[h.wall].setFieldValue(h.station, walls[h.wall].fieldValue(h.station) + delta);
    return;
  }
  for (size_t w = 0; w < walls.size(); ++w) {
    if (!h.entersWall(static_cast<int>(w), walls[w])) continue;
    const FrictionParameters<double> fp = walls[w].frictionParameters();
    if (h.kind == ParameterKind::FrictionCoefficient)
      walls[w].setFrictionCoefficient(fp.frictionCoefficient + delta);
    else
      walls[w].setShearFactor(fp.shearFactor + delta);
  }
}

}  // namespace flowform
