// The material of one cell as the flow kernel sees it: with a Temperature field and a law that
// depends on the temperature, the law at the cell's centroid temperature T_K (physics/kernels/
// ThermoMechanicalKernel.hpp); otherwise the case's material. For what reads a solution cell by cell
// outside the kernels: the cell states (penalty scales, output fields) and the cell powers.
#pragma once

#include "flowform/assembly/EvaluationTypes.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/physics/kernels/ThermoMechanicalKernel.hpp"

namespace flowform {

/// The Temperature component when the law of `law` reads it, else −1.
inline int temperatureComponentFor(const DofMap& dofMap, int law) {
  return temperatureParameter(law) >= 0 ? dofMap.fields().componentOf(kTemperatureField) : -1;
}

/// `material` at cell k's temperature (x: the solution's workset; temperature: the component,
/// −1 for none: `material` itself).
template <typename Scalar>
MaterialParameters<Scalar> cellMaterial(const Workset& x, const DofMap& dofMap, size_t k, const CellGeometry& g,
                                        const MaterialParameters<Scalar>& material, int temperature) {
  if (temperature < 0) return material;
  LO dofs[kMaxNodesPerCell];
  Scalar values[kMaxNodesPerCell];
  dofMap.cellDofs(k, &temperature, 1, dofs);
  gather(x, dofs, dofMap.nodesPerCell(), values);
  return atTemperature(material, centroidTemperature(g, values, 1, 0));
}

}  // namespace flowform
