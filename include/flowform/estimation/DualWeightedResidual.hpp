// Goal-oriented error estimates of the responses by the dual-weighted residual
// (docs/theory.md §7; Becker & Rannacher, Acta Numerica 2001):
//
//     φ(u) − φ(u_h) ≈ η_φ = −R(u_h)(z⁺ − z_h),
//
// R the weak residual of the discrete problem evaluated with test functions from a richer
// space, z_h the discrete adjoint, K_tᵀ z_h = ∂φ/∂x (one transposed solve with the factors of
// the exact Jacobian at the converged state), z⁺ a higher-order reconstruction of z_h. Galerkin
// orthogonality makes R(u_h)(z_h) = 0, so only z⁺ − z_h counts.
//
// The reconstruction: on each edge e = (a, b), the quadratic whose end values are z_a, z_b and
// whose end slopes come from the recovered nodal gradients G (area-weighted averages of the
// cell gradients of z_h) has at the midpoint (z_a + z_b)/2 + (G_a − G_b)·(x_b − x_a)/8. So
// z⁺ − z_h = Σ_e w_e φ_e with φ_e = 4 N_a N_b the P2 edge function and w_e = (G_a − G_b)·d_e/8,
// per component (u_x, u_y, p). Components held by a velocity constraint at both ends of an
// edge get no weight where the test space has none (a prescribed velocity; the constrained
// direction of a symmetry line). The contact forces are nodal; against the edge functions of
// an active wall segment they enter as tractions (nodal force / tributary length, linear).
//
// Implemented for the responses linear in the reactions (Boundary Force, Mean Pressure:
// φ = c·R_unc(x), ∂φ/∂x = J_uncᵀ c), on triangles (P1/P1). Others get no estimate.
#pragma once

#include <map>
#include <string>

#include "flowform/assembly/Responses.hpp"
#include "flowform/solvers/FlowModel.hpp"

namespace flowform {

/// η_φ for every response the method covers, by name (the same on every rank). The model's
/// factors are replaced by those of the exact Jacobian at x.
std::map<std::string, double> dualWeightedResidual(FlowModel& model, const Vector& x, const Responses& responses,
                                                   const Mesh& mesh, const std::vector<ContactWall>& walls);

}  // namespace flowform
