// The refined-space Newton step estimate of every response (Error Estimation/Method = Newton
// Step; docs/theory.md §7): the two-level estimate (TwoLevelEstimate.hpp) with the refined solve
// replaced by a few Newton steps from the interpolated solution, without the contact-status loop.
//
// The mesh is refined once uniformly and u_h interpolated on it (exact: P1/Q1 are nested), the
// contact statuses carried over (ContactWall::takeStatusesFrom, a node inside an old zone
// limit decided by whether it moves into the tool). There, from u_f⁰ = I u_h,
//
//     u_f^(k+1) = u_f^k − K_f(u_f^k)⁻¹ R_f(u_f^k),        φ_f − φ_h ≈ φ(u_f^k) − φ(u_h),
//
// and η_φ = (φ(u_f^k) − φ_h) / (1 − 2^(−p)) as in the two-level estimate. The first step, with
// the exact K_f at I u_h, is the dual-weighted residual with the adjoint solved on the refined
// space (−z_fᵀ R_f(I u_h), K_fᵀ z_f = ∂φ_f/∂q) plus the response's own nonlinearity; on the
// power-law extrusion it overshoots (effectivity 1.5–4.9: the exact tangent of a nearly
// rigid-plastic law is soft along D, docs/theory.md §9), so the steps go on with the case's
// Newton linearization (the dual one by default). Before each new factorization a chord step
// with the factors at hand (one residual, one back-substitution) tests whether the responses
// have settled: every differentiable response moved by at most `Step Tolerance` (0.1) times its
// distance from φ_h. Then the chord step is kept and the steps end; else a Newton step follows,
// at most `Newton Steps` (8) factorizations (not settled then: error_estimation.details says
// so and the log warns). On the extrusion at ν ≤ 0.1: 2 Newton steps and one chord step.
//
// The DDM sensitivities on the refined mesh are taken at the last iterate with K_f factored
// there exactly (one more factorization, Sensitivity's "Converged": the last step's factors,
// one iterate behind, gave dF/dν effectivities 0.77 for 0.99), η of dφ/dh =
// (dφ_f/dh − dφ_h/dh) / (1 − 2^(−p)). The adaptive loop's indicators are the two-level
// estimate's, made the same way (estimation/RefinedRun addIndicators at I u_h with the zone
// limits left free), which costs one more factorization: the steps start from the zone limits
// decided, where the die lip's penalty residual takes the indicators (TwoLevelEstimate.cpp).
// Measured: the indicators from the first step's factors there coarsen the bulk cycle after
// cycle, and the extrusion scenes' loops end unmet after 8 cycles (docs/BENCHMARKS.md §15).
//
// Neglected: status changes the refined status loop would make (none on the extrusion at
// ν ≤ 0.1 from the carried statuses); statuses decided inside the residual (a semi-smooth
// contact law) the steps see as any other nonlinearity. Free surfaces: at the carried shape a step leaves the
// shape's responses (the swell) as they are, so a case with free surfaces gets the two-level
// estimate (error_estimation.details.free_surface_fallback = 1). docs/BENCHMARKS.md measures both.
#pragma once

#include <string>
#include <vector>

#include "flowform/estimation/CaseRun.hpp"
#include "flowform/estimation/ErrorEstimate.hpp"

namespace flowform {

struct NewtonStepEstimate {
  static constexpr const char* kName = "Newton Step";
  static constexpr const char* kDescription =
      "Newton steps on the uniformly refined mesh from the interpolated solution and contact statuses until a chord "
      "step moves the responses by at most Step Tolerance of their estimates (at most Newton Steps factorizations; "
      "2 and a chord step on the extrusion), the sensitivities with one more factorization; with free surfaces "
      "the two-level estimate";
  /// The estimate of `coarse`'s converged responses (and sensitivities, when computed), with
  /// indicators for `indicatorResponses`; the refined problem is made by `makeRun`. When the
  /// refined Jacobian cannot be factored there is no estimate (`failure` says why). Collective.
  static ErrorEstimate estimate(const CaseRun& coarse, const CaseRunFactory& makeRun,
                                const std::vector<std::string>& indicatorResponses,
                                const IndicatorsWanted& wanted = {});
};

}  // namespace flowform
