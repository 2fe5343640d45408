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
const Known kKnown[] = {{"Friction Coefficient", "nu", ParameterKind::FrictionCoefficient},
                        {"Shear Factor", "m", ParameterKind::ShearFactor},
                        {"Yield Stress", "sigma0", ParameterKind::YieldStress},
                        {"Rate Constant", "gamma", ParameterKind::RateConstant},
                        {"Rate Exponent", "n", ParameterKind::RateExponent}};

std::string allowedNames(const std::vector<ContactWall>& walls) {
  std::string list;
  for (const Known& k : kKnown) {
    list += std::string(list.empty() ? "" : ", ") + "'" + k.name + "'";
    const bool friction = k.kind == ParameterKind::FrictionCoefficient || k.kind == ParameterKind::ShearFactor;
    if (friction)
      for (const ContactWall& w : walls) list += ", '" + std::string(k.name) + ":" + w.name() + "'";
  }
  if (walls.empty()) list += " (the friction parameters need contact walls; this case has none)";
  return list;
}

double& materialEntry(ParameterKind kind, MaterialParameters<double>& m) {
  return kind == ParameterKind::YieldStress ? m.yieldStress : kind == ParameterKind::RateConstant ? m.rateConstant
                                                                                                : m.rateExponent;
}

}  // namespace

SensitivityParameter parseSensitivityParameter(const std::string& name, const std::vector<ContactWall>& walls) {
  const std::string where = "Sensitivity/Parameters: '" + name + "'";
  const size_t colon = name.find(':');
  const std::string base = name.substr(0, colon);
  const Known* known = nullptr;
  for (const Known& k : kKnown)
    if (base == k.name) known = &k;
  if (!known) throw InputError(where + " is not a parameter; allowed: " + allowedNames(walls));

  SensitivityParameter h;
  h.name = name;
  h.symbol = known->symbol;
  h.kind = known->kind;
  if (!h.isFriction()) {
    if (colon != std::string::npos)
      throw InputError(where + ": '" + base + "' is one value for the whole body, not per wall; allowed: " +
                       allowedNames(walls));
    return h;
  }
  if (walls.empty())
    throw InputError(where + " is a friction parameter, but the case has no contact wall; allowed: " +
                     allowedNames(walls));
  if (colon != std::string::npos) {
    const std::string group = name.substr(colon + 1);
    for (size_t w = 0; w < walls.size(); ++w)
      if (walls[w].name() == group) h.wall = static_cast<int>(w);
    if (h.wall < 0) throw InputError(where + ": '" + group + "' is not a contact wall; allowed: " + allowedNames(walls));
    h.symbol += "_" + group;
  }
  bool enters = false;
  for (size_t w = 0; w < walls.size(); ++w) enters |= h.entersWall(static_cast<int>(w), walls[w]);
  if (!enters)
    throw InputError(where + ": no friction law of " + (h.wall >= 0 ? "that wall" : "the case's walls") + " uses " +
                     (h.kind == ParameterKind::FrictionCoefficient ? "ν (Coulomb, Orowan do)" : "m (Tresca, Orowan do)"));
  return h;
}

double SensitivityParameter::finiteDifferenceStep(double s, const FlowPhysics& physics) const {
  if (isFriction()) return s;
  MaterialParameters<double> m = physics.material;
  const double value = std::abs(materialEntry(kind, m));
  return value > 0.0 ? s * value : s;
}

double parameterValue(const SensitivityParameter& h, const FlowPhysics& physics, const std::vector<ContactWall>& walls) {
  if (!h.isFriction()) {
    MaterialParameters<double> m = physics.material;
    return materialEntry(h.kind, m);
  }
  for (size_t w = 0; w < walls.size(); ++w)
    if (h.entersWall(static_cast<int>(w), walls[w])) {
      const FrictionParameters<double> fp = walls[w].frictionParameters();
      return h.kind == ParameterKind::FrictionCoefficient ? fp.frictionCoefficient : fp.shearFactor;
    }
  return 0.0;
}

void shiftParameter(const SensitivityParameter& h, double delta, FlowPhysics& physics, std::vector<ContactWall>& walls) {
  if (!h.isFriction()) {
    materialEntry(h.kind, physics.material) += delta;
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
