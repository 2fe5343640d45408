// The Hensel–Spittel hot-working law (A. Hensel, T. Spittel, "Kraft- und Arbeitsbedarf bildsamer
// Formgebungsverfahren", 1978), in the form forming codes tabulate it:
//
//   σ̄ = A e^(m1 θ) θ^m9 ε^m2 e^(m4/ε) (1 + ε)^(m5 θ) e^(m7 ε) e_r^(m3 + m8 θ)
//
// θ = T − 273.15 the temperature in °C (the published constants are fitted in °C; T, the
// Temperature field or the law's uniform Temperature, is in kelvin), ε the equivalent strain,
// e_r the shared regularized strain rate. A in the case's stress unit, m1, m5, m8 per °C.
//
// The strain: flowform's Eulerian steady state has no strain field (a material point's history
// is not carried); the law is read at the uniform `Strain` the case gives — the strain of the
// deformation zone it models (in hot extrusion the strain terms saturate: at ε ≥ 1 they move σ̄ by
// a few per cent). m9 = 0 drops θ^m9 (no θ > 0 needed then).
//
// Numerics: formed in logs, log σ̄ = log A + m1 θ + m9 log θ + m2 log ε + m4/ε + m5 θ log(1+ε) +
// m7 ε + (m3 + m8 θ) log e_r, so nothing overflows; the rate exponent m3 + m8 θ must stay > 0 (a
// flow stress that rises with the rate). Every constant is a sensitivity parameter; the derivative
// in T (the field's, for ∂R_u/∂T) is Sacado's, as for the other laws.
#pragma once

#include <cmath>
#include <string>

#include "flowform/physics/materials/MaterialLaw.hpp"

namespace flowform {

struct HenselSpittel {
  static constexpr const char* kName = "Hensel-Spittel";
  static constexpr const char* kDescription =
      "σ̄ = A e^(m1 θ) θ^m9 ε^m2 e^(m4/ε) (1+ε)^(m5 θ) e^(m7 ε) e_r^(m3 + m8 θ), θ = T − 273.15 °C, at a uniform "
      "Strain ε (docs/theory.md §1)";
  static constexpr double kCelsiusZero = 273.15;  ///< θ = T − 273.15
  enum Parameter { kA, kM1, kM2, kM3, kM4, kM5, kM7, kM8, kM9, kStrain, kTemperature, kNumParameters };
  using Range = MaterialParameterInfo::Range;
  /// Defaults: a rate-sensitive law (m3 = 0.15) with a 0.3 %/°C softening and mild strain terms,
  /// of the size published for hot-working steels; a case states its own.
  static constexpr MaterialParameterInfo kParameters[kNumParameters] = {
      {"A", "A", "A > 0 [stress]", 1500.0, Range::Positive, true, true},
      {"m1", "m1", "temperature coefficient [1/°C]", -0.003, Range::Finite, true, true},
      {"m2", "m2", "strain exponent", -0.1, Range::Finite, true, true},
      {"m3", "m3", "rate exponent m3 > 0 (with m8 θ: the rate sensitivity)", 0.15, Range::Positive, true, true},
      {"m4", "m4", "coefficient of 1/ε", -0.05, Range::Finite, true, true},
      {"m5", "m5", "coefficient of θ ln(1 + ε) [1/°C]", 0.0, Range::Finite, true, true},
      {"m7", "m7", "coefficient of ε", 0.0, Range::Finite, true, true},
      {"m8", "m8", "coefficient of θ in the rate exponent [1/°C]", 0.0, Range::Finite, true, true},
      {"m9", "m9", "exponent of θ (0: no θ^m9)", 0.0, Range::Finite, true, true},
      {"Strain", "eps", "the equivalent strain ε > 0 the law is read at (uniform)", 1.0, Range::Positive, true, true},
      {"Temperature", "T", "T > 273.15, uniform and prescribed, or the field's [K]", 1373.15, Range::Positive, true,
       true}};
  static constexpr int kExponent = kM3;

  template <typename Scalar, typename PScalar>
  static Scalar flowStress(const Scalar& eReg, const PScalar* p) {
    using std::exp;
    using std::log;
    const PScalar theta = p[kTemperature] - kCelsiusZero;
    const PScalar eps = p[kStrain];
    PScalar logC = log(p[kA]) + p[kM1] * theta + p[kM2] * log(eps) + p[kM4] / eps + p[kM5] * theta * log(1.0 + eps) +
                   p[kM7] * eps;
    // θ^m9: with θ > 0 always (so that ∂/∂m9 = log θ survives at m9 = 0); at θ ≤ 0 only when m9 ≠ 0,
    // where it is NaN (refused for the law's own T by inputError; the field's is checked for NaN).
    if (theta > 0.0 || p[kM9] != 0.0) logC += p[kM9] * log(theta);
    return exp(logC + (p[kM3] + p[kM8] * theta) * log(eReg));
  }

  static bool isNewtonian(const double*) { return false; }

  /// What is wrong with the constants at the law's own temperature ("" when nothing): θ > 0 where
  /// θ^m9 is used, and a flow stress that rises with the rate (m3 + m8 θ > 0).
  static std::string inputError(const double* p) {
    const double theta = p[kTemperature] - kCelsiusZero;
    if (p[kM9] != 0.0 && theta <= 0.0)
      return "Temperature must exceed 273.15 K (θ > 0 °C) when m9 != 0 (θ^m9)";
    if (p[kM3] + p[kM8] * theta <= 0.0)
      return "the rate exponent m3 + m8 θ = " + std::to_string(p[kM3] + p[kM8] * theta) +
             " at θ = " + std::to_string(theta) + " °C must be > 0 (a flow stress that rises with the rate)";
    return "";
  }

  /// γ of the Newtonian predictor: σ̄ = e_r/γ through the law's stress at e_r = 1, γ = 1/σ̄(1).
  static double newtonianRateConstant(const double* p) { return 1.0 / flowStress<double, double>(1.0, p); }
};

}  // namespace flowform
