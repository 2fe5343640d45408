#include "flowform/solvers/AndersonAcceleration.hpp"

#include <cmath>

namespace flowform {

namespace {
double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}
}  // namespace

std::vector<double> AndersonAcceleration::step(const std::vector<double>& x, const std::vector<double>& f,
                                               double mixing) {
  if (!m_x.empty() && (m_x.back().size() != x.size() || f.size() != x.size())) reset();
  m_x.push_back(x);
  m_f.push_back(f);
  while (static_cast<int>(m_x.size()) > m_depth + 1) {
    m_x.pop_front();
    m_f.pop_front();
  }
  const size_t n = x.size(), pairs = m_x.size() - 1;
  // The columns ΔF_j, ΔX_j, newest first, orthogonalized against the newer ones kept (Q R = ΔF).
  std::vector<std::vector<double>> q, dx, df;  // kept columns: Q's, and the ΔX, ΔF they came from
  std::vector<std::vector<double>> r;           // R's columns (upper triangular, r[j][i] for i ≤ j)
  for (size_t p = 0; p < pairs; ++p) {
    const size_t j = pairs - 1 - p;  // the pair (j, j + 1), newest first
    std::vector<double> dF(n), dX(n);
    for (size_t i = 0; i < n; ++i) {
      dF[i] = m_f[j + 1][i] - m_f[j][i];
      dX[i] = m_x[j + 1][i] - m_x[j][i];
    }
    const double norm0 = std::sqrt(dot(dF, dF));
    if (!(norm0 > 0.0)) continue;
    std::vector<double> v = dF, rj(q.size() + 1, 0.0);
    for (size_t c = 0; c < q.size(); ++c) {
      rj[c] = dot(q[c], v);
      for (size_t i = 0; i < n; ++i) v[i] -= rj[c] * q[c][i];
    }
    const double norm = std::sqrt(dot(v, v));
    if (!(norm > kDropTolerance * norm0)) continue;  // dependent on the newer columns: dropped
    rj.back() = norm;
    for (double& vi : v) vi /= norm;
    q.push_back(std::move(v));
    r.push_back(std::move(rj));
    dx.push_back(std::move(dX));
    df.push_back(std::move(dF));
  }
  m_used = static_cast<int>(q.size());
  // γ from R γ = Qᵀ f (back substitution), then Δx = β f − Σ_c γ_c (ΔX_c + β ΔF_c).
  const size_t m = q.size();
  std::vector<double> gamma(m, 0.0);
  for (size_t c = 0; c < m; ++c) gamma[c] = dot(q[c], f);
  for (size_t c = m; c-- > 0;) {
    for (size_t d = c + 1; d < m; ++d) gamma[c] -= r[d][c] * gamma[d];
    gamma[c] /= r[c][c];
  }
  std::vector<double> dx_out(n);
  for (size_t i = 0; i < n; ++i) dx_out[i] = mixing * f[i];
  for (size_t c = 0; c < m; ++c)
    for (size_t i = 0; i < n; ++i) dx_out[i] -= gamma[c] * (dx[c][i] + mixing * df[c][i]);
  return dx_out;
}

}  // namespace flowform
