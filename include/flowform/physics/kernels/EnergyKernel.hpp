// The steady energy balance of the flowing metal as a physics kernel: owns Temperature, reads
// Velocity and Temperature (docs/theory.md §10). Present only in a case with Material/Thermal.
//
// Strong form, with a = ρc u the heat-capacity flux and q = η s:D the plastic heating
// (s = 2 μ(e_r) D the deviatoric stress of the flow, so s:D = 2 μ D:D, the plastic power
// density the flow dissipates):
//
//   a·∇T − ∇·(k ∇T) = q
//
// Weak form on a cell K, streamline-upwind/Petrov–Galerkin (Brooks–Hughes) with the test
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
// q uses the law at the cell's temperature T_K (the flow kernel's, ThermalFlowKernel.hpp), so it
// is the flow's dissipation in every cell. With a temperature-independent law the flow does not
// read T and the coupling is one way; either way the system is solved as one (one Newton, the
// Jacobian's blocks ∂R_T/∂u and, with ThermalFlowKernel, ∂R_u/∂T by Sacado).
#pragma once

#include <cmath>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/PhysicsKernel.hpp"
#include "flowform/physics/ThermalProperties.hpp"
#include "flowform/physics/kernels/ThermalFlowKernel.hpp"

namespace flowform {

struct EnergyKernel {
  // Element vector per node: u_x, u_y, T — the flow's layout with T in p's slot, so
  // strainRateAt (which reads slots kUx, kUy of a 3-component node) applies unchanged.
  static constexpr int kNumComponents = 3;
  static constexpr int kT = 2;
  static_assert(kNumComponents == EqualOrderLayout::kFieldsPerNode && kUx == 0 && kUy == 1,
                "strainRateAt reads u_x, u_y at the flow layout's slots");
  static constexpr bool kUsesStressDual = false;


  const char* name() const { return "Energy"; }
  KernelFields fields() const { return {{kTemperatureField}, {"Velocity", kTemperatureField}}; }

  template <typename Scalar, typename PScalar>
  void evaluate(const CellContext<PScalar>& c, const Scalar* values, Scalar* residual) const {
    constexpr int C = kNumComponents;
    using std::sqrt;
    const CellQuadrature& cq = c.cell.rule;
    const Geometry geometry = c.settings.geometry;
    // k, ρc, η: the case's (FlowPhysics::thermal), an AD type when one is the parameter of a derivative.
    const PScalar k = c.thermal->conductivity, rhoC = c.thermal->capacity, eta = c.thermal->heatFraction;
    const double h = c.cell.diameter;
    const PScalar diffusive = 9.0 * (4.0 * k / (h * h)) * (4.0 * k / (h * h));
    // The law at the cell's temperature T_K, as the flow kernel's (ThermalFlowKernel.hpp): the
    // heat is the flow's dissipation exactly (unchanged for a law without a temperature).
    const MaterialParameters<Scalar> material = atTemperature(c.material, centroidTemperature(c.cell, values, C, kT));
    for (int q = 0; q < cq.numPoints; ++q) {
      const double w = measureWeight(cq, q, geometry);
      Scalar ax = 0.0, ay = 0.0, tx = 0.0, ty = 0.0;
      for (int a = 0; a < cq.numNodes; ++a) {
        ax += cq.N[q][a] * values[C * a + kUx];
        ay += cq.N[q][a] * values[C * a + kUy];
        tx += cq.dNdx[q][a] * values[C * a + kT];
        ty += cq.dNdy[q][a] * values[C * a + kT];
      }
      ax *= rhoC;
      ay *= rhoC;
      const StrainRate<Scalar> d = strainRateAt(cq, q, geometry, values);
      const Scalar ddot = d.ddot();
      const Scalar heating = eta * 2.0 * viscosity(regularizedStrainRate(ddot, material), material) * ddot;
      const Scalar tau = 1.0 / sqrt(4.0 * (ax * ax + ay * ay) / (h * h) + diffusive);
      const Scalar strong = ax * tx + ay * ty - heating;  // a·∇T − q (the diffusion of T_h dropped)
      for (int a = 0; a < cq.numNodes; ++a) {
        const double N = cq.N[q][a], Nx = cq.dNdx[q][a], Ny = cq.dNdy[q][a];
        residual[C * a + kT] += w * ((N + tau * (ax * Nx + ay * Ny)) * strong + k * (Nx * tx + Ny * ty));
      }
    }
  }
};

}  // namespace flowform
