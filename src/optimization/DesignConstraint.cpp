#include "flowform/optimization/DesignConstraint.hpp"

#include <algorithm>
#include <cmath>

#include "flowform/optimization/DesignVectors.hpp"

namespace flowform {

DesignConstraint::DesignConstraint(const OptimizationSettings& settings, DesignRuns& runs,
                                   const DesignObjective& objective)
    : m_settings(settings), m_runs(runs), m_objective(objective) {
  for (std::size_t i = 0; i < settings.constrained.size(); ++i) {
    double s = 0.0;
    for (double b : {settings.constraintLower[i], settings.constraintUpper[i]})
      if (std::isfinite(b)) s = std::max(s, std::abs(b));
    m_scale.push_back(s > 0.0 ? s : 1.0);
  }
}

std::vector<double> DesignConstraint::values(const std::vector<double>& z) {
  const DesignSolution& s = m_runs.at(m_objective.design(z));
  std::vector<double> c(m_scale.size());
  for (std::size_t i = 0; i < m_scale.size(); ++i) c[i] = s.functionals.at(m_settings.constrained[i]) / m_scale[i];
  return c;
}

void DesignConstraint::value(ROL::Vector<double>& c, const ROL::Vector<double>& z, double&) {
  entries(c) = values(entries(z));
}

std::vector<std::vector<double>> DesignConstraint::jacobian(const std::vector<double>& z) {
  const DesignSolution& s = m_runs.at(m_objective.design(z));
  const std::size_t n = m_settings.design.size();
  std::vector<std::vector<double>> A(m_scale.size(), std::vector<double>(n));
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < n; ++j)
      A[i][j] = m_objective.derivative(s, m_settings.constrained[i], m_settings.design[j]) *
                (m_settings.upper[j] - m_settings.lower[j]) / m_scale[i];
  return A;
}

void DesignConstraint::applyJacobian(ROL::Vector<double>& jv, const ROL::Vector<double>& v,
                                     const ROL::Vector<double>& z, double&) {
  const auto A = jacobian(entries(z));
  const std::vector<double>& x = entries(v);
  std::vector<double>& out = entries(jv);
  for (std::size_t i = 0; i < A.size(); ++i) {
    out[i] = 0.0;
    for (std::size_t j = 0; j < x.size(); ++j) out[i] += A[i][j] * x[j];
  }
}

void DesignConstraint::applyAdjointJacobian(ROL::Vector<double>& ajv, const ROL::Vector<double>& v,
                                            const ROL::Vector<double>& z, double&) {
  const auto A = jacobian(entries(z));
  const std::vector<double>& y = entries(v);
  std::vector<double>& out = entries(ajv);
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t j = 0; j < out.size(); ++j) out[j] += A[i][j] * y[i];
}

void DesignConstraint::applyAdjointHessian(ROL::Vector<double>& ahuv, const ROL::Vector<double>&,
                                           const ROL::Vector<double>&, const ROL::Vector<double>&, double&) {
  ahuv.zero();
}

namespace {

/// bound_i / s_i, `none` where the side has no bound.
std::vector<double> scaledSide(const std::vector<double>& bounds, const std::vector<double>& scale, double none) {
  std::vector<double> out(scale.size());
  for (std::size_t i = 0; i < scale.size(); ++i) out[i] = std::isfinite(bounds[i]) ? bounds[i] / scale[i] : none;
  return out;
}

}  // namespace

std::vector<double> DesignConstraint::scaledLower() const {
  return scaledSide(m_settings.constraintLower, m_scale, ROL::ROL_NINF<double>());
}

std::vector<double> DesignConstraint::scaledUpper() const {
  return scaledSide(m_settings.constraintUpper, m_scale, ROL::ROL_INF<double>());
}

ROL::Ptr<ROL::Bounds<double>> DesignConstraint::bounds() const {
  return ROL::makePtr<ROL::Bounds<double>>(stdVector(scaledLower()), stdVector(scaledUpper()));
}

ROL::Ptr<ROL::Vector<double>> DesignConstraint::zero() const {
  return stdVector(std::vector<double>(m_scale.size(), 0.0));
}

double DesignConstraint::violation(const std::map<std::string, double>& functionals) const {
  double worst = 0.0;
  for (std::size_t i = 0; i < m_scale.size(); ++i) {
    const double phi = functionals.at(m_settings.constrained[i]);
    worst = std::max({worst, (m_settings.constraintLower[i] - phi) / m_scale[i],
                      (phi - m_settings.constraintUpper[i]) / m_scale[i]});
  }
  return worst;
}

}  // namespace flowform
