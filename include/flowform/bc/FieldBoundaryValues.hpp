// Prescribed values of a scalar field on boundary groups: an entry named after the field
// (`Temperature`, `Strain`) on any group, whatever its flow Type, holds the field at the group's
// nodes (docs/interfaces.md). What the thermal conditions (ThermalBoundaryConditions) and the
// strain field's inflow (physics/StrainField.hpp) read.
#pragma once

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/core/Types.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// Adds the field entries (the thermal ones, ThermalBoundaryConditions::declareGroupParameters,
/// and `Strain`) to a boundary group's valid list.
void declareFieldBoundaryEntries(Teuchos::ParameterList& valid);

/// The first group of `bcList` that gives `entry` ("" when none does).
std::string firstGroupWith(const Teuchos::ParameterList& bcList, const std::string& entry);

struct NodeValue {
  GO node;
  double value;
};

/// The values the groups of `bcList` prescribe through `entry`, each node once. InputError when an
/// entry is not a finite double, names a group the mesh lacks, or two groups prescribe different
/// values at a shared node (`quantity` names the values in that message: "temperatures").
std::vector<NodeValue> prescribedGroupValues(const Teuchos::ParameterList& bcList, const Mesh& mesh,
                                             const std::string& entry, const std::string& quantity);

}  // namespace flowform
