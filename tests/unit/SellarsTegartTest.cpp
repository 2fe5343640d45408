// The Sellars–Tegart law (materials/SellarsTegart.hpp) and the material-law registry
// (materials/MaterialLaws.hpp):
//
//   Z = e_r exp(Q/(R T)),   σ̄ = (1/α) asinh((Z/A)^(1/n)),   R = 8.314 J/(mol K)
//
// Values against constants computed independently (python3 mpmath, 40 digits, the formula
// as written above: asinh((Z/A)**(1/n))/α) and against the same formula in long double with
// powl; the small- and large-Z limits; no overflow where exp(Q/(R T)) alone would; the
// Sacado derivatives in each parameter against central differences; the registry's facts,
// its Material sublist and its messages.
#include <Sacado.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>

#include "flowform/core/InputError.hpp"
#include "flowform/physics/Material.hpp"

namespace {

using flowform::MaterialParameters;
using flowform::SellarsTegart;
using PFad = Sacado::Fad::SFad<double, 6>;  // Q, T, α, A, n, e0

constexpr int kLaw = flowform::kMaterialLawIndex<SellarsTegart>;

/// AA6061-like constants (MPa): Q = 145 kJ/mol, T = 723 K, α = 0.045 /MPa, A = 2.4e8 /s,
/// n = 3.55, e0 = 1e-3 /s. Q/(R T) = 24.12: exp of it is 3.0e10.
template <typename Scalar>
MaterialParameters<Scalar> aa6061(const Scalar& q, const Scalar& t, const Scalar& alpha, const Scalar& a,
                                  const Scalar& n, const Scalar& e0) {
  MaterialParameters<Scalar> m;
  m.law = kLaw;
  m.values[SellarsTegart::kActivationEnergy] = q;
  m.values[SellarsTegart::kTemperature] = t;
  m.values[SellarsTegart::kStressMultiplier] = alpha;
  m.values[SellarsTegart::kRateFactor] = a;
  m.values[SellarsTegart::kRateExponent] = n;
  m.cutoff = e0;
  return m;
}
const MaterialParameters<double> kAA6061 = aa6061(145000.0, 723.0, 0.045, 2.4e8, 3.55, 1e-3);

/// The law as written, in long double with powl and expl (not the library's log form).
long double handFlowStress(long double eReg, const MaterialParameters<double>& m) {
  const long double q = m.values[0], t = m.values[1], alpha = m.values[2], a = m.values[3], n = m.values[4];
  const long double z = eReg * std::exp(q / (8.314L * t));
  return std::asinh(std::pow(z / a, 1.0L / n)) / alpha;
}

// The library forms (Z/A)^(1/n) as exp((log e_r + Q/(R T) − log A)/n): the argument is ~24,
// so its round-off is ~24 eps absolute, ~1e-14 relative after exp and 1/n; asinh and 1/α
// add a few ulps. 1e-13 relative is above that and far below any wrong constant (R, a
// missing 1/n: O(1)).
constexpr double kValueTol = 1e-13;

TEUCHOS_UNIT_TEST(SellarsTegart, HandValues) {
  // e_r → σ̄ [MPa], mpmath at 40 digits.
  const double expected[][2] = {{1e-3, 11.800878736792199593},
                                {0.1, 32.433842297753678376},
                                {1.0, 45.971853484197318535},
                                {10.0, 60.127377771729740796},
                                {100.0, 74.468919563898478838}};
  for (const auto& row : expected) {
    const double sigma = flowform::flowStress(row[0], kAA6061);
    out << "e_r = " << row[0] << ": σ̄ = " << sigma << " (mpmath " << row[1] << ")\n";
    TEST_FLOATING_EQUALITY(sigma, row[1], kValueTol);
    TEST_FLOATING_EQUALITY(sigma, static_cast<double>(handFlowStress(row[0], kAA6061)), kValueTol);
    TEST_FLOATING_EQUALITY(flowform::viscosity(row[0], kAA6061), row[1] / (3.0 * row[0]), kValueTol);
  }
  // The regularized rate is the shared one: e_r(D:D = 0) = e0.
  TEST_EQUALITY(flowform::regularizedStrainRate(0.0, kAA6061), kAA6061.cutoff);
}

TEUCHOS_UNIT_TEST(SellarsTegart, Limits) {
  // x = (Z/A)^(1/n). Small x: asinh x = x − x³/6 + …, so σ̄ α / x − 1 = −x²/6 to O(x⁴);
  // large x: asinh x = ln(2x) + 1/(4x²) − …, so σ̄ α − ln(2x) = 1/(4x²) to O(x⁻⁴).
  // Each is asserted to 1 % of its leading correction, which a wrong limit misses by far.
  const double alpha = kAA6061.values[2], n = kAA6061.values[4];
  const double zOverA = std::exp(145000.0 / (8.314 * 723.0)) / 2.4e8;  // Z/A at e_r = 1
  for (double eReg : {1e-12, 1e-9}) {
    const double x = std::pow(eReg * zOverA, 1.0 / n);
    const double sigma = flowform::flowStress(eReg, kAA6061);
    out << "small: e_r = " << eReg << ", x = " << x << "\n";
    TEST_COMPARE(x, <, 0.05);
    TEST_FLOATING_EQUALITY(sigma * alpha / x - 1.0, -x * x / 6.0, 1e-2);
  }
  for (double eReg : {1e6, 1e8}) {
    const double x = std::pow(eReg * zOverA, 1.0 / n);
    const double sigma = flowform::flowStress(eReg, kAA6061);
    out << "large: e_r = " << eReg << ", x = " << x << "\n";
    TEST_COMPARE(x, >, 100.0);
    TEST_FLOATING_EQUALITY(sigma * alpha - std::log(2.0 * x), 1.0 / (4.0 * x * x), 1e-2);
  }
}

TEUCHOS_UNIT_TEST(SellarsTegart, NoOverflowWhereExpQOverRTWould) {
  // Q/(R T) = 793.8 > 709.8: exp(Q/(R T)) alone is inf in double, Z/A = 1e300-scaled is not.
  // mpmath: σ̄ = 473.47520345875935180 at Q = 3.3e6, T = 500, α = 0.045, A = 1e300, n = 5, e_r = 1.
  const MaterialParameters<double> m = aa6061(3.3e6, 500.0, 0.045, 1e300, 5.0, 1e-3);
  TEST_ASSERT(std::isinf(std::exp(3.3e6 / (8.314 * 500.0))));
  const double sigma = flowform::flowStress(1.0, m);
  TEST_ASSERT(std::isfinite(sigma));
  // The argument of exp is now ~794/5 with round-off ~800 eps: 1e-12 relative.
  TEST_FLOATING_EQUALITY(sigma, 473.47520345875935180, 1e-12);
}

PFad seeded(const MaterialParameters<double>& m, int i) {
  return PFad(6, i, i < 5 ? m.values[i] : m.cutoff);
}

/// μ(D:D) with every parameter seeded: derivative i is dμ/dh_i (h = Q, T, α, A, n, e0).
PFad viscosityWrtParameters(double ddot, const MaterialParameters<double>& m) {
  const MaterialParameters<PFad> p = aa6061(seeded(m, 0), seeded(m, 1), seeded(m, 2), seeded(m, 3), seeded(m, 4),
                                            seeded(m, 5));
  return flowform::viscosity(flowform::regularizedStrainRate(PFad(ddot), p), p);
}

double viscosityOf(double ddot, const MaterialParameters<double>& m) {
  return flowform::viscosity(flowform::regularizedStrainRate(ddot, m), m);
}

TEUCHOS_UNIT_TEST(SellarsTegart, DerivativeWrtParametersMatchesFd) {
  // Rates from the cutoff-dominated to fast flow (D:D = 1e-8 gives e ≈ 8e-5 < e0).
  for (double ddot : {1e-8, 0.37, 25.0, 1e4}) {
    const PFad mu = viscosityWrtParameters(ddot, kAA6061);
    TEST_FLOATING_EQUALITY(mu.val(), viscosityOf(ddot, kAA6061), kValueTol);
    // Central FD with δ = 1e-5 of each parameter (of e_r for e0, as MaterialTest): σ̄ varies
    // on the scale of each parameter except Q and T, where it varies on the scale
    // R T/(…): d(Q/(R T))/dQ · Q = Q/(R T) ≈ 24, so the step in the exponent is 24e-5 and the
    // truncation (24e-5)²/6 · O(1) ≈ 1e-8 relative; round-off eps·|μ|/(δ|μ'|) ≲ 1e-10
    // (≈ 1e-7 for e0 when e ≫ e0). Tolerance 1e-6 relative; a derivative missing a
    // chain-rule factor (1/n, R, the sign of log A) is off by O(1).
    const double er = std::sqrt(2.0 / 3.0 * ddot + kAA6061.cutoff * kAA6061.cutoff);
    for (int i = 0; i < 6; ++i) {
      const double h = 1e-5 * (i < 5 ? kAA6061.values[i] : er);
      MaterialParameters<double> mp = kAA6061, mm = kAA6061;
      (i < 5 ? mp.values[i] : mp.cutoff) += h;
      (i < 5 ? mm.values[i] : mm.cutoff) -= h;
      const double fd = (viscosityOf(ddot, mp) - viscosityOf(ddot, mm)) / (2.0 * h);
      out << "D:D = " << ddot << ", parameter " << i << ": AD " << mu.dx(i) << ", FD " << fd << "\n";
      TEST_FLOATING_EQUALITY(mu.dx(i), fd, 1e-6);
    }
    // Closed forms: σ̄ ∝ 1/α, so dμ/dα = −μ/α; and Q, T enter only through Q/T, so
    // T dμ/dT = −Q dμ/dQ.
    TEST_FLOATING_EQUALITY(mu.dx(2), -mu.val() / kAA6061.values[2], kValueTol);
    TEST_FLOATING_EQUALITY(kAA6061.values[1] * mu.dx(1), -kAA6061.values[0] * mu.dx(0), 1e-12);
  }
}

TEUCHOS_UNIT_TEST(MaterialLaws, Registry) {
  const auto& laws = flowform::materialLaws();
  TEST_EQUALITY_CONST(laws.size(), 3u);
  TEST_EQUALITY(laws[0].name, std::string("Power Law"));  // the default, first
  TEST_EQUALITY(laws[kLaw].name, std::string("Sellars-Tegart"));
  TEST_EQUALITY(flowform::materialLawIndex("Sellars-Tegart"), kLaw);
  TEST_EQUALITY_CONST(flowform::materialLawIndex("Johnson-Cook"), -1);
  TEST_EQUALITY(laws[kLaw].parameters[laws[kLaw].exponent].name, std::string("Rate Exponent"));
  for (const auto& p : laws[kLaw].parameters) TEST_ASSERT(p.sensitivity && p.relativeStep);

  // The Material sublist: Law, the law's parameters, the shared cutoff.
  Teuchos::ParameterList material("Material");
  material.set("Law", std::string("Sellars-Tegart"));
  material.set("Temperature", 650.0);
  TEST_EQUALITY(flowform::materialLawOf(material), kLaw);
  material.validateParametersAndSetDefaults(*flowform::validMaterialParameters(kLaw));
  const MaterialParameters<double> m = flowform::materialFromParameters(material);
  TEST_EQUALITY(m.law, kLaw);
  TEST_EQUALITY(m.values[SellarsTegart::kTemperature], 650.0);
  TEST_EQUALITY(m.values[SellarsTegart::kActivationEnergy], 145000.0);
  TEST_EQUALITY(m.cutoff, 1e-3);
  // A parameter of another law is not in this law's list (Teuchos names the valid ones).
  Teuchos::ParameterList mixed(material);
  mixed.set("Yield Stress", 1.0);
  TEST_THROW(mixed.validateParameters(*flowform::validMaterialParameters(kLaw)), std::exception);
  // ... and materialLawOf says whose parameter it is.
  try {
    flowform::materialLawOf(mixed);
    TEST_ASSERT(false);
  } catch (const flowform::InputError& e) {
    const std::string what = e.what();
    TEST_ASSERT(what.find("Material/Yield Stress is a parameter of material law 'Power Law'") != std::string::npos);
  }
  // An unknown law: InputError naming the registered ones.
  Teuchos::ParameterList unknown("Material");
  unknown.set("Law", std::string("Johnson-Cook"));
  try {
    flowform::materialLawOf(unknown);
    TEST_ASSERT(false);
  } catch (const flowform::InputError& e) {
    const std::string what = e.what();
    TEST_ASSERT(what.find("'Power Law', 'Sellars-Tegart'") != std::string::npos);
  }
  // No Law: the default, so every case without one runs the power law.
  TEST_EQUALITY_CONST(flowform::materialLawOf(Teuchos::ParameterList("Material")), 0);
}

TEUCHOS_UNIT_TEST(MaterialLaws, NewtonianPredictor) {
  // Sellars–Tegart is never linear; its predictor is the power law with σ0 = 0, n = 1 and
  // γ = α A exp(−Q/(R T)), the law's small-Z limit at n = 1: σ̄ ≈ Z/(α A) = e_r/γ.
  TEST_ASSERT(!flowform::isNewtonian(kAA6061));
  const MaterialParameters<double> p = flowform::newtonianPredictor(kAA6061);
  TEST_ASSERT(flowform::isNewtonian(p));
  TEST_EQUALITY_CONST(p.law, 0);
  const double gamma = 0.045 * 2.4e8 * std::exp(-145000.0 / (8.314 * 723.0));
  TEST_FLOATING_EQUALITY(p.values[1], gamma, kValueTol);
  TEST_EQUALITY(p.cutoff, kAA6061.cutoff);
  MaterialParameters<double> linear = kAA6061;
  linear.values[SellarsTegart::kRateExponent] = 1.0;
  const double eReg = 1e-12;  // Z/A ≈ 1.3e-10: asinh x = x to 1e-20
  TEST_FLOATING_EQUALITY(flowform::viscosity(eReg, linear), flowform::viscosity(eReg, p), kValueTol);
  // The power law's own predictor keeps γ and e0, sets σ0 = 0, n = 1 (NonlinearSolver's).
  const MaterialParameters<double> power = flowform::newtonianPredictor(flowform::powerLaw(0.5, 1.3, 5.0, 1e-2));
  TEST_EQUALITY(power.values[0], 0.0);
  TEST_EQUALITY(power.values[1], 1.3);
  TEST_EQUALITY(power.values[2], 1.0);
  TEST_EQUALITY(power.cutoff, 1e-2);
}

}  // namespace
