#include "flowform/problem/EnergyBalance.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include <nlohmann/json.hpp>

#include "flowform/assembly/CellMaterial.hpp"
#include "flowform/physics/ThermalProperties.hpp"
#include "flowform/problem/Problem.hpp"
#include "flowform/responses/HeatFlow.hpp"
#include "flowform/responses/FluxWeightedMean.hpp"
#include "flowform/responses/TemperatureResponses.hpp"
#include "flowform/responses/WallPowers.hpp"

namespace flowform {

namespace {

/// C = ∫ ρc u·∇T dΩ over this rank's cells, on the kernels' quadrature (CoupledFlowKernel's Galerkin
/// convection term tested with Σ_a N_a = 1).
double convectedHeat(const Workset& x, const Mesh& mesh, const DofMap& dofMap, Geometry geometry, double rhoC) {
  const int components[3] = {kUx, kUy, dofMap.fields().component(kTemperatureField)};
  const int npc = dofMap.nodesPerCell();
  CellGeometry g;
  LO dofs[3 * kMaxNodesPerCell];
  double values[3 * kMaxNodesPerCell];
  double local = 0.0;
  for (size_t k = 0; k < dofMap.cells().size(); ++k) {
    computeCellGeometry(mesh, dofMap.cells()[k], geometry, g);
    dofMap.cellDofs(k, components, 3, dofs);
    gather(x, dofs, 3 * npc, values);
    for (int q = 0; q < g.rule.numPoints; ++q) {
      double ux = 0.0, uy = 0.0, tx = 0.0, ty = 0.0;
      for (int a = 0; a < npc; ++a) {
        ux += g.rule.N[q][a] * values[3 * a];
        uy += g.rule.N[q][a] * values[3 * a + 1];
        tx += g.rule.dNdx[q][a] * values[3 * a + 2];
        ty += g.rule.dNdy[q][a] * values[3 * a + 2];
      }
      local += measureWeight(g.rule, q, geometry) * rhoC * (ux * tx + uy * ty);
    }
  }
  return local;
}

}  // namespace

EnergyBalance energyBalance(const Problem& problem) {
  const Mesh& mesh = problem.mesh();
  const DofMap& dofMap = problem.dofMap();
  const Comm& comm = *dofMap.comm();
  const Assembler& assembler = problem.assembler();
  const Teuchos::ParameterList& params = problem.parameters();
  const ThermalProperties& thermal = problem.physics().thermal;
  const ThermalBoundaryConditions conditions(params.sublist("Boundary Conditions"), mesh);
  const double rhoC = thermal.capacity();
  const int t = dofMap.fields().component(kTemperatureField);

  Vector reactions(dofMap.ownedMap()), xOverlap(dofMap.overlapMap());
  assembler.residual(problem.solution(), reactions, false);
  xOverlap.doImport(problem.solution(), *dofMap.importer(), Tpetra::INSERT);
  const Workset x = vectorReader(xOverlap), R = vectorReader(reactions);
  const ResponseContext<double> c{x, R, mesh, dofMap, assembler.physics(), assembler.physics().material,
                                  problem.contactWalls(), nullptr};

  EnergyBalance b;
  double plastic = 0.0, stabilization = 0.0, deadArea = 0.0;
  cellIntegrals(x, mesh, dofMap, assembler.physics(), c.material, 0.0, plastic, stabilization, deadArea);
  b.plasticHeat = thermal.heatFraction * sumOverRanks(comm, plastic);
  double made = b.plasticHeat;
  for (const ContactWall& wall : problem.contactWalls()) {
    const double power = FrictionPower::of(c, wall.name());
    b.frictionPower[wall.name()] = power;
    b.frictionHeat[wall.name()] = conditions.frictionHeatFraction(wall.name()) * power;
    made += b.frictionHeat[wall.name()];
  }
  // The heat that leaves: −R_T at the nodes of the groups that hold or transfer T (each node once
  // for the total; a node two such groups share is in both groups' Heat Flow).
  std::vector<char> thermalNode(mesh.numNodes(), 0);
  for (const std::string& group : conditions.heatExchangingGroups()) {
    for (const auto& edge : mesh.boundary(group).edges) thermalNode[edge[0]] = thermalNode[edge[1]] = 1;
    Teuchos::ParameterList p;
    p.set("Boundary", group);
    try {
      b.heatOut[group] = HeatFlow(p).evaluate(c);
    } catch (const std::exception&) {  // not one simple curve: in the total only
      b.groupsLeftOut.push_back(group);
    }
  }
  double out = 0.0;
  for (LO n = 0; n < dofMap.numOwnedNodes(); ++n)
    if (thermalNode[dofMap.overlapNodes()[n]]) out -= R.x(dofMap.dof(n, t), 0);
  b.heatOutTotal = sumOverRanks(comm, out);
  b.convected = sumOverRanks(comm, convectedHeat(x, mesh, dofMap, c.geometry(), rhoC));

  // Per group: the flux and the temperature flux crossing it (the Mean Temperature's sums, FluxWeightedMean.hpp).
  std::vector<std::pair<std::string, Crossing<double>>> crossings;
  double largest = 0.0;
  for (const BoundaryGroup& group : mesh.boundaries) {
    // A group that is not one simple curve (several pieces, a branch) has no oriented normal here:
    // left out of the enthalpy flows and listed (the same on every rank: the mesh is replicated).
    BoundaryCurve curve;
    try {
      curve = buildBoundaryCurve(mesh, group);
    } catch (const std::exception&) {
      b.groupsLeftOut.push_back(group.name);
      continue;
    }
    crossings.emplace_back(group.name, crossing(c, curve, t));
    largest = std::max(largest, std::abs(crossings.back().second.flux));
  }
  // T_ref: the mixing-cup temperature of what enters through the groups that carry material in
  // (a wall's flux is the penalty's small penetration: below 1e-3 of the largest, left out).
  double inFlux = 0.0, inHeat = 0.0;
  for (const auto& [group, through] : crossings)
    if (through.flux < -1e-3 * largest) {
      inFlux += through.flux;
      inHeat += through.valueFlux;
    }
  b.referenceTemperature = inFlux < 0.0 ? inHeat / inFlux : 0.0;
  double enthalpy = 0.0;
  for (const auto& [group, through] : crossings) {
    b.enthalpyFlow[group] = rhoC * (through.valueFlux - b.referenceTemperature * through.flux);
    enthalpy += b.enthalpyFlow[group];
  }
  b.heatMade = made;
  b.imbalance = made - b.heatOutTotal - b.convected;
  b.massLossTerm = b.convected - enthalpy;
  // The balance's scale: the largest of its flows (the heat made is 0 in a case without heating
  // that only cools, e.g. an extrudate in air).
  double flows = 0.0;
  for (const auto& [group, e] : b.enthalpyFlow) flows += std::abs(e);
  b.scale = std::max({std::abs(made), std::abs(b.heatOutTotal), flows});
  b.enthalpyClosure = b.scale > 0.0 ? (made - b.heatOutTotal - enthalpy) / b.scale : 0.0;
  return b;
}

void EnergyBalance::report(nlohmann::json& summary) const {
  summary["energy_balance"] = {{"reference_temperature", referenceTemperature},
                               {"plastic_heat", plasticHeat},
                               {"friction_power", frictionPower},
                               {"friction_heat", frictionHeat},
                               {"heat_made", heatMade},
                               {"heat_out", heatOut},
                               {"heat_out_total", heatOutTotal},
                               {"enthalpy_flow", enthalpyFlow},
                               {"convected", convected},
                               {"mass_loss_term", massLossTerm},
                               {"imbalance", imbalance},
                               {"scale", scale},
                               {"relative_imbalance", scale > 0.0 ? imbalance / scale : 0.0},
                               {"enthalpy_closure", enthalpyClosure},
                               {"groups_left_out", groupsLeftOut}};
}

}  // namespace flowform
