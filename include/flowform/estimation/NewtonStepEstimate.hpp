// The refined-space Newton step estimate of every response (Error Estimation/Method = Newton
// Step; docs/theory.md §7): the two-level estimate (TwoLevelEstimate.hpp) with the refined solve
// replaced by one Newton step from the interpolated solution, at the cost of one assembly and one
// factorization on the refined mesh.
//
// The mesh is refined once uniformly and u_h interpolated on it (exact: P1/Q1 are nested), the
// contact statuses carried over (ContactWall::takeStatusesFrom, a node inside an old zone
// limit decided by whether it moves into the tool), the free surfaces in their converged shape
// (carryShape). There, with R_f and K_f the refined residual and exact Jacobian at I u_h,
//
//     u_f¹ = I u_h − K_f⁻¹ R_f(I u_h),        φ_f − φ_h ≈ φ(u_f¹) − φ(u_h),
//
// and η_φ = (φ(u_f¹) − φ_h) / (1 − 2^(−p)) as in the two-level estimate. The step is the
// dual-weighted residual with the adjoint solved on the refined space, −z_fᵀ R_f(I u_h) with
// K_fᵀ z_f = ∂φ_f/∂q, plus the response's own nonlinearity in the step: the reaction responses
// are evaluated at u_f¹. `Error Estimation/Newton Steps` > 1 takes further chord steps
// u_f^(k+1) = u_f^k − K_f⁻¹ R_f(u_f^k) with the same factors (one residual assembly and one
// back-substitution each).
//
// The same factors give the rest by back-substitution: the indicators' adjoints
// (estimation/RefinedRun addIndicators) and the DDM sensitivities on the refined mesh at u_f¹,
// K_f dq_f/dh = −∂R_f/∂h(u_f¹) with K_f at I u_h (the DDM's "Last Newton Iterate"), from which
// η of dφ/dh = (dφ_f/dh − dφ_h/dh) / (1 − 2^(−p)); with free surfaces the total derivatives
// through them (ShapeDerivative) at u_f¹ on the carried shape.
//
// Neglected: the statuses and the free surfaces the refined solve would converge to (the step is
// taken at the carried ones) and the step's quadratic remainder. docs/BENCHMARKS.md measures the
// effectivity against the two-level estimate and against references.
#pragma once

#include <string>
#include <vector>

#include "flowform/estimation/CaseRun.hpp"
#include "flowform/estimation/ErrorEstimate.hpp"

namespace flowform {

struct NewtonStepEstimate {
  static constexpr const char* kName = "Newton Step";
  static constexpr const char* kDescription =
      "one Newton step on the uniformly refined mesh from the interpolated solution and contact statuses "
      "(one assembly and factorization there; Newton Steps > 1 adds chord steps), the adjoints and "
      "sensitivities by back-substitution with the same factors";
  /// The estimate of `coarse`'s converged responses (and sensitivities, when computed), with
  /// indicators for `indicatorResponses`; the refined problem is made by `makeRun`. When the
  /// refined Jacobian cannot be factored there is no estimate (`failure` says why). Collective.
  static ErrorEstimate estimate(const CaseRun& coarse, const CaseRunFactory& makeRun,
                                const std::vector<std::string>& indicatorResponses);
};

}  // namespace flowform
