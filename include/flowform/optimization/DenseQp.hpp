// A small dense convex quadratic program (the SQP's subproblem, a handful of variables):
//
//   min ½ xᵀ H x + fᵀ x   subject to   G x <= h,
//
// H symmetric positive semidefinite (0 for a linear program), by Mehrotra's primal–dual interior
// point method: with slacks s = h − G x >= 0 and multipliers z >= 0, Newton on
//   H x + f + Gᵀ z = 0,   G x + s − h = 0,   s∘z = σμ e,
// each step from the normal equations (H + Gᵀ S⁻¹Z G) Δx = …, the affine predictor choosing the
// centring σ = (μ_aff/μ)³, the step kept 99 % inside the positive orthant. The feasible set must be
// bounded (box rows on every variable): then the normal matrix is positive definite.
#pragma once

#include <vector>

namespace flowform {

struct DenseQpResult {
  std::vector<double> x;
  std::vector<double> z;  ///< the multipliers of G x <= h
  bool converged = false;
  int iterations = 0;
};

/// Solves M y = b in place (M symmetric positive definite, small) by Cholesky; false (b untouched)
/// when a pivot falls to `relativePivot` of M's largest diagonal entry (M not positive definite).
bool choleskySolve(std::vector<std::vector<double>> M, std::vector<double>& b, double relativePivot = 1e-15);

/// Solves the QP (H: n × n, G: rows × n); converged when the residuals and the duality gap are
/// below `tolerance` relative to the data.
DenseQpResult solveDenseQp(const std::vector<std::vector<double>>& H, const std::vector<double>& f,
                           const std::vector<std::vector<double>>& G, const std::vector<double>& h,
                           double tolerance = 1e-11, int maxIterations = 200);

}  // namespace flowform
