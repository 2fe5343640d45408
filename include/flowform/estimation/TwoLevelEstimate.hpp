// The two-level error estimate of every response (Error Estimation/Method = Two-Level;
// docs/theory.md §7): the reference the cheaper Newton Step estimate (NewtonStepEstimate.hpp) is
// measured against.
//
// The mesh is refined once uniformly (every cell split in four, the .geo's curves kept); the
// converged solution u_h is interpolated on it (exactly: P1/Q1 fields are nested) with the
// contact statuses carried over, and the refined problem is solved from there (Newton at the
// target, then the contact-status loop; no continuation): u_f. For every response φ
//
//     φ_f − φ_h = φ(u_f) − φ(u_h),
//
// and with an error that falls like h^p under uniform refinement,
//
//     φ(u) − φ(u_h) ≈ η_φ = (φ_f − φ_h) / (1 − 2^(−p)).
//
// p is the case's Error Estimation/Order (default 1: the die-lip corner of the extrusion makes
// the ram force first order in the corner size; on a smooth problem of order 2 the default
// over-estimates by 1.5 at most). The sensitivities get the same: dφ/dh by DDM at u_f on the
// refined mesh (one more factorization and back-substitution there),
// η = (dφ_f/dh − dφ_h/dh) / (1 − 2^(−p)), and so do the total derivatives through moving free
// surfaces (ShapeDerivative on the refined mesh).
//
// With free surfaces the refined mesh first takes the converged shape (carryShape: the refined
// nodes placed in the moved coarse cells as they lay in the cells as made), and the refined
// free-surface loop starts from there, not from the .geo's starting shape.
//
// The indicators are the dual-weighted residual with the adjoint solved on the refined space:
// with K_fᵀ z_f = ∂φ_f/∂q (the transposed factors of the exact K_f at I u_h), the linearized
// change is φ'(δu) = −z_fᵀ R_f(I u_h). (As an estimate this linearization fails on the
// extrusion: the refined solve changes contact statuses; docs/theory.md §7.)
// Localized with ζ_f = c − z_f (the adjoint carrying the response's Dirichlet data, smooth at the
// response's group; estimation/ResponseAdjoint.hpp): Σ_i R_f,i (ζ_f − I_h ζ_f)_i over the refined
// mesh's nodes i (I_h ζ_f the coarse interpolant, equal to ζ_f at the coarse nodes) gives each
// node's share; shared among the coarse cell's nodes by the shape functions, it is the nodal
// indicator the adaptive loop sizes the next mesh from. Only for responses linear in the reactions (Boundary Force, Mean Pressure).
#pragma once

#include <string>
#include <vector>

#include "flowform/estimation/CaseRun.hpp"
#include "flowform/estimation/ErrorEstimate.hpp"

namespace flowform {

struct TwoLevelEstimate {
  static constexpr const char* kName = "Two-Level";
  static constexpr const char* kDescription =
      "the case solved again on the uniformly refined mesh from the interpolated solution and contact statuses "
      "(Newton, the contact-status loop, the free-surface loop: the reference, about half of a run)";
  /// The two-level estimate of `coarse`'s converged responses (and sensitivities, when
  /// computed), with indicators for `indicatorResponses`; the refined run is made by `makeRun`
  /// (the case on the mesh refined once more). When the refined solve does not converge there
  /// is no estimate: `estimated` false and `failure` says why. Collective.
  static ErrorEstimate estimate(const CaseRun& coarse, const CaseRunFactory& makeRun,
                                const std::vector<std::string>& indicatorResponses,
                                const IndicatorsWanted& wanted = {});
};

}  // namespace flowform
