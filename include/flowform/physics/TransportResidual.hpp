// The rows of a scalar φ carried by the flow (docs/theory.md §10, §1.1): the steady balance
//
//   c u·∇φ − ∇·(k ∇φ) = q
//
// with c the capacity (ρc for the temperature, 1 for the strain), k the diffusivity and q the
// source at each point (the plastic heating η s:D; the strain rate), weak form on a cell K,
// streamline-upwind/Petrov–Galerkin (Brooks–Hughes) with a = c u and the test function
// N_a + τ_K a·∇N_a:
//
//   R_φ[a] = ∫_K [ (N_a + τ_K a·∇N_a)(a·∇φ − q) + k ∇N_a·∇φ ] dΩ
//   τ_K    = ( (2|a|/h_K)² + 9 (4k/h_K²)² )^(−1/2)
//
// τ_K is the doubly asymptotic form (Shakib): h_K/(2|a|) where convection dominates (cell Péclet
// number |a| h_K / 2k ≫ 1), h_K²/(12 k) where diffusion does, and smooth in u (its argument is
// ≥ (12k/h_K²)² > 0, so no regularization is needed before the square root). The SUPG term
// drops the diffusion of φ_h inside the cell (zero on linear triangles, small on bilinear
// quadrilaterals), the usual approximation. Boundaries without a condition have k ∂φ/∂n = 0 (the
// natural condition); prescribed values are rows φ − φ_b. Plane strain: dΩ = dx dy;
// axisymmetric: dΩ = 2π r dr dz, u = (u_r, u_z).
#pragma once

#include <cmath>

#include "flowform/core/Types.hpp"
#include "flowform/discretization/CellGeometry.hpp"

namespace flowform {

/// Adds R_φ into `residual` (node-major, `stride` components per node, φ in slot `slot`, the
/// velocity in kUx, kUy). `source[q]` is q at point q of `cq`; `hK` the cell diameter.
template <typename Scalar, typename CScalar, typename KScalar>
void addTransportResidual(const CellQuadrature& cq, Geometry geometry, double hK, const CScalar& capacity,
                          const KScalar& diffusivity, const Scalar* values, int stride, int slot, const Scalar* source,
                          Scalar* residual) {
  using std::sqrt;
  const int nodes = cq.numNodes;
  const double h = hK;
  const KScalar& k = diffusivity;
  const KScalar diffusive = 9.0 * (4.0 * k / (h * h)) * (4.0 * k / (h * h));
  for (int q = 0; q < cq.numPoints; ++q) {
    const double w = measureWeight(cq, q, geometry);
    Scalar ax = 0.0, ay = 0.0, px = 0.0, py = 0.0;
    for (int a = 0; a < nodes; ++a) {
      ax += cq.N[q][a] * values[stride * a + kUx];
      ay += cq.N[q][a] * values[stride * a + kUy];
      px += cq.dNdx[q][a] * values[stride * a + slot];
      py += cq.dNdy[q][a] * values[stride * a + slot];
    }
    ax *= capacity;
    ay *= capacity;
    const Scalar tau = 1.0 / sqrt(4.0 * (ax * ax + ay * ay) / (h * h) + diffusive);
    const Scalar strong = ax * px + ay * py - source[q];  // a·∇φ − q (the diffusion of φ_h dropped)
    for (int a = 0; a < nodes; ++a) {
      const double N = cq.N[q][a], Nx = cq.dNdx[q][a], Ny = cq.dNdy[q][a];
      residual[stride * a + slot] += w * ((N + tau * (ax * Nx + ay * Ny)) * strong + k * (Nx * px + Ny * py));
    }
  }
}

}  // namespace flowform
