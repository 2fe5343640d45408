// The flow and its steady energy balance as one physics kernel (docs/theory.md §10): a case with
// Material/Thermal. Owns and reads Velocity, Pressure and Temperature; each cell's law is
// evaluated once for both equations.
//
// Flow rows: addFlowResidual (physics/FlowResidual.hpp) with the law at the cell's temperature
//
//   T_K = Σ_a N_a(x_K) T_a   (x_K the centroid),   σ̄ = σ̄(e_r; T_K)
//
// (unchanged for a law without a temperature: the coupling is then one way, flow → heat). T_K
// carries its dof derivative: the Jacobian's block ∂R_u/∂T (softening as the metal heats).
//
// Temperature rows, with a = ρc u the heat-capacity flux and q = η s:D the plastic heating
// (s:D = 2 μ(e_r) D:D, the dissipation density the flow rows integrate, handed over point by
// point so that the plastic heat is the flow's dissipation exactly):
//
//   a·∇T − ∇·(k ∇T) = q
//
// weak form on a cell K, streamline-upwind/Petrov–Galerkin (Brooks–Hughes) with the test
// function N_a + τ_K a·∇N_a:
//
//   R_T[a] = ∫_K [ (N_a + τ_K a·∇N_a)(a·∇T − q) + k ∇N_a·∇T ] dΩ
//   τ_K    = ( (2|a|/h_K)² + 9 (4k/h_K²)² )^(−1/2)
//
// τ_K is the doubly asymptotic form (Shakib): h_K/(2|a|) where convection dominates (cell Péclet
// number |a| h_K / 2k ≫ 1), h_K²/(12 k) where diffusion does, and smooth in u (its argument is
// ≥ (12k/h_K²)² > 0, so no regularization is needed before the square root). The SUPG term
// drops the diffusion of T_h inside the cell (zero on linear triangles, small on bilinear
// quadrilaterals), the usual approximation. Boundaries without a condition are insulated
// (k ∂T/∂n = 0: the natural condition); prescribed temperatures are rows T − T_b. Plane
// strain: dΩ = dx dy; axisymmetric: dΩ = 2π r dr dz, D_θθ = u_r/r in s:D.
//
// One Newton solves the coupled system (the Jacobian's blocks ∂R_T/∂u and ∂R_u/∂T by Sacado).
// One kernel rather than a flow kernel and an energy kernel: two would evaluate the law twice per
// cell on two AD types, which made the coupled assembly 1.8 times the isothermal one
// (docs/BENCHMARKS.md §19).
#pragma once

#include <cmath>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/PhysicsKernel.hpp"
#include "flowform/physics/ThermalProperties.hpp"

namespace flowform {

/// The cell's temperature T_K at its centroid from an element vector with T in slot `slot` of
/// `stride` components per node.
template <typename Scalar>
Scalar centroidTemperature(const CellGeometry& cell, const Scalar* values, int stride, int slot) {
  Scalar T = 0.0;
  for (int a = 0; a < cell.rule.numNodes; ++a) T += cell.centroid.N[0][a] * values[stride * a + slot];
  return T;
}

struct ThermoMechanicalKernel {
  static constexpr int kNumComponents = kNumFlowComponents + 1;  // u_x, u_y, p, T
  static constexpr int kT = kNumFlowComponents;
  static constexpr bool kUsesStressDual = true;

  const char* name() const { return "Flow and energy"; }
  KernelFields fields() const {
    return {{"Velocity", "Pressure", kTemperatureField}, {"Velocity", "Pressure", kTemperatureField}};
  }

  template <typename Scalar, typename PScalar>
  void evaluate(const CellContext<PScalar>& c, const Scalar* values, Scalar* residual) const {
    constexpr int C = kNumComponents;
    using std::sqrt;
    const CellQuadrature& cq = c.cell.rule;
    const int nodes = cq.numNodes;
    // The flow rows, and the dissipation s:D at each point, from the law at T_K.
    Scalar flow[EqualOrderLayout::numDofs(kMaxNodesPerCell)], flowResidual[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < kNumFlowComponents; ++i) {
        flow[EqualOrderLayout::index(a, i)] = values[C * a + i];
        flowResidual[EqualOrderLayout::index(a, i)] = 0.0;
      }
    const MaterialParameters<Scalar> material = atTemperature(c.material, centroidTemperature(c.cell, values, C, kT));
    Scalar dissipation[kMaxQuadraturePoints];
    addFlowResidual(cq, c.cell.centroid, c.cell.diameter, c.settings, material, flow, flowResidual, c.dual,
                    dissipation);
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < kNumFlowComponents; ++i) residual[C * a + i] += flowResidual[EqualOrderLayout::index(a, i)];

    // The temperature rows. k, ρc, η: the case's (FlowPhysics::thermal), an AD type when one is
    // the parameter of a derivative.
    const Geometry geometry = c.settings.geometry;
    const PScalar k = c.thermal->conductivity, rhoC = c.thermal->capacity, eta = c.thermal->heatFraction;
    const double h = c.cell.diameter;
    const PScalar diffusive = 9.0 * (4.0 * k / (h * h)) * (4.0 * k / (h * h));
    for (int q = 0; q < cq.numPoints; ++q) {
      const double w = measureWeight(cq, q, geometry);
      Scalar ax = 0.0, ay = 0.0, tx = 0.0, ty = 0.0;
      for (int a = 0; a < nodes; ++a) {
        ax += cq.N[q][a] * values[C * a + kUx];
        ay += cq.N[q][a] * values[C * a + kUy];
        tx += cq.dNdx[q][a] * values[C * a + kT];
        ty += cq.dNdy[q][a] * values[C * a + kT];
      }
      ax *= rhoC;
      ay *= rhoC;
      const Scalar heating = eta * dissipation[q];
      const Scalar tau = 1.0 / sqrt(4.0 * (ax * ax + ay * ay) / (h * h) + diffusive);
      const Scalar strong = ax * tx + ay * ty - heating;  // a·∇T − q (the diffusion of T_h dropped)
      for (int a = 0; a < nodes; ++a) {
        const double N = cq.N[q][a], Nx = cq.dNdx[q][a], Ny = cq.dNdy[q][a];
        residual[C * a + kT] += w * ((N + tau * (ax * Nx + ay * Ny)) * strong + k * (Nx * tx + Ny * ty));
      }
    }
  }
};

}  // namespace flowform
