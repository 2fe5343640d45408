#include "flowform/optimization/DenseQp.hpp"

#include <algorithm>
#include <cmath>

namespace flowform {

namespace {

using Matrix = std::vector<std::vector<double>>;

double maxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

bool choleskySolve(Matrix M, std::vector<double>& b, double relativePivot) {
  const std::size_t n = b.size();
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, std::abs(M[i][i]));
  for (std::size_t j = 0; j < n; ++j) {
    double d = M[j][j];
    for (std::size_t k = 0; k < j; ++k) d -= M[j][k] * M[j][k];
    if (!(d > 1e-300 + relativePivot * largest)) return false;
    M[j][j] = std::sqrt(d);
    for (std::size_t i = j + 1; i < n; ++i) {
      double v = M[i][j];
      for (std::size_t k = 0; k < j; ++k) v -= M[i][k] * M[j][k];
      M[i][j] = v / M[j][j];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < i; ++k) b[i] -= M[i][k] * b[k];
    b[i] /= M[i][i];
  }
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t k = i + 1; k < n; ++k) b[i] -= M[k][i] * b[k];
    b[i] /= M[i][i];
  }
  return true;
}

namespace {

/// The largest α <= 1 with v + α dv >= 0 (kept at 99 % of the way to the boundary by the caller).
double stepToBoundary(const std::vector<double>& v, const std::vector<double>& dv) {
  double alpha = 1.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (dv[i] < 0.0) alpha = std::min(alpha, -v[i] / dv[i]);
  return alpha;
}

}  // namespace

DenseQpResult solveDenseQp(const Matrix& H, const std::vector<double>& f, const Matrix& G, const std::vector<double>& h,
                           double tolerance, int maxIterations) {
  const std::size_t n = f.size(), m = h.size();
  DenseQpResult r;
  std::vector<double> x(n, 0.0), s(m), z(m, 1.0);
  for (std::size_t i = 0; i < m; ++i) s[i] = std::max(h[i], 1.0);  // G x = 0 at x = 0
  const double scale = 1.0 + std::max(maxAbs(f), maxAbs(h));

  // The Newton direction for the complementarity target rc (S z + Z s = rc): returns dx, ds, dz.
  auto direction = [&](const std::vector<double>& rd, const std::vector<double>& rp, const std::vector<double>& rc,
                       std::vector<double>& dx, std::vector<double>& ds, std::vector<double>& dz) {
    Matrix M = H;
    std::vector<double> rhs(n);
    for (std::size_t j = 0; j < n; ++j) rhs[j] = -rd[j];
    for (std::size_t i = 0; i < m; ++i) {
      const double w = z[i] / s[i], t = w * rp[i] + rc[i] / s[i];  // Δz = W (G Δx + rp) + S⁻¹ rc
      for (std::size_t j = 0; j < n; ++j) {
        if (G[i][j] == 0.0) continue;
        rhs[j] -= G[i][j] * t;
        for (std::size_t k = 0; k < n; ++k) M[j][k] += G[i][j] * w * G[i][k];
      }
    }
    // Near the solution of a degenerate problem S⁻¹Z spans many decades: a tiny shift keeps the
    // factorization (it only damps the step).
    double largest = 0.0;
    for (std::size_t j = 0; j < n; ++j) largest = std::max(largest, M[j][j]);
    for (double shift = 0.0; !choleskySolve(M, rhs); shift = shift == 0.0 ? 1e-14 * largest : 100.0 * shift) {
      if (shift > 1e-6 * largest) return false;
      for (std::size_t j = 0; j < n; ++j) M[j][j] += shift;
    }
    dx = rhs;
    for (std::size_t i = 0; i < m; ++i) {
      double Gdx = 0.0;
      for (std::size_t j = 0; j < n; ++j) Gdx += G[i][j] * dx[j];
      dz[i] = z[i] / s[i] * (Gdx + rp[i]) + rc[i] / s[i];
      ds[i] = -rp[i] - Gdx;
    }
    return true;
  };

  std::vector<double> rd(n), rp(m), rc(m), dx(n), ds(m), dz(m), dxa(n), dsa(m), dza(m);
  for (r.iterations = 0; r.iterations < maxIterations; ++r.iterations) {
    for (std::size_t j = 0; j < n; ++j) {
      rd[j] = f[j];
      for (std::size_t k = 0; k < n; ++k) rd[j] += H[j][k] * x[k];
    }
    for (std::size_t i = 0; i < m; ++i) {
      rp[i] = s[i] - h[i];
      for (std::size_t j = 0; j < n; ++j) {
        rp[i] += G[i][j] * x[j];
        rd[j] += G[i][j] * z[i];
      }
    }
    double gap = 0.0;
    for (std::size_t i = 0; i < m; ++i) gap += s[i] * z[i];
    const double mu = m ? gap / static_cast<double>(m) : 0.0;
    if (maxAbs(rd) <= tolerance * scale && maxAbs(rp) <= tolerance * scale && mu <= tolerance * scale) {
      r.converged = true;
      break;
    }
    // Predictor (affine scaling), then Mehrotra's corrector with centring σ = (μ_aff/μ)³.
    for (std::size_t i = 0; i < m; ++i) rc[i] = -s[i] * z[i];
    if (!direction(rd, rp, rc, dxa, dsa, dza)) break;
    const double alphaAffine = std::min(stepToBoundary(s, dsa), stepToBoundary(z, dza));
    double gapAffine = 0.0;
    for (std::size_t i = 0; i < m; ++i) gapAffine += (s[i] + alphaAffine * dsa[i]) * (z[i] + alphaAffine * dza[i]);
    const double sigma = std::pow(gapAffine / std::max(gap, 1e-300), 3.0);
    for (std::size_t i = 0; i < m; ++i) rc[i] = -s[i] * z[i] - dsa[i] * dza[i] + sigma * mu;
    if (!direction(rd, rp, rc, dx, ds, dz)) break;
    const double alpha = std::min(1.0, 0.99 * std::min(stepToBoundary(s, ds), stepToBoundary(z, dz)));
    for (std::size_t j = 0; j < n; ++j) x[j] += alpha * dx[j];
    for (std::size_t i = 0; i < m; ++i) {
      s[i] += alpha * ds[i];
      z[i] += alpha * dz[i];
    }
  }
  r.x = x;
  r.z = z;
  return r;
}

}  // namespace flowform
