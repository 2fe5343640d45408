// The SQP's dense QP (optimization/DenseQp.hpp) on problems whose solutions are known by hand:
// a strictly convex QP with one active constraint (the projection of a point onto a half-plane
// in a box), a linear program whose optimum is a vertex (the box and one cut), a degenerate LP
// (an optimal edge: any point of it, the objective's value exact) and a QP whose unconstrained
// minimum is feasible (no constraint active, multipliers 0). Tolerance 1e-8: the method stops
// at residuals and gap 1e-11 of the data, the solutions are O(1).
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>

#include "flowform/optimization/DenseQp.hpp"

namespace {

using flowform::solveDenseQp;
using Matrix = std::vector<std::vector<double>>;

/// Rows of the box lo <= x <= hi.
void box(Matrix& G, std::vector<double>& h, std::size_t n, double lo, double hi) {
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> a(n, 0.0);
    a[j] = 1.0;
    G.push_back(a);
    h.push_back(hi);
    a[j] = -1.0;
    G.push_back(a);
    h.push_back(-lo);
  }
}

TEUCHOS_UNIT_TEST(DenseQp, ProjectionOntoAHalfPlane) {
  // min ½|x − (2, 1)|² s.t. x1 + x2 <= 1 in [−5, 5]²: x* = (1, 0), multiplier 1.
  Matrix H = {{1, 0}, {0, 1}}, G;
  std::vector<double> f = {-2, -1}, h;
  box(G, h, 2, -5, 5);
  G.push_back({1, 1});
  h.push_back(1);
  const auto r = solveDenseQp(H, f, G, h);
  TEST_ASSERT(r.converged);
  TEST_FLOATING_EQUALITY(r.x[0], 1.0, 1e-8);
  TEST_COMPARE(std::abs(r.x[1]), <, 1e-8);
  TEST_FLOATING_EQUALITY(r.z.back(), 1.0, 1e-8);
}

/// min fᵀx s.t. x1 + x2 <= cut in [0, 1]² (a linear program).
flowform::DenseQpResult unitSquareLp(const std::vector<double>& f, double cut) {
  Matrix G;
  std::vector<double> h;
  box(G, h, 2, 0, 1);
  G.push_back({1, 1});
  h.push_back(cut);
  return solveDenseQp(Matrix{{0, 0}, {0, 0}}, f, G, h);
}

TEUCHOS_UNIT_TEST(DenseQp, LinearProgramAtAVertex) {
  // min −x1 − 2 x2 s.t. x1 + x2 <= 1.5 in [0, 1]²: x* = (0.5, 1).
  const auto r = unitSquareLp({-1, -2}, 1.5);
  TEST_ASSERT(r.converged);
  TEST_FLOATING_EQUALITY(r.x[0], 0.5, 1e-8);
  TEST_FLOATING_EQUALITY(r.x[1], 1.0, 1e-8);
}

TEUCHOS_UNIT_TEST(DenseQp, DegenerateLinearProgram) {
  // min −x1 − x2 s.t. x1 + x2 <= 1 in [0, 1]²: the whole edge is optimal, value −1.
  const auto r = unitSquareLp({-1, -1}, 1.0);
  TEST_ASSERT(r.converged);
  TEST_FLOATING_EQUALITY(r.x[0] + r.x[1], 1.0, 1e-8);
  TEST_COMPARE(r.x[0], >=, -1e-8);
  TEST_COMPARE(r.x[1], >=, -1e-8);
}

TEUCHOS_UNIT_TEST(DenseQp, InteriorMinimum) {
  // min ½ xᵀ H x − bᵀx with H = [[2, 1], [1, 2]], b = (1, 1): x* = (1/3, 1/3), inside the box.
  Matrix H = {{2, 1}, {1, 2}}, G;
  std::vector<double> f = {-1, -1}, h;
  box(G, h, 2, -1, 1);
  const auto r = solveDenseQp(H, f, G, h);
  TEST_ASSERT(r.converged);
  TEST_FLOATING_EQUALITY(r.x[0], 1.0 / 3.0, 1e-8);
  TEST_FLOATING_EQUALITY(r.x[1], 1.0 / 3.0, 1e-8);
  for (double z : r.z) TEST_COMPARE(z, <, 1e-8);
}

}  // namespace
