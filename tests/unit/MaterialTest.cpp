// The rigid-viscoplastic law (Material.hpp, docs/theory.md §1): values against the formulas written
// out again here with std::pow (the library uses exp(log(·)/n)), the Newtonian limit, and
// Sacado derivatives — with respect to D:D and to each parameter σ0, γ, n, e0 — against
// closed-form derivatives and central finite differences.
//
//   e_r = sqrt(2/3 D:D + e0²),   σ̄ = σ0 + (e_r/γ)^(1/n),   μ = σ̄ / (3 e_r)
#include <Sacado.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>

#include "flowform/physics/Material.hpp"

namespace {

using flowform::MaterialParameters;
using flowform::powerLaw;
// Fixed-size Fad throughout (as the assembler uses): GCC 12 reports a false -Wuse-after-free
// inside Sacado's DFad storage.
using Fad1 = Sacado::Fad::SFad<double, 1>;  // d/d(D:D)
using Fad3 = Sacado::Fad::SFad<double, 3>;  // d/d(D_xx, D_yy, D_xy)
using PFad = Sacado::Fad::SFad<double, 4>;  // one derivative per parameter: σ0, γ, n, e0

// The law written out independently of Material.hpp (pow instead of exp∘log).
double handRate(double ddot, const MaterialParameters<double>& m) {
  return std::sqrt(2.0 / 3.0 * ddot + m.cutoff * m.cutoff);
}
// The power law's parameters in MaterialParameters::values: σ0, γ, n.
double sigma0(const MaterialParameters<double>& m) { return m.values[0]; }
double gammaOf(const MaterialParameters<double>& m) { return m.values[1]; }
double exponent(const MaterialParameters<double>& m) { return m.values[2]; }
double handFlowStress(double eReg, const MaterialParameters<double>& m) {
  return sigma0(m) + std::pow(eReg / gammaOf(m), 1.0 / exponent(m));
}
double handViscosity(double eReg, const MaterialParameters<double>& m) {
  return handFlowStress(eReg, m) / (3.0 * eReg);
}

double libViscosityOfDdot(double ddot, const MaterialParameters<double>& m) {
  return flowform::viscosity(flowform::regularizedStrainRate(ddot, m), m);
}

// Values are O(1) and each is a handful of operations (sqrt, one pow or exp∘log, a
// division): both forms carry a few ulps of round-off, and exp(log(y)/n) amplifies the
// error of log(y) by |log(y)/n| ≤ 2 here. 1e-14 ≈ 45 ulps leaves a wide margin while any
// wrong factor or exponent (e.g. 2/3 ↔ 3/2, 1/n ↔ n) is off by O(1).
constexpr double kValueTol = 1e-14;

const MaterialParameters<double> kLaw = powerLaw(0.5, 2.0, 4.0, 1e-3);  // σ0, γ, n, e0

TEUCHOS_UNIT_TEST(Material, HandValues) {
  // D:D values from the rigid limit to fast flow, so both regimes of e_r are exercised.
  for (double ddot : {0.0, 1e-8, 0.37, 25.0}) {
    const double er = flowform::regularizedStrainRate(ddot, kLaw);
    const double erHand = handRate(ddot, kLaw);
    TEST_FLOATING_EQUALITY(er, erHand, kValueTol);
    TEST_FLOATING_EQUALITY(flowform::flowStress(er, kLaw), handFlowStress(erHand, kLaw), kValueTol);
    TEST_FLOATING_EQUALITY(flowform::viscosity(er, kLaw), handViscosity(erHand, kLaw), kValueTol);
  }
  // One point fully by hand: D:D = 0.375 → 2/3 D:D = 0.25, e_r = sqrt(0.25 + 1e-6);
  // σ̄ = 0.5 + (e_r/2)^(1/4), μ = σ̄ / (3 e_r).
  const double er = std::sqrt(0.25 + 1e-6);
  const double sigma = 0.5 + std::sqrt(std::sqrt(er / 2.0));
  TEST_FLOATING_EQUALITY(flowform::regularizedStrainRate(0.375, kLaw), er, kValueTol);
  TEST_FLOATING_EQUALITY(flowform::flowStress(er, kLaw), sigma, kValueTol);
  TEST_FLOATING_EQUALITY(libViscosityOfDdot(0.375, kLaw), sigma / (3.0 * er), kValueTol);
  // In the rigid limit e_r = e0 exactly (0 + e0² under the sqrt).
  TEST_EQUALITY(flowform::regularizedStrainRate(0.0, kLaw), kLaw.cutoff);
}

TEUCHOS_UNIT_TEST(Material, NewtonianViscosityIsConstant) {
  // n = 1, σ0 = 0: μ = (e_r/γ)/(3 e_r) = 1/(3γ) for every strain rate and cutoff.
  for (double gamma : {1.0, 1.7, 1e-2})
    for (double e0 : {1e-6, 1e-3, 0.5}) {
      const MaterialParameters<double> m = powerLaw(0.0, gamma, 1.0, e0);
      TEST_ASSERT(flowform::isNewtonian(m));
      for (double ddot : {0.0, 1e-10, 1.0, 1e6})
        TEST_FLOATING_EQUALITY(libViscosityOfDdot(ddot, m), 1.0 / (3.0 * gamma), kValueTol);
    }
  TEST_ASSERT(!flowform::isNewtonian(kLaw));
  TEST_ASSERT(!flowform::isNewtonian(powerLaw(0.0, 1.0, 2.0, 1e-3)));
  TEST_ASSERT(!flowform::isNewtonian(powerLaw(0.1, 1.0, 1.0, 1e-3)));
}

TEUCHOS_UNIT_TEST(Material, StressInvariantMatchesFlowStress) {
  // With s = 2 μ D: sqrt(3/2 s:s) = 2 μ sqrt(3/2 D:D) = 3 μ e = σ̄ e/e_r (Material.hpp).
  // Plane strain D = [[0.3, 0.2], [0.2, -0.3]], D:D = 0.09 + 0.09 + 2·0.04 = 0.26.
  const double ddot = 0.26;
  const double e = std::sqrt(2.0 / 3.0 * ddot);
  const double er = flowform::regularizedStrainRate(ddot, kLaw);
  const double twoMu = 2.0 * flowform::viscosity(er, kLaw);
  const double sds = twoMu * twoMu * ddot;
  TEST_FLOATING_EQUALITY(std::sqrt(1.5 * sds), flowform::flowStress(er, kLaw) * e / er, kValueTol);
}

// Closed-form derivatives with respect to D:D (chain rule through e_r):
//   de_r/d(D:D) = 1/(3 e_r),  dσ̄/de_r = (e_r/γ)^(1/n) / (n e_r),
//   dμ/de_r = (e_r dσ̄/de_r − σ̄) / (3 e_r²).
TEUCHOS_UNIT_TEST(Material, DerivativeWrtDdotMatchesClosedFormAndFd) {
  for (double ddot : {0.0, 1e-4, 0.37, 25.0}) {
    const Fad1 d(1, 0, ddot);
    const Fad1 er = flowform::regularizedStrainRate(d, kLaw);
    const Fad1 sig = flowform::flowStress(er, kLaw);
    const Fad1 mu = flowform::viscosity(er, kLaw);

    const double r = handRate(ddot, kLaw);
    const double dr = 1.0 / (3.0 * r);
    const double dsdr = std::pow(r / gammaOf(kLaw), 1.0 / exponent(kLaw)) / (exponent(kLaw) * r);
    const double dmudr = (r * dsdr - handFlowStress(r, kLaw)) / (3.0 * r * r);
    // Closed form vs AD: the same few operations in another order, round-off only (see
    // kValueTol); the derivatives are finite at D:D = 0 because e_r ≥ e0 > 0.
    TEST_ASSERT(std::isfinite(mu.dx(0)));
    TEST_FLOATING_EQUALITY(er.dx(0), dr, kValueTol);
    TEST_FLOATING_EQUALITY(sig.dx(0), dsdr * dr, kValueTol);
    TEST_FLOATING_EQUALITY(mu.dx(0), dmudr * dr, kValueTol);

    // Central FD, where D:D ± δ stays ≥ 0. Step δ = 1e-4·(D:D): truncation error
    // (δ²/6)|μ'''| ≈ 1e-8/6 · |μ'| · |x² μ'''/μ'|, and for the power laws here
    // (μ ~ x^k with |k| ≤ 1) x² μ'''/μ' is O(1), so ~1e-9 relative; round-off
    // eps·|μ|/δ·x ≈ 1e-12 relative. Tolerance 1e-7: 100× above both, while a derivative
    // missing a chain-rule factor is off by O(1).
    if (ddot > 0.0) {
      const double h = 1e-4 * ddot;
      const double fd = (libViscosityOfDdot(ddot + h, kLaw) - libViscosityOfDdot(ddot - h, kLaw)) / (2.0 * h);
      TEST_FLOATING_EQUALITY(mu.dx(0), fd, 1e-7);
    }
  }
}

TEUCHOS_UNIT_TEST(Material, DerivativeThroughZeroStrainRateIsFinite) {
  // The tangent at a rigid zone: D:D = Σ D_ij² with D = 0 seeded as independent variables.
  // d(D:D)/dD = 2D = 0, so dμ/dD must be exactly 0 (not 0·∞ = NaN, which an unregularized
  // sqrt(D:D) would give through Sacado's sqrt'(0) = ∞).
  const Fad3 dxx(3, 0, 0.0), dyy(3, 1, 0.0), dxy(3, 2, 0.0);
  const Fad3 ddot = dxx * dxx + dyy * dyy + 2.0 * dxy * dxy;
  const Fad3 mu = flowform::viscosity(flowform::regularizedStrainRate(ddot, kLaw), kLaw);
  TEST_FLOATING_EQUALITY(mu.val(), handViscosity(kLaw.cutoff, kLaw), kValueTol);
  for (int i = 0; i < 3; ++i) TEST_EQUALITY(mu.dx(i), 0.0);
}

/// μ at D:D = `ddot` with the parameters seeded: derivative i is dμ/d(parameter i).
PFad viscosityWrtParameters(double ddot, const MaterialParameters<double>& m) {
  const MaterialParameters<PFad> p =
      powerLaw(PFad(4, 0, sigma0(m)), PFad(4, 1, gammaOf(m)), PFad(4, 2, exponent(m)), PFad(4, 3, m.cutoff));
  // The strain measure is a constant (zero derivatives) of the parameter Fad type, as the
  // assembler's ParamDeriv evaluation would pass it.
  return flowform::viscosity(flowform::regularizedStrainRate(PFad(ddot), p), p);
}

MaterialParameters<double> perturbed(const MaterialParameters<double>& m, int which, double delta) {
  MaterialParameters<double> q = m;
  double* v[4] = {&q.values[0], &q.values[1], &q.values[2], &q.cutoff};
  *v[which] += delta;
  return q;
}

TEUCHOS_UNIT_TEST(Material, DerivativeWrtParametersMatchesFd) {
  // Both regimes: e dominated by D (D:D = 0.37) and by the cutoff (D:D = 1e-8 < e0²).
  for (double ddot : {1e-8, 0.37, 25.0}) {
    const PFad mu = viscosityWrtParameters(ddot, kLaw);
    TEST_FLOATING_EQUALITY(mu.val(), libViscosityOfDdot(ddot, kLaw), kValueTol);
    // Central FD, each step 1e-5 of the scale on which μ varies with that parameter: σ0,
    // γ and n enter through σ0 + (e_r/γ)^(1/n), which varies on the scale of the parameter
    // itself; e0 enters only through e_r² = 2/3 D:D + e0², which varies on the scale e_r
    // (≥ e0), so that step is 1e-5·e_r (it keeps e0 − δ > 0: e_r ≤ 4.1 here).
    // Truncation: (δ/scale)² × O(1) ≈ 1e-10 × (the O(1..10) ratio of third to first
    // derivative of these powers and logs in scaled variables) ≤ 1e-9 relative.
    // Round-off: eps·|μ|/(δ|μ'|) — at most ≈ 1e-7 for e0 when e ≫ e0 (dμ/de0 ≈ μ e0/e_r²
    // is then small), ≈ 2e-11 for the others. Tolerance 1e-6 relative: 10× above the
    // worst of these; a derivative missing a chain-rule factor is off by O(1).
    const double er = handRate(ddot, kLaw);
    const double steps[4] = {1e-5 * sigma0(kLaw), 1e-5 * gammaOf(kLaw), 1e-5 * exponent(kLaw),
                             1e-5 * er};
    for (int i = 0; i < 4; ++i) {
      const double h = steps[i];
      const double fd = (libViscosityOfDdot(ddot, perturbed(kLaw, i, h)) -
                         libViscosityOfDdot(ddot, perturbed(kLaw, i, -h))) / (2.0 * h);
      out << "D:D = " << ddot << ", parameter " << i << ": AD " << mu.dx(i) << ", FD " << fd << "\n";
      TEST_FLOATING_EQUALITY(mu.dx(i), fd, 1e-6);
    }
    // dμ/dσ0 = 1/(3 e_r) exactly (σ̄ is affine in σ0).
    TEST_FLOATING_EQUALITY(mu.dx(0), 1.0 / (3.0 * handRate(ddot, kLaw)), kValueTol);
  }
}

}  // namespace
