// The thermal conditions on boundary groups, for a case with a Temperature field
// (Material/Thermal; docs/theory.md §10). Any group, whatever its flow Type, may carry
//   Temperature   T = T_b on the group's nodes (the billet's temperature at an inflow, a wall
//                 held at its temperature)
//   Heat Transfer Coefficient  h ≥ 0: the heat h (T − T_a) per unit area leaves through the group
//                 (a tool in contact, a surface to the air), with
//   Ambient Temperature        T_a (the surroundings; on a Contact Wall its name is Tool
//                 Temperature: the tool's)
//   Friction Heat Fraction     β ∈ [0, 1], on a Contact Wall only: the share of the friction
//                 power g (u − v_w)·t at each wall node that heats the workpiece there (the
//                 assembler adds R_T[k] −= β g_k (u_k − v_w)·t_k; the rest goes into the tool)
// and a group without either is insulated (k ∂T/∂n = 0, the energy equation's natural condition:
// an outflow, a symmetry line). Each flow condition's validator accepts these entries
// (declareGroupParameters, through bc/FieldBoundaryValues.hpp); this class reads them. The transfer is a boundary condition, not a
// reaction: the assembler adds R_T[a] += ∫_edge N_a h (T − T_a) dΓ (× 2π r axisymmetric) to the
// constrained residual only, so the unconstrained residual's temperature rows at a group's nodes
// are the heat that leaves there (the Heat Flow response, for held and transferring groups alike).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/bc/FieldBoundaryValues.hpp"
#include "flowform/core/Types.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

class ThermalBoundaryConditions {
 public:
  /// Adds the thermal entries to a boundary group's valid list.
  static void declareGroupParameters(Teuchos::ParameterList& valid);
  /// The first group of `bcList` that gives a thermal entry ("" when none does).
  static std::string firstThermalGroup(const Teuchos::ParameterList& bcList);

  /// Reads the groups of `bcList` (the case's Boundary Conditions). InputError when two groups
  /// prescribe different temperatures at a shared node, a coefficient lacks its temperature (or
  /// the reverse), a group names the other kind's temperature (Ambient on a wall, Tool off one),
  /// or a group holds its Temperature and transfers heat too.
  ThermalBoundaryConditions(const Teuchos::ParameterList& bcList, const Mesh& mesh);

  /// The prescribed nodal temperatures, each node once (bc/FieldBoundaryValues.hpp).
  const std::vector<NodeValue>& prescribed() const { return m_prescribed; }

  /// One boundary edge that transfers heat: its two overlap nodes, h and T_a.
  struct TransferEdge {
    LO nodes[2];
    double coefficient, ambient;
  };
  /// The transferring edges that are an edge of one of this rank's cells (each edge once over
  /// the ranks).
  std::vector<TransferEdge> transferEdges(const Mesh& mesh, const DofMap& dofMap) const;
  /// The groups that hold their temperature or transfer heat (a positive coefficient), in the
  /// case's order.
  const std::vector<std::string>& heatExchangingGroups() const { return m_groups; }
  /// β of the contact wall called `wall` (0 when it gives none).
  double frictionHeatFraction(const std::string& wall) const;

 private:
  struct Transfer {
    std::string group;
    double coefficient, ambient;
  };
  std::vector<NodeValue> m_prescribed;
  std::vector<Transfer> m_transfer;
  std::vector<std::string> m_groups;  ///< heatExchangingGroups()
  std::map<std::string, double> m_frictionHeat;  ///< wall -> β ≠ 0
};

}  // namespace flowform
