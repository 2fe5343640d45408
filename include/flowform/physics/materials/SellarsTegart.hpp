// The Sellars–Tegart (Zener–Hollomon) hot-working law at a prescribed uniform temperature T:
//
//   Z = e_r exp(Q/(R T))              Zener–Hollomon parameter [1/s]
//   σ̄ = (1/α) asinh((Z/A)^(1/n))      flow stress
//
// Q activation energy [J/mol], T temperature [K], R = 8.314 J/(mol K), α stress multiplier
// [1/stress], A rate factor [1/s], n rate exponent; e_r the shared regularized rate.
// Small Z/A: σ̄ ≈ (1/α)(Z/A)^(1/n) (a power law); large: σ̄ ≈ (1/α) ln(2 (Z/A)^(1/n)).
//
// Numerics: exp(Q/(R T)) is e^30–e^40 for aluminium near 700 K, and A ~ 1e8–1e13; their
// ratio is formed in logs, (Z/A)^(1/n) = exp((log e_r + Q/(R T) − log A)/n), so nothing
// overflows; asinh of the result is exact for any finite argument.
#pragma once

#include <cmath>

#include "flowform/physics/materials/MaterialLaw.hpp"

namespace flowform {

struct SellarsTegart {
  static constexpr const char* kName = "Sellars-Tegart";
  static constexpr const char* kDescription =
      "σ̄ = (1/α) asinh((Z/A)^(1/n)), Z = e_r exp(Q/(R T)) at a uniform temperature T (docs/theory.md §1)";
  static constexpr double kGasConstant = 8.314;  ///< R [J/(mol K)]
  /// Defaults: AA6xxx-like constants in MPa (α per MPa), of the size published for 6xxx
  /// alloys; a case states its own.
  enum Parameter { kActivationEnergy, kTemperature, kStressMultiplier, kRateFactor, kRateExponent, kNumParameters };
  using Range = MaterialParameterInfo::Range;
  static constexpr MaterialParameterInfo kParameters[kNumParameters] = {
      {"Activation Energy", "Q", "Q >= 0 [J/mol]", 145000.0, Range::NonNegative, true, true},
      {"Temperature", "T", "T > 0, uniform and prescribed [K]", 700.0, Range::Positive, true, true},
      {"Stress Multiplier", "alpha", "α > 0 [1/stress]", 0.045, Range::Positive, true, true},
      {"Rate Factor", "A", "A > 0 [1/time]", 2.4e8, Range::Positive, true, true},
      {"Rate Exponent", "n", "n > 0", 3.55, Range::Positive, true, true}};
  static constexpr int kExponent = kRateExponent;

  /// log(Z/A)/n = (log e_r + Q/(R T) − log A)/n, then σ̄ = asinh(exp(·))/α.
  template <typename Scalar, typename PScalar>
  static Scalar flowStress(const Scalar& eReg, const PScalar* p) {
    using std::asinh;
    using std::exp;
    using std::log;
    const Scalar x = exp((log(eReg) + p[kActivationEnergy] / (kGasConstant * p[kTemperature]) - log(p[kRateFactor])) /
                         p[kRateExponent]);
    return asinh(x) / p[kStressMultiplier];
  }

  static bool isNewtonian(const double*) { return false; }

  /// γ of the Newtonian predictor: the small-Z limit at n = 1, σ̄ ≈ Z/(α A) = e_r/γ with
  /// γ = α A exp(−Q/(R T)), formed in logs.
  static double newtonianRateConstant(const double* p) {
    return std::exp(std::log(p[kStressMultiplier] * p[kRateFactor]) -
                    p[kActivationEnergy] / (kGasConstant * p[kTemperature]));
  }
};

}  // namespace flowform
