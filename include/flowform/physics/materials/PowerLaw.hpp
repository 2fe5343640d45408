// The rigid-viscoplastic power law of docs/theory.md §1 (paper eq. 4-5), the default law:
//
//   σ̄ = σ0 + (e_r/γ)^(1/n)            σ0 >= 0 yield stress, γ > 0 rate constant, n > 0
//
// With n = 1 and σ0 = 0, μ = σ̄/(3 e_r) = 1/(3γ) for every e: the Newtonian (linear) case,
// which is every law's predictor (NonlinearSolver), each law giving its γ.
#pragma once

#include <cmath>

#include "flowform/physics/materials/MaterialLaw.hpp"

namespace flowform {

struct PowerLaw {
  static constexpr const char* kName = "Power Law";
  static constexpr const char* kDescription = "σ̄ = σ0 + (e_r/γ)^(1/n) (docs/theory.md §1)";
  enum Parameter { kYieldStress, kRateConstant, kRateExponent, kNumParameters };
  using Range = MaterialParameterInfo::Range;
  static constexpr MaterialParameterInfo kParameters[kNumParameters] = {
      {"Yield Stress", "sigma0", "σ0 >= 0 [stress]", 1.0, Range::NonNegative, true, true},
      {"Rate Constant", "gamma", "γ > 0 [1/time]", 1.0, Range::Positive, true, true},
      {"Rate Exponent", "n", "n > 0: σ̄ = σ0 + (e/γ)^(1/n)", 1.0, Range::Positive, true, true}};
  /// The parameter the continuation in the rate exponent moves (NonlinearSolver).
  static constexpr int kExponent = kRateExponent;

  /// σ̄(e_r) = σ0 + (e_r/γ)^(1/n), written as exp(log(e_r/γ)/n): e_r >= e0 > 0, so the log is
  /// finite, and the form is differentiable in n as well.
  template <typename Scalar, typename PScalar>
  static Scalar flowStress(const Scalar& eReg, const PScalar* p) {
    using std::exp;
    using std::log;
    return p[kYieldStress] + exp(log(eReg / p[kRateConstant]) / p[kRateExponent]);
  }

  /// Linear (μ independent of the strain rate): n = 1 and σ0 = 0.
  static bool isNewtonian(const double* p) { return p[kRateExponent] == 1.0 && p[kYieldStress] == 0.0; }

  /// γ of the Newtonian predictor (this law at σ0 = 0, n = 1: μ = 1/(3γ) everywhere).
  static double newtonianRateConstant(const double* p) { return p[kRateConstant]; }
};

}  // namespace flowform
