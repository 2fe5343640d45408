#include "flowform/optimization/DesignObjective.hpp"

#include <cmath>

#include "flowform/optimization/DesignVectors.hpp"

namespace flowform {

DesignObjective::DesignObjective(const OptimizationSettings& settings, DesignRuns& runs, double scale)
    : m_settings(settings), m_runs(runs), m_scale(scale > 0.0 ? scale : 1.0), m_scaleKnown(scale > 0.0) {}

std::vector<double> DesignObjective::design(const std::vector<double>& z) const {
  std::vector<double> h(z.size());
  for (std::size_t i = 0; i < z.size(); ++i)
    h[i] = m_settings.lower[i] + z[i] * (m_settings.upper[i] - m_settings.lower[i]);
  return h;
}

std::vector<double> DesignObjective::scaled(const std::vector<double>& h) const {
  std::vector<double> z(h.size());
  for (std::size_t i = 0; i < h.size(); ++i)
    z[i] = (h[i] - m_settings.lower[i]) / (m_settings.upper[i] - m_settings.lower[i]);
  return z;
}

const DesignSolution& DesignObjective::solved(const ROL::Vector<double>& z) {
  const DesignSolution& s = m_runs.at(design(entries(z)));
  if (!m_scaleKnown && !m_settings.isMisfit()) {  // the start's value: the first design solved
    const double value = std::abs(m_runs.history().front().functionals.at(m_settings.objective));
    m_scale = value > 0.0 && std::isfinite(value) ? value : 1.0;
    m_scaleKnown = true;
  }
  return s;
}

double DesignObjective::derivative(const DesignSolution& s, const std::string& response,
                                   const std::string& parameter) const {
  const auto r = s.derivatives.find(response);
  if (r == s.derivatives.end() || r->second.find(parameter) == r->second.end())
    throw DesignNotSolved("the response '" + response + "' has no derivative by '" + parameter +
                          "' (a piecewise-constant response, e.g. Dead Zone or Contact Length, cannot be optimized)");
  return r->second.at(parameter);
}

std::vector<double> DesignObjective::residuals(const DesignSolution& s) const {
  std::vector<double> r(m_settings.measured.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    r[i] = (s.functionals.at(m_settings.measured[i]) - m_settings.values[i]) / m_settings.errors[i];
  return r;
}

std::vector<std::vector<double>> DesignObjective::residualJacobian(const DesignSolution& s) const {
  std::vector<std::vector<double>> A(m_settings.measured.size(), std::vector<double>(m_settings.design.size()));
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < m_settings.design.size(); ++j)
      A[i][j] = derivative(s, m_settings.measured[i], m_settings.design[j]) / m_settings.errors[i];
  return A;
}

double DesignObjective::objective(const DesignSolution& s) const {
  if (!m_settings.isMisfit())
    return (m_settings.maximize ? -1.0 : 1.0) * s.functionals.at(m_settings.objective) / m_scale;
  double J = 0.0;
  for (double r : residuals(s)) J += 0.5 * r * r;
  return J;
}

std::vector<double> DesignObjective::scaledGradient(const DesignSolution& s) const {
  const std::size_t n = m_settings.design.size();
  std::vector<double> g(n, 0.0);
  if (!m_settings.isMisfit()) {
    for (std::size_t j = 0; j < n; ++j)
      g[j] = (m_settings.maximize ? -1.0 : 1.0) * derivative(s, m_settings.objective, m_settings.design[j]) / m_scale;
  } else {
    const auto r = residuals(s);
    const auto A = residualJacobian(s);
    for (std::size_t i = 0; i < r.size(); ++i)
      for (std::size_t j = 0; j < n; ++j) g[j] += r[i] * A[i][j];
  }
  for (std::size_t j = 0; j < n; ++j) g[j] *= m_settings.upper[j] - m_settings.lower[j];
  return g;
}

double DesignObjective::value(const ROL::Vector<double>& z, double&) { return objective(solved(z)); }

void DesignObjective::gradient(ROL::Vector<double>& g, const ROL::Vector<double>& z, double&) {
  entries(g) = scaledGradient(solved(z));
}

void DesignObjective::hessVec(ROL::Vector<double>& hv, const ROL::Vector<double>& v, const ROL::Vector<double>& z,
                              double& tol) {
  if (!m_settings.isMisfit()) {  // not called: the secant stands in for the Hessian
    ROL::Objective<double>::hessVec(hv, v, z, tol);
    return;
  }
  const DesignSolution& s = solved(z);
  const auto A = residualJacobian(s);
  const std::vector<double>& x = entries(v);
  const std::size_t n = x.size();
  std::vector<double> range(n);
  for (std::size_t j = 0; j < n; ++j) range[j] = m_settings.upper[j] - m_settings.lower[j];
  std::vector<double> out(n, 0.0);
  for (const auto& row : A) {
    double Av = 0.0;
    for (std::size_t j = 0; j < n; ++j) Av += row[j] * range[j] * x[j];
    for (std::size_t j = 0; j < n; ++j) out[j] += row[j] * range[j] * Av;
  }
  entries(hv) = out;
}

}  // namespace flowform
