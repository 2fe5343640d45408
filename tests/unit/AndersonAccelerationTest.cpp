// Anderson acceleration (solvers/AndersonAcceleration), on linear maps g(x) = G x + c whose fixed
// point x* = (I − G)⁻¹ c is known:
// - with a slow mode (ρ = 0.95) and an overshooting one (−1.3, where the plain iteration diverges),
//   Anderson with depth ≥ the dimension n is GMRES on (I − G) x = c: x* to round-off after n + 1
//   steps (here n = 3, so within 4 steps, 1e-10), from where the plain iteration has grown;
// - with the mixing β = 0.5 the same (β changes the path, not the fixed point);
// - a repeated iterate (a zero column ΔF) is dropped, not divided by: the step stays finite and
//   the plain one (f) comes back;
// - reset() forgets the history: the next step is β f; so does an iterate of another size;
// - a one-column step is the secant step along that column (checked by value), and the history
//   keeps only the last depth + 1 iterates (depth 1: one column at most, the newest pair's).
#include <Teuchos_UnitTestHarness.hpp>
#include <array>
#include <cmath>
#include <vector>

#include "flowform/solvers/AndersonAcceleration.hpp"

namespace {

using flowform::AndersonAcceleration;

// G = Q diag(0.95, −1.3, 0.2) Qᵀ with a rotation Q (so that the modes mix the unknowns), c = (1, 2, 3).
struct LinearMap {
  std::array<std::array<double, 3>, 3> G{};
  std::array<double, 3> c{1.0, 2.0, 3.0};
  LinearMap() {
    const double eig[3] = {0.95, -1.3, 0.2};
    const double a = 0.6, b = 0.8;  // a rotation in (x, y), then one in (y, z)
    const double Q[3][3] = {{a, -b * a, b * b}, {b, a * a, -a * b}, {0.0, b, a}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) G[i][j] += Q[i][k] * eig[k] * Q[j][k];
  }
  std::vector<double> residual(const std::vector<double>& x) const {  // g(x) − x
    std::vector<double> f(3);
    for (int i = 0; i < 3; ++i) {
      f[i] = c[i] - x[i];
      for (int j = 0; j < 3; ++j) f[i] += G[i][j] * x[j];
    }
    return f;
  }
};

double norm(const std::vector<double>& v) {
  double s = 0.0;
  for (double vi : v) s += vi * vi;
  return std::sqrt(s);
}

TEUCHOS_UNIT_TEST(AndersonAcceleration, SolvesALinearFixedPointInDimensionPlusOneSteps) {
  const LinearMap map;
  for (double mixing : {1.0, 0.5}) {
    AndersonAcceleration anderson(5);
    std::vector<double> x{0.0, 0.0, 0.0}, plain = x;
    double residual = 0.0;
    for (int k = 0; k < 5; ++k) {
      const std::vector<double> f = map.residual(x);
      residual = norm(f);
      if (residual < 1e-10) break;
      const std::vector<double> dx = anderson.step(x, f, mixing);
      for (int i = 0; i < 3; ++i) x[i] += dx[i];
      const std::vector<double> fp = map.residual(plain);
      for (int i = 0; i < 3; ++i) plain[i] += fp[i];
    }
    out << "mixing " << mixing << ": |g(x) − x| = " << residual << ", the plain iteration's "
        << norm(map.residual(plain)) << "\n";
    TEST_COMPARE(residual, <, 1e-10);
    TEST_COMPARE(norm(map.residual(plain)), >, 1.0);  // the overshooting mode grows
  }
}

TEUCHOS_UNIT_TEST(AndersonAcceleration, DropsADependentColumnAndResets) {
  AndersonAcceleration anderson(3);
  const std::vector<double> x{1.0, 2.0}, f{0.5, -0.25};
  std::vector<double> dx = anderson.step(x, f, 1.0);
  TEST_FLOATING_EQUALITY(dx[0], 0.5, 1e-15);
  dx = anderson.step(x, f, 1.0);  // the same iterate again: ΔF = 0, dropped
  TEST_EQUALITY(anderson.columnsUsed(), 0);
  TEST_FLOATING_EQUALITY(dx[0], 0.5, 1e-15);
  TEST_FLOATING_EQUALITY(dx[1], -0.25, 1e-15);
  anderson.step({1.5, 1.75}, {0.25, 0.0}, 1.0);
  TEST_EQUALITY(anderson.columnsUsed(), 1);
  anderson.reset();
  dx = anderson.step({1.5, 1.75}, {0.25, 0.0}, 0.5);
  TEST_EQUALITY(anderson.columnsUsed(), 0);
  TEST_FLOATING_EQUALITY(dx[0], 0.125, 1e-15);
}

TEUCHOS_UNIT_TEST(AndersonAcceleration, OneColumnStepAndDepth) {
  // Scalar map g(x) = 0.5 x + 1 (x* = 2), residual f = 1 − 0.5 x. From x0 = 0 (f0 = 1) and
  // x1 = 1 (f1 = 0.5): ΔF = −0.5, ΔX = 1, γ = f1/ΔF = −1, Δx = f1 − γ(ΔX + ΔF) = 0.5 + 0.5 = 1:
  // x2 = 2, the fixed point (the secant step is exact on a linear map).
  AndersonAcceleration anderson(1);
  anderson.step({0.0}, {1.0}, 1.0);
  std::vector<double> dx = anderson.step({1.0}, {0.5}, 1.0);
  TEST_EQUALITY(anderson.columnsUsed(), 1);
  TEST_FLOATING_EQUALITY(dx[0], 1.0, 1e-14);
  // Depth 1 keeps the newest pair only: from x = 2.5 (f = −0.25) the column is (1 → 2.5), not
  // (0 → 1): ΔF = −0.75, ΔX = 1.5, γ = 1/3, Δx = −0.25 − (1.5 − 0.75)/3 = −0.5, to x* = 2 again.
  dx = anderson.step({2.5}, {-0.25}, 1.0);
  TEST_EQUALITY(anderson.columnsUsed(), 1);
  TEST_FLOATING_EQUALITY(dx[0], -0.5, 1e-14);
  // In two unknowns, with independent differences, depth 1 still uses one column (the newest).
  AndersonAcceleration shallow(1);
  shallow.step({0.0, 0.0}, {1.0, 0.0}, 1.0);
  shallow.step({1.0, 0.0}, {0.0, 1.0}, 1.0);
  shallow.step({1.0, 1.0}, {0.5, 0.0}, 1.0);  // ΔF (−1, 1) and (0.5, −1): independent
  TEST_EQUALITY(shallow.columnsUsed(), 1);
  // An iterate of another size starts the history again.
  dx = anderson.step({1.0, 1.0}, {0.5, 0.25}, 0.5);
  TEST_EQUALITY(anderson.columnsUsed(), 0);
  TEST_FLOATING_EQUALITY(dx[1], 0.125, 1e-15);
}

}  // namespace
