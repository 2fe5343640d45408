// What the bulk physics is: geometry, stabilization, body force, the material law and (a case with
// a Temperature field) the thermal properties, (a case with a Strain field) its settings. The
// solvers change it between solves (continuation in n and e0); the assembler reads it.
#pragma once

#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/StrainField.hpp"
#include "flowform/physics/ThermalProperties.hpp"

namespace flowform {

struct FlowPhysics {
  FlowKernelSettings kernel;
  MaterialParameters<double> material = powerLaw(0.0, 1.0, 1.0, 1e-3);
  ThermalProperties thermal;  ///< Material/Thermal (read by the temperature rows; a case without it has no T)
  StrainFieldSettings strainField;  ///< Material/Strain Field (read where a law reads the Strain field)
};

}  // namespace flowform
