// The two-level error estimate of every response (docs/theory.md §7).
//
// The mesh is refined once uniformly (every cell split in four, the .geo's curves kept); the
// converged solution u_h is interpolated on it (exactly: P1/Q1 fields are nested) with the
// contact statuses carried over, and one Newton step with the exact tangent K_f of the
// refined problem is taken:  u_f = I u_h − K_f⁻¹ R_f(I u_h). That step is the linearized
// solve on the refined mesh, so for every response φ
//
//     φ_f − φ_h = φ(u_f) − φ(u_h) ≈ φ(u_{h/2}) − φ(u_h)         (to O(|u_f − u_{h/2}|²)),
//
// and with an error that falls like h^p under uniform refinement,
//
//     φ(u) − φ(u_h) ≈ η_φ = (φ_f − φ_h) / (1 − 2^(−p)).
//
// p is the case's Error Estimation/Order (default 1: the die-lip corner of the extrusion makes
// the ram force first order in the corner size; on a smooth problem of order 2 the default
// over-estimates by 1.5 at most). The sensitivities get the same: dφ/dh by DDM at u_f on the
// refined mesh (one more factorization there), η = (dφ_f/dh − dφ_h/dh) / (1 − 2^(−p)).
//
// This is the dual-weighted residual with the adjoint solved on the refined space: with
// K_fᵀ z_f = ∂φ_f/∂q (the transposed factors of the same K_f), φ'(u_f − I u_h) = −z_fᵀ R_f(I u_h).
// Localized, −Σ_i R_f,i (z_f − I_h z_f)_i over the refined mesh's nodes i (I_h z_f the coarse
// interpolant, zero at the coarse nodes' own) gives each node's share; shared among the coarse
// cell's nodes by the shape functions, it is the nodal indicator the adaptive loop sizes the
// next mesh from. Only for responses linear in the reactions (Boundary Force, Mean Pressure).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "flowform/core/Types.hpp"

namespace flowform {

class Simulation;

struct ErrorEstimate {
  bool estimated = false;
  double order = 1.0;  ///< p
  /// η_φ ≈ φ(u) − φ(u_h), by response name.
  std::map<std::string, double> functionals;
  /// η of dφ/dh: response → parameter → value (when the case asks for sensitivities).
  std::map<std::string, std::map<std::string, double>> sensitivities;
  /// φ_f and dφ_f/dh on the refined mesh.
  std::map<std::string, double> refinedFunctionals;
  std::map<std::string, std::map<std::string, double>> refinedSensitivities;
  /// Per node of the coarse mesh and per indicator response: |share of η| (replicated).
  std::map<std::string, std::vector<double>> indicators;
  GO refinedDofs = 0;
  double seconds = 0.0;

  /// "functionals_error_estimate", "sensitivities_error_estimate" and "error_estimation"
  /// (method, order, refined dofs and responses, seconds) into the summary.
  void report(nlohmann::json& summary) const;
};

/// The two-level estimate of `coarse`'s converged responses (and sensitivities, when computed),
/// with indicators for `indicatorResponses`. Collective.
ErrorEstimate twoLevelEstimate(const Simulation& coarse, const std::vector<std::string>& indicatorResponses);

}  // namespace flowform
