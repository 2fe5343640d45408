// The rigid-viscoplastic material of docs/theory.md §1 (paper eq. 4-5), templated on the scalar
// type so that the same code gives values (double), the exact tangent (Sacado Fad of the element
// dofs) and parameter derivatives (Fad of the material parameters). What every law shares:
//
//   e   = sqrt(2/3 D:D)                 equivalent strain rate (D_θθ included when axisymmetric)
//   e_r = sqrt(e² + e0²)                regularized: e0 > 0 keeps μ finite in rigid zones
//   σ̄   = σ̄(e_r; h)                     flow stress: the case's law (materials/MaterialLaws.hpp),
//                                       by default the power law σ0 + (e_r/γ)^(1/n)
//   μ   = σ̄ / (3 e_r)                   viscosity, so that s = 2 μ D has  sqrt(3/2 s:s) = σ̄ e/e_r
#pragma once

#include <cmath>

#include "flowform/physics/materials/MaterialLaws.hpp"

namespace flowform {

/// The power law's parameters (σ0, γ, n, e0) as a MaterialParameters, for tests and tools.
template <typename Scalar>
MaterialParameters<Scalar> powerLaw(const Scalar& yieldStress, const Scalar& rateConstant, const Scalar& rateExponent,
                                    const Scalar& cutoff) {
  MaterialParameters<Scalar> m;
  m.law = kMaterialLawIndex<PowerLaw>;
  m.values[PowerLaw::kYieldStress] = yieldStress;
  m.values[PowerLaw::kRateConstant] = rateConstant;
  m.values[PowerLaw::kRateExponent] = rateExponent;
  m.cutoff = cutoff;
  return m;
}

/// e_r = sqrt(2/3 D:D + e0²). `ddot` is D:D. The cutoff is added before the sqrt, so the
/// derivative at D = 0 is finite (Sacado's sqrt'(0) is infinite).
template <typename Scalar, typename PScalar>
Scalar regularizedStrainRate(const Scalar& ddot, const MaterialParameters<PScalar>& m) {
  using std::sqrt;
  return sqrt((2.0 / 3.0) * ddot + m.cutoff * m.cutoff);
}

/// σ̄(e_r) by the case's law.
template <typename Scalar, typename PScalar>
Scalar flowStress(const Scalar& eReg, const MaterialParameters<PScalar>& m) {
  return lawFlowStress(eReg, m);
}

/// The material in a cell whose fields the law reads: the law's "Temperature" parameter replaced by
/// *T (a Temperature field's value in the cell) and its "Strain" parameter by *strain (the strain
/// field's regularized value, physics/StrainField.hpp), each when given and when the law has it;
/// the others carried over (with their seeded derivatives). Scalar may carry the derivatives of T
/// and ε with respect to the dofs (the Jacobian's coupling blocks ∂R_u/∂T, ∂R_u/∂ε).
template <typename Scalar, typename PScalar>
MaterialParameters<Scalar> atFieldValues(const MaterialParameters<PScalar>& m, const Scalar* T, const Scalar* strain) {
  MaterialParameters<Scalar> out;
  out.law = m.law;
  for (int i = 0; i < kMaxMaterialParameters; ++i) out.values[i] = Scalar(m.values[i]);
  out.cutoff = Scalar(m.cutoff);
  if (const int t = temperatureParameter(m.law); T && t >= 0) out.values[t] = *T;
  if (const int e = strainParameter(m.law); strain && e >= 0) out.values[e] = *strain;
  return out;
}

/// The material at temperature T (atFieldValues without a strain).
template <typename Scalar, typename PScalar>
MaterialParameters<Scalar> atTemperature(const MaterialParameters<PScalar>& m, const Scalar& T) {
  return atFieldValues(m, &T, static_cast<const Scalar*>(nullptr));
}

/// μ = σ̄ / (3 e_r).
template <typename Scalar, typename PScalar>
Scalar viscosity(const Scalar& eReg, const MaterialParameters<PScalar>& m) {
  return flowStress(eReg, m) / (3.0 * eReg);
}

}  // namespace flowform
