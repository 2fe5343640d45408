// The flow and the fields it carries as one physics kernel: a case with Material/Thermal (the
// temperature, docs/theory.md §10), Material/Strain Field (the equivalent strain, §1.1) or both.
// Owns and reads Velocity, Pressure and the fields; each cell's law is evaluated once for all
// the equations.
//
// Flow rows: addFlowResidual (physics/FlowResidual.hpp) with the law at the cell's field values
//
//   T_K = Σ_a N_a(x_K) T_a,   ε̃_K = ε_K held within [ε_min, ε_max], ε_K = Σ_a N_a(x_K) ε_a   (x_K the centroid)
//   σ̄ = σ̄(e_r; T_K, ε̃_K)
//
// (ε̃_K blended with the law's uniform strain while the solver's continuation switches the coupling
// on: physics/StrainField.hpp).
//
// (a law without a temperature or strain parameter ignores them: the coupling is then one way,
// flow → field). T_K and ε̃_K carry their dof derivatives: the Jacobian's blocks ∂R_u/∂T (softening
// as the metal heats) and ∂R_u/∂ε (hardening as it strains).
//
// Temperature rows (physics/TransportResidual.hpp with capacity ρc, conductivity k): with
// q = η s:D the plastic heating (s:D = 2 μ(e_r) D:D, the dissipation density the flow rows
// integrate, handed over point by point so that the plastic heat is the flow's dissipation exactly)
//
//   ρc u·∇T − ∇·(k ∇T) = q.
//
// Strain rows (physics/StrainField.hpp): u·∇ε − ∇·(κ_K ∇ε) = e_r − e0, κ_K = e0 h_K², e_r handed
// over point by point from the flow rows.
//
// One Newton solves the coupled system (every coupling block by Sacado). One kernel rather than
// a flow kernel and a kernel per field: separate kernels would evaluate the law once per kernel
// per cell on as many AD types, which made the coupled assembly 1.8 times the isothermal one
// (docs/BENCHMARKS.md §19).
#pragma once

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/PhysicsKernel.hpp"
#include "flowform/physics/StrainField.hpp"
#include "flowform/physics/ThermalProperties.hpp"
#include "flowform/physics/TransportResidual.hpp"

namespace flowform {

/// A scalar field's value at the cell's centroid from an element vector with it in slot `slot` of
/// `stride` components per node.
template <typename Scalar>
Scalar centroidValue(const CellGeometry& cell, const Scalar* values, int stride, int slot) {
  Scalar v = 0.0;
  for (int a = 0; a < cell.rule.numNodes; ++a) v += cell.centroid.N[0][a] * values[stride * a + slot];
  return v;
}

template <bool Thermal, bool Strain>
struct CoupledFlowKernel {
  static_assert(Thermal || Strain, "a flow without fields is FlowKernel");
  static constexpr int kT = kNumFlowComponents;                   ///< T's slot (Thermal)
  static constexpr int kE = kNumFlowComponents + (Thermal ? 1 : 0);  ///< ε's slot (Strain)
  static constexpr int kNumComponents = kNumFlowComponents + (Thermal ? 1 : 0) + (Strain ? 1 : 0);
  static constexpr bool kUsesStressDual = true;

  const char* name() const {
    return Thermal && Strain ? "Flow, energy and strain" : Thermal ? "Flow and energy" : "Flow and strain";
  }
  KernelFields fields() const {
    std::vector<std::string> names = {"Velocity", "Pressure"};
    if (Thermal) names.push_back(kTemperatureField);
    if (Strain) names.push_back(kStrainField);
    return {names, names};
  }

  template <typename Scalar, typename PScalar>
  void evaluate(const CellContext<PScalar>& c, const Scalar* values, Scalar* residual) const {
    constexpr int C = kNumComponents;
    const CellQuadrature& cq = c.cell.rule;
    const int nodes = cq.numNodes;
    // The flow rows, with the dissipation s:D and the strain rate e_r at each point, from the law at
    // the cell's fields.
    Scalar flow[EqualOrderLayout::numDofs(kMaxNodesPerCell)], flowResidual[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < kNumFlowComponents; ++i) {
        flow[EqualOrderLayout::index(a, i)] = values[C * a + i];
        flowResidual[EqualOrderLayout::index(a, i)] = 0.0;
      }
    Scalar T = 0.0, epsLaw = 0.0;
    if constexpr (Thermal) T = centroidValue(c.cell, values, C, kT);
    if constexpr (Strain) {
      const int s = strainParameter(c.material.law);
      epsLaw = coupledLawStrain(centroidValue(c.cell, values, C, kE), s >= 0 ? c.material.values[s] : PScalar(1.0),
                                *c.strainField);
    }
    const MaterialParameters<Scalar> material =
        atFieldValues(c.material, Thermal ? &T : nullptr, Strain ? &epsLaw : nullptr);
    Scalar dissipation[kMaxQuadraturePoints], strainRate[kMaxQuadraturePoints];
    addFlowResidual(cq, c.cell.centroid, c.cell.diameter, c.settings, material, flow, flowResidual, c.dual,
                    Thermal ? dissipation : nullptr, Strain ? strainRate : nullptr);
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < kNumFlowComponents; ++i) residual[C * a + i] += flowResidual[EqualOrderLayout::index(a, i)];

    if constexpr (Thermal) {
      // k, ρc, η: the case's (FlowPhysics::thermal), an AD type when one is the parameter of a
      // derivative.
      Scalar heating[kMaxQuadraturePoints];
      for (int q = 0; q < cq.numPoints; ++q) heating[q] = c.thermal->heatFraction * dissipation[q];
      addTransportResidual(cq, c.settings.geometry, c.cell.diameter, c.thermal->capacity, c.thermal->conductivity,
                           values, C, kT, heating, residual);
    }
    if constexpr (Strain)
      addStrainResidual(cq, c.settings.geometry, c.cell.diameter, c.material.cutoff, values, C, kE, strainRate,
                        residual);
  }
};

}  // namespace flowform
