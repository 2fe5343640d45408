#include "flowform/physics/ThermalProperties.hpp"

#include "flowform/core/NumberRange.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

static void buildValidParameters(const ValidList& valid) {
  valid->set("Conductivity", 1.0, "k > 0, heat conductivity [power / (length temperature)]", positive());
  valid->set("Density", 1.0, "rho > 0 [mass / volume]", positive());
  valid->set("Specific Heat", 1.0, "c > 0 [energy / (mass temperature)]; rho c is the heat per volume and degree",
             positive());
  valid->set("Heat Fraction", 0.9, "eta in [0, 1]: the share of the plastic power s:D that heats the metal",
             inRange(0.0, 1.0));
}

Teuchos::RCP<const Teuchos::ParameterList> ThermalProperties::validParameters() {
  return validListOnce<buildValidParameters>("Thermal");
}

ThermalProperties ThermalProperties::fromParameters(const Teuchos::ParameterList& thermal) {
  ThermalProperties p;
  p.conductivity = thermal.get<double>("Conductivity");
  p.density = thermal.get<double>("Density");
  p.specificHeat = thermal.get<double>("Specific Heat");
  p.heatFraction = thermal.get<double>("Heat Fraction");
  return p;
}

}  // namespace flowform
