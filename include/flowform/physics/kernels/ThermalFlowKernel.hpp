// The flow kernel of a case whose flow stress depends on the temperature (a law with a
// "Temperature" parameter, e.g. Sellars–Tegart, and a Temperature field: docs/theory.md §10):
// owns Velocity and Pressure as FlowKernel does, and reads Temperature too. Its element residual
// is addFlowResidual with the law at the cell's temperature
//
//   T_K = Σ_a N_a(x_K) T_a   (x_K the centroid),   σ̄ = σ̄(e_r; T_K)
//
// one temperature per cell, the same one the energy kernel's heating and the Plastic Power
// response use (so that the plastic heat is the flow's dissipation exactly). T_K carries its
// dof derivative: the Jacobian has the coupling block ∂R_u/∂T (softening as the metal heats).
#pragma once

#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/discretization/ShapeFunctions.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/PhysicsKernel.hpp"

namespace flowform {

/// The cell's temperature T_K at its centroid from an element vector with T in slot `slot` of
/// `stride` components per node.
template <typename Scalar>
Scalar centroidTemperature(const CellGeometry& cell, const Scalar* values, int stride, int slot) {
  Scalar T = 0.0;
  for (int a = 0; a < cell.rule.numNodes; ++a) T += cell.centroid.N[0][a] * values[stride * a + slot];
  return T;
}

struct ThermalFlowKernel {
  static constexpr int kNumComponents = kNumFlowComponents + 1;  // u_x, u_y, p, T
  static constexpr int kT = kNumFlowComponents;
  static constexpr bool kUsesStressDual = true;

  const char* name() const { return "Flow (temperature-dependent law)"; }
  KernelFields fields() const { return {{"Velocity", "Pressure"}, {"Velocity", "Pressure", kTemperatureField}}; }

  template <typename Scalar, typename PScalar>
  void evaluate(const CellContext<PScalar>& c, const Scalar* values, Scalar* residual) const {
    constexpr int C = kNumComponents;
    const int nodes = c.cell.rule.numNodes;
    Scalar flow[EqualOrderLayout::numDofs(kMaxNodesPerCell)], flowResidual[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < kNumFlowComponents; ++i) {
        flow[EqualOrderLayout::index(a, i)] = values[C * a + i];
        flowResidual[EqualOrderLayout::index(a, i)] = 0.0;
      }
    const MaterialParameters<Scalar> material = atTemperature(c.material, centroidTemperature(c.cell, values, C, kT));
    addFlowResidual(c.cell.rule, c.cell.centroid, c.cell.diameter, c.settings, material, flow, flowResidual, c.dual);
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < kNumFlowComponents; ++i) residual[C * a + i] += flowResidual[EqualOrderLayout::index(a, i)];
  }
};

}  // namespace flowform
