// The material of one cell as the flow kernel sees it: with a Temperature or Strain field that
// the law reads, the law at the cell's centroid temperature T_K and regularized strain ε̃_K
// (physics/kernels/CoupledFlowKernel.hpp); otherwise the case's material. For what reads a
// solution cell by cell outside the kernels: the cell states (penalty scales, output fields) and
// the cell powers.
#pragma once

#include "flowform/assembly/EvaluationTypes.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/physics/FlowPhysics.hpp"
#include "flowform/physics/kernels/CoupledFlowKernel.hpp"

namespace flowform {

/// The components of the fields the case's law reads (−1: none, or the law does not read it),
/// and the strain field's settings.
struct LawFieldComponents {
  int temperature = -1, strain = -1;
  StrainFieldSettings strainField;
  bool any() const { return temperature >= 0 || strain >= 0; }
};

inline LawFieldComponents lawFieldComponents(const DofMap& dofMap, const FlowPhysics& physics) {
  const int law = physics.material.law;
  LawFieldComponents c;
  if (temperatureParameter(law) >= 0) c.temperature = dofMap.fields().componentOf(kTemperatureField);
  if (strainParameter(law) >= 0) c.strain = dofMap.fields().componentOf(kStrainField);
  c.strainField = physics.strainField;
  return c;
}

/// The material at the cell's field values T_K and ε̃_K, from the cell's nodal values of each
/// (`temperatures`, `strains`: null when the law reads no such field).
template <typename Scalar, typename PScalar>
MaterialParameters<Scalar> materialAtCellFields(const CellGeometry& g, const MaterialParameters<PScalar>& material,
                                               const Scalar* temperatures, const Scalar* strains,
                                               const StrainFieldSettings& strainField) {
  Scalar T = 0.0, eps = 0.0;
  if (temperatures) T = centroidValue(g, temperatures, 1, 0);
  if (const int s = strainParameter(material.law); strains && s >= 0)
    eps = coupledLawStrain(centroidValue(g, strains, 1, 0), material.values[s], strainField);
  return atFieldValues(material, temperatures ? &T : nullptr, strains ? &eps : nullptr);
}

/// `material` at cell k's fields (x: the solution's workset; `fields`: the components the law
/// reads, none: `material` itself).
template <typename Scalar>
MaterialParameters<Scalar> cellMaterial(const Workset& x, const DofMap& dofMap, size_t k, const CellGeometry& g,
                                        const MaterialParameters<Scalar>& material, const LawFieldComponents& fields) {
  if (!fields.any()) return material;
  LO dofs[kMaxNodesPerCell];
  Scalar temperatures[kMaxNodesPerCell], strains[kMaxNodesPerCell];
  if (fields.temperature >= 0) {
    dofMap.cellDofs(k, &fields.temperature, 1, dofs);
    gather(x, dofs, dofMap.nodesPerCell(), temperatures);
  }
  if (fields.strain >= 0) {
    dofMap.cellDofs(k, &fields.strain, 1, dofs);
    gather(x, dofs, dofMap.nodesPerCell(), strains);
  }
  return materialAtCellFields(g, material, fields.temperature >= 0 ? temperatures : nullptr,
                              fields.strain >= 0 ? strains : nullptr, fields.strainField);
}

}  // namespace flowform
