// Total derivatives through the shape of free surfaces (docs/theory.md §3.5).
//
// At convergence the flow q and the surface unknowns b (the spine coordinates of the nodes the
// update places on streamlines) satisfy
//     R(q, X(b); h) = 0            the discrete flow on the mesh X(b) (interior by the harmonic
//                                  extension E of the surface move),
//     b = U(q, X(b))               the spine update (FreeSurfaces::step).
// Differentiating along h, with dq = dq_frozen + Y db, Y = −K_t⁻¹ (∂R/∂X E) (one column per
// surface unknown, back-substitutions with the converged factors):
//     (I − G) db = U_q dq_frozen,    G = ∂U/∂b + U_q Y,
//     dφ/dh = dφ/dh|frozen + Σ_j (∂φ/∂b_j + φ_q Y_j) db_j.
// ∂R/∂X E, ∂U/∂b and ∂φ/∂b are central differences in the node positions (each surface
// unknown moved by ±ε = 10⁻⁶ × the surface length, the interior following by E); U_q and φ_q
// along Y_j and dq_frozen are central differences in q. The flow part is the DDM's (the
// converged factors, one back-substitution per surface unknown); the contact statuses and the
// penalty scales are held, as in the DDM. Cost: two residual assemblies, mesh moves and update
// evaluations per surface unknown, one dense solve of their number.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace flowform {

class Simulation;

struct ShapeDerivative {
  bool computed = false;
  std::string failure;  ///< why it was not computed
  /// dφ/dh through the moving surfaces: response → parameter → value.
  std::map<std::string, std::map<std::string, double>> responses;
  int unknowns = 0;           ///< surface unknowns b
  /// The spectral radius of G (power iteration): the plain update's contraction per step near
  /// the fixed point (< 1: it converges).
  double contraction = 0.0;
  double seconds = 0.0;
  /// "sensitivities_total_shape" and the "shape_derivative" block into the summary.
  void report(nlohmann::json& summary) const;
};

/// The total derivatives of the responses with respect to the sensitivity parameters at the
/// converged state of `sim` (after Sensitivity::compute). Moves the mesh and restores it; the
/// factors of K_t at the converged state are left in the model.
ShapeDerivative totalShapeDerivative(Simulation& sim);

}  // namespace flowform
