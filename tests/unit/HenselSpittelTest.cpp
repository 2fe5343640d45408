// The Hensel–Spittel law (materials/HenselSpittel.hpp):
//
//   σ̄ = A e^(m1 θ) θ^m9 ε^m2 e^(m4/ε) (1 + ε)^(m5 θ) e^(m7 ε) e_r^(m3 + m8 θ),   θ = T − 273.15
//
// Values against the product as written, in long double with powl and expl (the library forms
// it in logs); its reduction to the power law (only A and m3: σ̄ = A e_r^m3 is the power law with
// σ0 = 0, n = 1/m3, γ = A^(−1/m3)); the Sacado derivatives in every parameter (the temperature's
// among them: the Jacobian's ∂R_u/∂T) against central differences; its registry facts and its
// Newtonian predictor.
#include <Sacado.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>

#include "flowform/physics/Material.hpp"

namespace {

using flowform::HenselSpittel;
using flowform::MaterialParameters;
constexpr int kLaw = flowform::kMaterialLawIndex<HenselSpittel>;
constexpr int kNum = HenselSpittel::kNumParameters;
using PFad = Sacado::Fad::SFad<double, kNum + 1>;  // the law's parameters and e0

/// Every term on: constants of the size of published steel fits (A in MPa, θ in °C), at 1100 °C.
MaterialParameters<double> steel() {
  MaterialParameters<double> m;
  m.law = kLaw;
  const double v[kNum] = {1500.0, -0.0029, -0.12, 0.14, -0.055, 0.0002, -0.02, 0.00003, 0.15, 0.8, 1373.15};
  for (int i = 0; i < kNum; ++i) m.values[i] = v[i];
  m.cutoff = 1e-3;
  return m;
}

long double handFlowStress(long double er, const MaterialParameters<double>& m) {
  const long double a = m.values[0], m1 = m.values[1], m2 = m.values[2], m3 = m.values[3], m4 = m.values[4],
                    m5 = m.values[5], m7 = m.values[6], m8 = m.values[7], m9 = m.values[8], eps = m.values[9];
  const long double theta = m.values[10] - 273.15L;
  return a * std::exp(m1 * theta) * std::pow(theta, m9) * std::pow(eps, m2) * std::exp(m4 / eps) *
         std::pow(1.0L + eps, m5 * theta) * std::exp(m7 * eps) * std::pow(er, m3 + m8 * theta);
}

// log σ̄ is a sum of terms up to ~|m1 θ| ≈ 3.2; its round-off a few eps of that, ~1e-15
// relative after exp. 1e-13 is above it and far below a wrong term (O(1e-2) or more).
constexpr double kValueTol = 1e-13;

TEUCHOS_UNIT_TEST(HenselSpittel, HandValues) {
  const MaterialParameters<double> m = steel();
  for (double er : {1e-3, 0.1, 1.0, 10.0, 300.0}) {
    const double sigma = flowform::flowStress(er, m);
    out << "e_r = " << er << ": σ̄ = " << sigma << "\n";
    TEST_FLOATING_EQUALITY(sigma, static_cast<double>(handFlowStress(er, m)), kValueTol);
  }
  // 100 °C hotter: the factor e^(100 m1) (1.1^... the other θ terms) — softer.
  MaterialParameters<double> hotter = m;
  hotter.values[HenselSpittel::kTemperature] += 100.0;
  TEST_COMPARE(flowform::flowStress(1.0, hotter), <, flowform::flowStress(1.0, m));
}

TEUCHOS_UNIT_TEST(HenselSpittel, ReducesToThePowerLaw) {
  // A = 80, m3 = 0.2, the rest 0: σ̄ = 80 e_r^0.2 = (e_r/γ)^(1/n), n = 5, γ = 80^(−5).
  MaterialParameters<double> m;
  m.law = kLaw;
  m.values[HenselSpittel::kA] = 80.0;
  m.values[HenselSpittel::kM3] = 0.2;
  m.values[HenselSpittel::kStrain] = 1.0;
  m.values[HenselSpittel::kTemperature] = 900.0;
  m.cutoff = 1e-2;
  const MaterialParameters<double> power = flowform::powerLaw(0.0, std::pow(80.0, -5.0), 5.0, 1e-2);
  for (double ddot : {0.0, 1e-4, 0.3, 40.0}) {
    const double er = flowform::regularizedStrainRate(ddot, m);
    TEST_FLOATING_EQUALITY(flowform::viscosity(er, m), flowform::viscosity(er, power), kValueTol);
  }
}

TEUCHOS_UNIT_TEST(HenselSpittel, DerivativeWrtParametersMatchesFd) {
  const MaterialParameters<double> m = steel();
  for (double ddot : {1e-8, 0.37, 25.0, 1e4}) {
    MaterialParameters<PFad> p;
    p.law = kLaw;
    for (int i = 0; i < kNum; ++i) p.values[i] = PFad(kNum + 1, i, m.values[i]);
    p.cutoff = PFad(kNum + 1, kNum, m.cutoff);
    const PFad mu = flowform::viscosity(flowform::regularizedStrainRate(PFad(ddot), p), p);
    auto muOf = [&](const MaterialParameters<double>& q) {
      return flowform::viscosity(flowform::regularizedStrainRate(ddot, q), q);
    };
    TEST_FLOATING_EQUALITY(mu.val(), muOf(m), kValueTol);
    // Central differences, δ = 1e-6 of each parameter's scale (1e-6 absolute for the small θ
    // coefficients, whose effect is θ δ ~ 1e-3 in log σ̄); truncation (θ δ)²/6 ~ 2e-7 relative at
    // most, round-off eps/1e-6 ~ 1e-10: tolerance 1e-5; a missing chain-rule factor (θ, 1/ε,
    // log e_r) is off by O(1).
    const double er = std::sqrt(2.0 / 3.0 * ddot + m.cutoff * m.cutoff);
    for (int i = 0; i <= kNum; ++i) {
      const double scale = i == kNum ? er : (std::abs(m.values[i]) > 0.01 ? std::abs(m.values[i]) : 1.0);
      const double h = 1e-6 * scale;
      MaterialParameters<double> mp = m, mm = m;
      (i < kNum ? mp.values[i] : mp.cutoff) += h;
      (i < kNum ? mm.values[i] : mm.cutoff) -= h;
      const double fd = (muOf(mp) - muOf(mm)) / (2.0 * h);
      out << "D:D = " << ddot << ", parameter " << i << ": AD " << mu.dx(i) << ", FD " << fd << "\n";
      TEST_FLOATING_EQUALITY(mu.dx(i), fd, 1e-5);
    }
    // Closed form: σ̄ ∝ A, so dμ/dA = μ/A.
    TEST_FLOATING_EQUALITY(mu.dx(HenselSpittel::kA), mu.val() / m.values[HenselSpittel::kA], kValueTol);
  }
}

TEUCHOS_UNIT_TEST(HenselSpittel, DerivativeInM9AtZero) {
  // m9 = 0 (no θ^m9 term) still has ∂σ̄/∂m9 = σ̄ log θ: the term is kept with its zero exponent.
  MaterialParameters<double> m = steel();
  m.values[HenselSpittel::kM9] = 0.0;
  MaterialParameters<PFad> p;
  p.law = kLaw;
  for (int i = 0; i < kNum; ++i) p.values[i] = PFad(kNum + 1, i, m.values[i]);
  p.cutoff = PFad(m.cutoff);
  const PFad sigma = flowform::flowStress(PFad(2.0), p);
  const double theta = m.values[HenselSpittel::kTemperature] - 273.15;
  TEST_FLOATING_EQUALITY(sigma.dx(HenselSpittel::kM9), sigma.val() * std::log(theta), kValueTol);
}

TEUCHOS_UNIT_TEST(HenselSpittel, RegistryAndPredictor) {
  const auto& laws = flowform::materialLaws();
  TEST_EQUALITY(laws[kLaw].name, std::string("Hensel-Spittel"));
  TEST_EQUALITY(flowform::materialLawIndex("Hensel-Spittel"), kLaw);
  TEST_EQUALITY(flowform::temperatureParameter(kLaw), static_cast<int>(HenselSpittel::kTemperature));
  TEST_EQUALITY(laws[kLaw].parameters[laws[kLaw].exponent].name, std::string("m3"));
  // The Material sublist with its defaults.
  Teuchos::ParameterList material("Material");
  material.set("Law", std::string("Hensel-Spittel"));
  material.set("m9", 0.1);
  TEST_EQUALITY(flowform::materialLawOf(material), kLaw);
  material.validateParametersAndSetDefaults(*flowform::validMaterialParameters(kLaw));
  const MaterialParameters<double> m = flowform::materialFromParameters(material);
  TEST_EQUALITY(m.values[HenselSpittel::kM9], 0.1);
  TEST_EQUALITY(m.values[HenselSpittel::kA], 1500.0);
  // The predictor: the power law with n = 1 through the law's stress at e_r = 1.
  TEST_ASSERT(!flowform::isNewtonian(m));
  const MaterialParameters<double> p = flowform::newtonianPredictor(m);
  TEST_FLOATING_EQUALITY(flowform::flowStress(1.0, p), flowform::flowStress(1.0, m), kValueTol);
}

}  // namespace
