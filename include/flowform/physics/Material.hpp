// The rigid-viscoplastic law of docs/theory.md §1 (paper eq. 4-5), templated on the scalar type so
// that the same code gives values (double), the exact tangent (Sacado Fad of the element
// dofs) and parameter derivatives (Fad of the material parameters).
//
//   e   = sqrt(2/3 D:D)                 equivalent strain rate (D_θθ included when axisymmetric)
//   e_r = sqrt(e² + e0²)                regularized: e0 > 0 keeps μ finite in rigid zones
//   σ̄   = σ0 + (e_r/γ)^(1/n)            flow stress
//   μ   = σ̄ / (3 e_r)                   viscosity, so that s = 2 μ D has  sqrt(3/2 s:s) = σ̄ e/e_r
//
// With n = 1 and σ0 = 0, μ = 1/(3γ) for every e: the Newtonian (linear) case.
#pragma once

#include <cmath>

namespace flowform {

template <typename Scalar>
struct MaterialParameters {
  Scalar yieldStress;   ///< σ0 >= 0
  Scalar rateConstant;  ///< γ > 0
  Scalar rateExponent;  ///< n > 0 (1/n is the rate sensitivity)
  Scalar cutoff;        ///< e0 > 0, the strain-rate cutoff
};

/// True when the law is linear (μ independent of the strain rate): n = 1 and σ0 = 0.
inline bool isNewtonian(const MaterialParameters<double>& m) {
  return m.rateExponent == 1.0 && m.yieldStress == 0.0;
}

/// e_r = sqrt(2/3 D:D + e0²). `ddot` is D:D. The cutoff is added before the sqrt, so the
/// derivative at D = 0 is finite (Sacado's sqrt'(0) is infinite).
template <typename Scalar, typename PScalar>
Scalar regularizedStrainRate(const Scalar& ddot, const MaterialParameters<PScalar>& m) {
  using std::sqrt;
  return sqrt((2.0 / 3.0) * ddot + m.cutoff * m.cutoff);
}

/// σ̄(e_r) = σ0 + (e_r/γ)^(1/n), written as exp(log(e_r/γ)/n): e_r >= e0 > 0, so the log is
/// finite, and the form is differentiable in n as well.
template <typename Scalar, typename PScalar>
Scalar flowStress(const Scalar& eReg, const MaterialParameters<PScalar>& m) {
  using std::exp;
  using std::log;
  return m.yieldStress + exp(log(eReg / m.rateConstant) / m.rateExponent);
}

/// μ = σ̄ / (3 e_r).
template <typename Scalar, typename PScalar>
Scalar viscosity(const Scalar& eReg, const MaterialParameters<PScalar>& m) {
  return flowStress(eReg, m) / (3.0 * eReg);
}

}  // namespace flowform
