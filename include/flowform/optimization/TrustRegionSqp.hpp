// Constrained designs (docs/optimization.md §1): a trust-region Sℓ1QP (Fletcher's sequential
// ℓ1-penalty quadratic programming) on the scaled design z ∈ [0, 1]^n,
//
//   min J(z)  subject to  l_i <= c_i(z) <= u_i,
//
// each iteration one solve of the case (J, ∇J, c and its Jacobian A from the same solve's DDM
// derivatives). The step d minimizes the model of the ℓ1 merit Φ(z) = J + ρ Σ_i viol_i(c(z)),
//
//   q(d) = ∇J·d + ½ dᵀ B d + ρ Σ_i viol_i(c + A d),   max(−z, −Δ) <= d <= min(1 − z, Δ),
//
// (B: the misfit's Gauss–Newton Hessian, or a damped BFGS of the objective's gradients from B = 0),
// written with elastic variables p, q >= 0 (l <= c + A d + p − q <= u, ρ Σ (p + q)) as a small
// dense convex QP (DenseQp: an interior-point method; no solve of the case). The step is taken
// when the merit falls by at least 10 % of the model's prediction; the radius Δ grows after good
// steps and shrinks after poor ones (or a design that did not solve). ρ is raised tenfold while
// that lowers the model's linearized violation (steering). Converged when the linearized merit's
// decrease over a unit box, χ (a first-order stationarity measure of the ℓ1
// merit: 0 at a KKT point with ρ above the multipliers), is below the gradient tolerance and the
// constraints hold to their tolerance. ROL's own general-constraint algorithms (augmented
// Lagrangian, stabilized LCL, Moreau–Yosida) remain selectable; on the shipped decisions they
// stopped infeasible or took 36–551 solves (docs/BENCHMARKS.md §21.1); ROL's augmented Lagrangian
// also stalled on the QP below, hence DenseQp.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "flowform/optimization/DesignConstraint.hpp"
#include "flowform/optimization/DesignObjective.hpp"
#include "flowform/optimization/OptimizationSettings.hpp"

namespace flowform {

/// A constraint within this many Constraint Tolerances of a bound is active (its multiplier is
/// estimated; summary.json marks it "active").
constexpr double kActiveFactor = 10.0;

struct SqpResult {
  std::vector<double> z;  ///< the last accepted design (scaled)
  int iterations = 0;
  bool converged = false;
  std::string status;
  double criticality = 0.0;  ///< χ at z
  double violation = 0.0;    ///< Σ_i viol_i(c(z)), scaled
  double penalty = 0.0;      ///< ρ
  /// λ_i of ∇J + Σ λ_i ∇c_i + (active design bounds) = 0 over the active constraints (0 elsewhere),
  /// by least squares: −λ_i is dJ*/d(the active bound of c_i).
  std::vector<double> multipliers;
};

/// Runs the SQP from the scaled design `z` (DesignNotSolved from the first design only: a later
/// design that does not solve shrinks the trust region).
SqpResult runTrustRegionSqp(DesignObjective& objective, DesignConstraint& constraint, std::vector<double> z,
                            const OptimizationSettings& settings, std::ostream& out);

}  // namespace flowform
