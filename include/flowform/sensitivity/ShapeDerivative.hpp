// Total derivatives through the shape of free surfaces (docs/theory.md §3.5).
//
// At convergence the flow q and the surface unknowns b satisfy R(q, X(b); h) = 0 and
// b = U(q, X(b)) (UpdateLinearization). Differentiating along h, with dq = dq_frozen + Y db:
//     (I − G) db = U_q dq_frozen,
//     dφ/dh = dφ/dh|frozen + Σ_j (∂φ/∂b_j + φ_q Y_j) db_j.
// The flow part is the DDM's (the converged factors, one back-substitution per surface unknown);
// contact statuses and penalty scales are held, as in the DDM. Cost: two residual assemblies,
// mesh moves and update evaluations per surface unknown, one dense solve of their number.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace flowform {

class Problem;
class Sensitivity;

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
/// converged state of `problem` (after `sensitivity`'s compute there). Moves the mesh and
/// restores it; the factors of K_t at the converged state are left in the model.
ShapeDerivative totalShapeDerivative(Problem& problem, const Sensitivity& sensitivity);

}  // namespace flowform
