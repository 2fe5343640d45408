// The element residual of the stabilized rigid-viscoplastic flow (docs/theory.md §1), templated on
// the scalar type of the dofs (Scalar) and of the material parameters (PScalar). It never
// seeds or reads derivatives: the assembler does (Residual, Jacobian, ParamDeriv).
//
// For a cell K with shape functions N_a, velocity u, pressure p, body force f:
//
//   R_u[a] = ∫_K ( s : D(N_a e_i) − p div(N_a e_i) − N_a f_i ) dΩ,     s = 2 μ(e_r) D(u)
//   R_p[a] = ∫_K ( − N_a div u − τ_K grad N_a · (grad p − f) ) dΩ
//   τ_K    = β h_K² / (2 μ_K),  μ_K = μ at the cell centroid (current solution)
//
// Plane strain: dΩ = dx dy (per unit depth), D_zz = 0. Axisymmetric (x = r, y = z):
// D_θθ = u_r / r, div u = ∂u_r/∂r + u_r/r + ∂u_z/∂z, dΩ = 2π r dr dz.
// The −τ term is the Hughes–Franca–Balestra pressure stabilization with μ_K from the
// current solution (its dependence on u is part of the exact tangent).
#pragma once

#include <cmath>
#include <type_traits>

#include "flowform/core/Types.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/StressDual.hpp"

namespace flowform {

/// What the flow kernel needs besides geometry, dofs and the material.
struct FlowKernelSettings {
  Geometry geometry = Geometry::PlaneStrain;
  double beta = 0.0;                 ///< stabilization factor β
  double bodyForce[2] = {0.0, 0.0};  ///< f, force per unit volume
};

/// Strain rate at quadrature point q: D_xx, D_yy, D_xy, D_θθ (zero in plane strain).
template <typename Scalar>
struct StrainRate {
  Scalar xx, yy, xy, tt;
  Scalar ddot() const { return xx * xx + yy * yy + 2.0 * xy * xy + tt * tt; }
  Scalar divergence() const { return xx + yy + tt; }
};

template <typename Scalar>
StrainRate<Scalar> strainRateAt(const CellQuadrature& cq, int q, Geometry geometry,
                                const Scalar* dofs) {
  StrainRate<Scalar> d{0.0, 0.0, 0.0, 0.0};
  Scalar ur = 0.0;
  for (int a = 0; a < cq.numNodes; ++a) {
    const Scalar& ux = dofs[EqualOrderLayout::index(a, kUx)];
    const Scalar& uy = dofs[EqualOrderLayout::index(a, kUy)];
    d.xx += cq.dNdx[q][a] * ux;
    d.yy += cq.dNdy[q][a] * uy;
    d.xy += 0.5 * (cq.dNdy[q][a] * ux + cq.dNdx[q][a] * uy);
    ur += cq.N[q][a] * ux;
  }
  if (geometry == Geometry::Axisymmetric) d.tt = ur / cq.x[q];
  return d;
}

/// μ at the centroid of the cell (the one-point rule `centroid`): the μ_K of τ_K.
template <typename Scalar, typename PScalar>
Scalar centroidViscosity(const CellQuadrature& centroid, Geometry geometry, const MaterialParameters<PScalar>& material,
                         const Scalar* dofs) {
  const StrainRate<Scalar> dc = strainRateAt(centroid, 0, geometry, dofs);
  return viscosity(regularizedStrainRate(dc.ddot(), material), material);
}

/// τ_K = β h_K² / (2 μ_K), the stabilization parameter of the cell.
template <typename Scalar>
Scalar stabilizationTau(double beta, double hK, const Scalar& muK) {
  return beta * hK * hK / (2.0 * muK);
}

/// Adds the cell residual (EqualOrderLayout: u_x, u_y, p per node, node-major) into `residual`.
/// `cq` is the integration rule, `centroid` a one-point rule at the centroid (for μ_K),
/// `hK` the cell diameter. `dual` (the cell's points, Jacobian evaluations only; null: the
/// exact tangent) selects the stress–velocity linearization of s (physics/StressDual.hpp) and
/// is moved to this iterate first; the values are the same either way. `dissipation` (null:
/// none) receives the plastic power density s:D = 2 μ(e_r) D:D at each point of `cq`, with the
/// exact μ (never the dual's): what the energy equation's heating reads (kernels/
/// CoupledFlowKernel.hpp), the law evaluated once for both; `strainRate` (null: none) receives e_r
/// at each point (what the strain field's rows read, physics/StrainField.hpp).
template <typename Scalar, typename PScalar>
void addFlowResidual(const CellQuadrature& cq, const CellQuadrature& centroid, double hK,
                     const FlowKernelSettings& settings, const MaterialParameters<PScalar>& material,
                     const Scalar* dofs, Scalar* residual, StressDualPoint* dual = nullptr,
                     Scalar* dissipation = nullptr, Scalar* strainRate = nullptr) {
  const Geometry geometry = settings.geometry;
  const double fx = settings.bodyForce[0], fy = settings.bodyForce[1];

  const Scalar muK = centroidViscosity(centroid, geometry, material, dofs);
  const Scalar tau = stabilizationTau(settings.beta, hK, muK);
  // A one-point rule at the centroid (P1 in plane strain): its μ is μ_K, the same value from the
  // same operands; the law is evaluated once per cell.
  const bool centroidRule = cq.numPoints == 1 && cq.x[0] == centroid.x[0] && cq.y[0] == centroid.y[0];

  for (int q = 0; q < cq.numPoints; ++q) {
    const double w = measureWeight(cq, q, geometry);
    const StrainRate<Scalar> d = strainRateAt(cq, q, geometry, dofs);
    const Scalar ddot = d.ddot();
    const Scalar eReg = regularizedStrainRate(ddot, material);
    const Scalar mu = centroidRule ? muK : viscosity(eReg, material);
    if (dissipation) dissipation[q] = 2.0 * mu * ddot;
    if (strainRate) strainRate[q] = eReg;
    Scalar sxx = 2.0 * mu * d.xx, syy = 2.0 * mu * d.yy, sxy = 2.0 * mu * d.xy, stt = 2.0 * mu * d.tt;
    if constexpr (!std::is_same_v<Scalar, double>) {
      if (dual) {
        // s = 2 μ D in value; derivative 2μ dD + 2 e_r τ dμ with dμ = μ' (g : dD), so τ = D/e_r
        // gives back the exact tangent (physics/StressDual.hpp).
        const double D[4] = {d.xx.val(), d.yy.val(), d.xy.val(), d.tt.val()};
        dual[q].update(D, eReg.val());
        const double muV = mu.val(), twoE = 2.0 * eReg.val();
        const Scalar dMu = mu - muV;  // value 0, derivative dμ
        const double* t = dual[q].tau;
        sxx = 2.0 * muV * d.xx + twoE * t[0] * dMu;
        syy = 2.0 * muV * d.yy + twoE * t[1] * dMu;
        sxy = 2.0 * muV * d.xy + twoE * t[2] * dMu;
        stt = 2.0 * muV * d.tt + twoE * t[3] * dMu;
      }
    }
    const Scalar divU = d.divergence();

    Scalar p = 0.0, dpdx = 0.0, dpdy = 0.0;
    for (int a = 0; a < cq.numNodes; ++a) {
      const Scalar& pa = dofs[EqualOrderLayout::index(a, kP)];
      p += cq.N[q][a] * pa;
      dpdx += cq.dNdx[q][a] * pa;
      dpdy += cq.dNdy[q][a] * pa;
    }
    const Scalar gx = tau * (dpdx - fx), gy = tau * (dpdy - fy);
    const double invR = geometry == Geometry::Axisymmetric ? 1.0 / cq.x[q] : 0.0;

    for (int a = 0; a < cq.numNodes; ++a) {
      const double N = cq.N[q][a], Nx = cq.dNdx[q][a], Ny = cq.dNdy[q][a];
      // s : D(N_a e_x) = s_xx N_x + s_xy N_y + s_θθ N / r;  div(N_a e_x) = N_x + N / r
      residual[EqualOrderLayout::index(a, kUx)] +=
          w * (sxx * Nx + sxy * Ny + stt * (N * invR) - p * (Nx + N * invR) - N * fx);
      // s : D(N_a e_y) = s_xy N_x + s_yy N_y;  div(N_a e_y) = N_y
      residual[EqualOrderLayout::index(a, kUy)] += w * (sxy * Nx + syy * Ny - p * Ny - N * fy);
      residual[EqualOrderLayout::index(a, kP)] += w * (-N * divU - (Nx * gx + Ny * gy));
    }
  }
}

}  // namespace flowform
