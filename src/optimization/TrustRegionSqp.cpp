#include "flowform/optimization/TrustRegionSqp.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <ROL_Types.hpp>

#include "flowform/optimization/DenseQp.hpp"
#include "flowform/optimization/DesignRuns.hpp"
#include "flowform/optimization/DesignVectors.hpp"

namespace flowform {

namespace {

using Matrix = std::vector<std::vector<double>>;

/// A step is taken when the merit falls by this fraction of the model's prediction; the radius
/// shrinks below kPoor and grows above kGood (a step that reached the radius).
constexpr double kAccept = 0.1, kPoor = 0.25, kGood = 0.75;
/// ρ at most (scaled units: the objective ≈ 1 at the start, the constraints ≈ 1 at their bounds).
constexpr double kMaxPenalty = 1e8;

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}
std::vector<double> times(const Matrix& M, const std::vector<double>& v) {
  std::vector<double> out(M.size(), 0.0);
  for (std::size_t i = 0; i < M.size(); ++i) out[i] = dot(M[i], v);
  return out;
}
double maxNorm(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s = std::max(s, std::abs(x));
  return s;
}

/// Σ_i max(0, l_i − c_i, c_i − u_i).
double violation(const std::vector<double>& c, const std::vector<double>& lo, const std::vector<double>& hi) {
  double v = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) v += std::max({0.0, lo[i] - c[i], c[i] - hi[i]});
  return v;
}

/// One solved design: J, ∇J, c, A (scaled).
struct Linearization {
  double J = 0.0;
  std::vector<double> g, c;
  Matrix A;
};

Linearization linearize(DesignObjective& objective, DesignConstraint& constraint, const std::vector<double>& z) {
  Linearization L;
  double tol = 0.0;
  auto x = stdVector(z), g = stdVector(z);
  L.J = objective.value(*x, tol);
  objective.gradient(*g, *x, tol);
  L.g = entries(*g);
  L.c = constraint.values(z);
  L.A = constraint.jacobian(z);
  return L;
}

struct ModelStep {
  std::vector<double> d;
  double decrease = 0.0;         ///< q(0) − q(d), the merit's predicted decrease
  double linearViolation = 0.0;  ///< Σ viol(c + A d)
};

/// The model's merit q(d) = ∇J·d + ½ dᵀBd + ρ Σ viol(c + A d).
double modelMerit(const Linearization& L, const Matrix& B, double rho, const std::vector<double>& d,
                  const std::vector<double>& lo, const std::vector<double>& hi) {
  std::vector<double> cd = L.c;
  for (std::size_t i = 0; i < cd.size(); ++i) cd[i] += dot(L.A[i], d);
  return dot(L.g, d) + 0.5 * dot(d, times(B, d)) + rho * violation(cd, lo, hi);
}

/// The step minimizing q over the box ∩ trust region: the elastic form, x = [d (n), p (m), q (m)],
///   min ∇J·d + ½ dᵀBd + ρ Σ (p_i + q_i),  l <= c + A d + p − q <= u,  box on d,  0 <= p, q <= P,
/// (P above any violation a step in the box can leave) as a dense QP (no solve of the case).
ModelStep solveModel(const Linearization& L, const Matrix& B, double rho, const std::vector<double>& z, double radius,
                     const std::vector<double>& lo, const std::vector<double>& hi) {
  const std::size_t n = z.size(), m = L.c.size(), N = n + 2 * m;
  Matrix H(N, std::vector<double>(N, 0.0)), G;
  std::vector<double> f(N, rho), h, xlo(n), xhi(n);
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t k = 0; k < n; ++k) H[j][k] = B[j][k];
    f[j] = L.g[j];
  }
  auto row = [&](std::vector<double> a, double b) {
    G.push_back(std::move(a));
    h.push_back(b);
  };
  auto unit = [&](std::size_t k, double sign) {
    std::vector<double> a(N, 0.0);
    a[k] = sign;
    return a;
  };
  for (std::size_t j = 0; j < n; ++j) {
    xlo[j] = std::max(-z[j], -radius);
    xhi[j] = std::min(1.0 - z[j], radius);
    row(unit(j, 1.0), xhi[j]);
    row(unit(j, -1.0), -xlo[j]);
  }
  for (std::size_t i = 0; i < m; ++i) {
    double P = 1.0 + std::max({0.0, lo[i] - L.c[i], L.c[i] - hi[i]});
    for (std::size_t j = 0; j < n; ++j) P += std::abs(L.A[i][j]) * std::max(-xlo[j], xhi[j]);
    for (std::size_t k : {n + i, n + m + i}) {
      row(unit(k, 1.0), P);
      row(unit(k, -1.0), 0.0);
    }
    std::vector<double> a(N, 0.0);
    for (std::size_t j = 0; j < n; ++j) a[j] = L.A[i][j];
    a[n + i] = 1.0;
    a[n + m + i] = -1.0;
    if (hi[i] < ROL::ROL_INF<double>()) row(a, hi[i] - L.c[i]);  // a side without a bound has no row
    if (lo[i] > ROL::ROL_NINF<double>()) {
      for (double& v : a) v = -v;
      row(a, L.c[i] - lo[i]);
    }
  }
  const DenseQpResult qp = solveDenseQp(H, f, G, h);

  ModelStep step;
  step.d.assign(qp.x.begin(), qp.x.begin() + n);
  for (std::size_t j = 0; j < n; ++j) step.d[j] = std::clamp(step.d[j], xlo[j], xhi[j]);
  const std::vector<double> none(n, 0.0);
  step.decrease = modelMerit(L, B, rho, none, lo, hi) - modelMerit(L, B, rho, step.d, lo, hi);
  if (!qp.converged || !(step.decrease > 0.0)) {  // no better than staying: stay
    step.d = none;
    step.decrease = 0.0;
  }
  std::vector<double> cd = L.c;
  for (std::size_t i = 0; i < m; ++i) cd[i] += dot(L.A[i], step.d);
  step.linearViolation = violation(cd, lo, hi);
  return step;
}

/// Damped BFGS (Powell) of the objective's Hessian from B = 0: the first pair with sᵀy > 0 sets
/// B = (yᵀy / sᵀy) I.
void updateBfgs(Matrix& B, const std::vector<double>& s, const std::vector<double>& y) {
  const std::size_t n = s.size();
  const double sy = dot(s, y);
  const std::vector<double> Bs = times(B, s);
  const double sBs = dot(s, Bs);
  if (!(sBs > 0.0)) {
    if (sy > 1e-12 * dot(s, s)) {
      const double gamma = dot(y, y) / sy;
      for (std::size_t i = 0; i < n; ++i) B[i][i] = gamma;
    }
    return;
  }
  const double theta = sy >= 0.2 * sBs ? 1.0 : 0.8 * sBs / (sBs - sy);
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = theta * y[i] + (1.0 - theta) * Bs[i];
  const double sr = dot(s, r);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) B[i][j] += -Bs[i] * Bs[j] / sBs + r[i] * r[j] / sr;
}

/// The misfit's Gauss–Newton Hessian in the scaled design (the objective's hessVec on unit vectors).
Matrix gaussNewton(DesignObjective& objective, const std::vector<double>& z) {
  const std::size_t n = z.size();
  Matrix B(n, std::vector<double>(n, 0.0));
  double tol = 0.0;
  auto x = stdVector(z), hv = stdVector(z);
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> e(n, 0.0);
    e[j] = 1.0;
    objective.hessVec(*hv, *stdVector(e), *x, tol);
    for (std::size_t i = 0; i < n; ++i) B[i][j] = entries(*hv)[i];
  }
  return B;
}

/// λ of ∇J + Σ_active λ_i ∇c_i = 0 on the design components off their bounds, by least squares
/// (normal equations; the active set is small).
std::vector<double> multipliers(const Linearization& L, const std::vector<double>& z, const std::vector<double>& lo,
                                const std::vector<double>& hi, double tolerance) {
  const std::size_t n = z.size(), m = L.c.size();
  std::vector<std::size_t> active, free;
  for (std::size_t i = 0; i < m; ++i)
    if (std::abs(L.c[i] - lo[i]) <= tolerance || std::abs(L.c[i] - hi[i]) <= tolerance) active.push_back(i);
  for (std::size_t j = 0; j < n; ++j)
    if (z[j] > 1e-9 && z[j] < 1.0 - 1e-9) free.push_back(j);
  std::vector<double> lambda(m, 0.0);
  if (active.empty() || free.empty()) return lambda;
  const std::size_t k = active.size();
  Matrix N(k, std::vector<double>(k, 0.0));  // AᵀA x = −Aᵀg on the free components
  std::vector<double> x(k, 0.0);
  for (std::size_t a = 0; a < k; ++a) {
    for (std::size_t b = 0; b < k; ++b)
      for (std::size_t j : free) N[a][b] += L.A[active[a]][j] * L.A[active[b]][j];
    for (std::size_t j : free) x[a] -= L.A[active[a]][j] * L.g[j];
  }
  if (!choleskySolve(N, x)) return lambda;  // dependent active constraints: no unique multipliers
  for (std::size_t a = 0; a < k; ++a) lambda[active[a]] = x[a];
  return lambda;
}

}  // namespace

SqpResult runTrustRegionSqp(DesignObjective& objective, DesignConstraint& constraint, std::vector<double> z,
                            const OptimizationSettings& settings, std::ostream& out) {
  const std::size_t n = z.size();
  const std::vector<double> lo = constraint.scaledLower(), hi = constraint.scaledUpper();
  const double ctol = settings.constraintTolerance, gtol = settings.gradientTolerance;
  SqpResult result;
  Linearization L = linearize(objective, constraint, z);  // DesignNotSolved: nothing to start from
  Matrix B(n, std::vector<double>(n, 0.0));
  if (settings.isMisfit()) B = gaussNewton(objective, z);
  double radius = std::min(settings.initialRadius, 1.0), rho = 1.0;
  const Matrix zero(n, std::vector<double>(n, 0.0));
  out << "optimization: SQP  iter  objective        violation   criticality  radius     penalty  ratio\n";
  auto report = [&](int k, double lastRatio) {  // formatted apart: the log keeps its own precision
    std::ostringstream line;
    line << "optimization: SQP  " << std::setw(4) << k << "  " << std::setw(15) << std::setprecision(9) << L.J << "  "
         << std::setw(10) << std::setprecision(3) << violation(L.c, lo, hi) << "  " << std::setw(11)
         << result.criticality << "  " << std::setw(9) << radius << "  " << std::setw(7) << rho << "  " << lastRatio
         << "\n";
    out << line.str();
  };
  double ratio = 0.0;  // of the step that led to the iterate reported
  for (int k = 0;; ++k) {
    // Steering: raise ρ while that lowers the linearized violation a step could reach.
    ModelStep unit = solveModel(L, zero, rho, z, 1.0, lo, hi);
    while (rho < kMaxPenalty && unit.linearViolation > ctol) {
      const ModelStep stronger = solveModel(L, zero, 10.0 * rho, z, 1.0, lo, hi);
      if (!(stronger.linearViolation < 0.9 * unit.linearViolation)) break;
      rho *= 10.0;
      unit = stronger;
    }
    result.criticality = unit.decrease;
    result.violation = violation(L.c, lo, hi);
    report(k, ratio);
    if (result.criticality <= gtol && result.violation <= ctol) {
      result.converged = true;
      result.status = "Converged (stationary, constraints met)";
      break;
    }
    if (k >= settings.iterationLimit) {
      result.status = "Iteration Limit Exceeded";
      break;
    }
    // Steps until one is taken (each trial one solve), or the region is below the step tolerance.
    for (;;) {
      if (radius < settings.stepTolerance) break;
      const ModelStep step = solveModel(L, B, rho, z, radius, lo, hi);
      if (!(step.decrease > 0.0)) {
        radius = 0.0;
        break;
      }
      std::vector<double> trial(n);
      for (std::size_t j = 0; j < n; ++j) trial[j] = std::clamp(z[j] + step.d[j], 0.0, 1.0);
      ratio = -1.0;
      Linearization T;
      try {
        T = linearize(objective, constraint, trial);
        const double before = L.J + rho * violation(L.c, lo, hi), after = T.J + rho * violation(T.c, lo, hi);
        ratio = (before - after) / step.decrease;
      } catch (const DesignNotSolved& e) {
        out << "optimization: SQP: the trial design did not solve (" << e.what() << "); the trust region shrinks\n";
      }
      const double length = maxNorm(step.d);
      if (ratio < kPoor) radius = 0.25 * length;
      else if (ratio > kGood && length >= 0.99 * radius) radius = std::min(2.0 * radius, 1.0);
      if (ratio >= kAccept) {
        if (settings.isMisfit()) {
          B = gaussNewton(objective, trial);
        } else {
          std::vector<double> s(n), y(n);
          for (std::size_t j = 0; j < n; ++j) {
            s[j] = trial[j] - z[j];
            y[j] = T.g[j] - L.g[j];
          }
          updateBfgs(B, s, y);
        }
        z = trial;
        L = T;
        ++result.iterations;
        break;
      }
      out << "optimization: SQP: step rejected (merit ratio " << ratio << "), radius " << radius << "\n";
    }
    if (radius < settings.stepTolerance) {
      result.status = "Step Tolerance Met (the trust region shrank below it)";
      break;
    }
  }
  result.z = z;
  result.penalty = rho;
  result.multipliers = multipliers(L, z, lo, hi, kActiveFactor * ctol);
  return result;
}

}  // namespace flowform
