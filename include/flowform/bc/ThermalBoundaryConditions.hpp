// The thermal conditions on boundary groups, for a case with a Temperature field
// (Material/Thermal; docs/theory.md §10). Any group, whatever its flow Type, may carry
//   Temperature   T = T_b on the group's nodes (the billet's temperature at an inflow, a wall
//                 held at its temperature)
// and a group without one is insulated (k ∂T/∂n = 0, the energy equation's natural condition:
// an outflow, a symmetry line). Each flow condition's validator accepts these entries
// (declareGroupParameters); this class reads them.
#pragma once

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/core/Types.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

class ThermalBoundaryConditions {
 public:
  /// Adds the thermal entries to a boundary group's valid list.
  static void declareGroupParameters(Teuchos::ParameterList& valid);
  /// Whether any group of `bcList` gives a thermal entry.
  static std::string firstThermalGroup(const Teuchos::ParameterList& bcList);

  /// Reads the groups of `bcList` (the case's Boundary Conditions). Throws InputError when two
  /// groups prescribe different temperatures at a shared node.
  ThermalBoundaryConditions(const Teuchos::ParameterList& bcList, const Mesh& mesh);

  struct NodeTemperature {
    GO node;
    double value;
  };
  /// The prescribed nodal temperatures, each node once.
  const std::vector<NodeTemperature>& prescribed() const { return m_prescribed; }

 private:
  std::vector<NodeTemperature> m_prescribed;
};

}  // namespace flowform
