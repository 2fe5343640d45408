// The dual linearizations of Newton (docs/theory.md §9): the stress dual of the cell kernel
// (physics/StressDual.hpp) and the slip dual of the bounded friction laws
// (contact/friction/FrictionDual.hpp). What they promise:
//   (1) residual values never change (only derivatives do);
//   (2) a fresh dual (the first Jacobian of a solve) is the exact tangent;
//   (3) after a step the tangent differs from the exact one, by O(step);
//   (4) |τ| = sqrt(2/3 τ:τ) ≤ 1 and ψ ∈ [−1, 1] after every update;
//   (5) slip: dg/du_t = 0 when the dual agrees with sign(u_t), f̂(1 − ψ sign)/|u_t| ∈ (0, 2α_t]
//       when it does not; stick: α_t whatever the dual.
#include <Sacado.hpp>

#include "FlowKernelCell.hpp"
#include "flowform/contact/friction/Coulomb.hpp"
#include "flowform/physics/StressDual.hpp"

namespace {

using flowform::FrictionDualPoint;
using flowform::StressDualPoint;

const std::vector<XY> kTriangle = {{{1.1, 0.2}}, {{2.3, 0.4}}, {{1.5, 1.1}}};
const std::vector<XY> kQuad = {{{1.0, 0.0}}, {{2.1, 0.2}}, {{2.3, 1.3}}, {{0.9, 1.0}}};
// σ0 = 1, n = 5, e0 = 1e-3: nearly rigid-plastic (β ≈ −1), where the dual matters.
const MaterialParameters<double> kPlastic = flowform::powerLaw(1.0, 1.0, 5.0, 1e-3);

std::vector<double> scrambled(int n, double phase) {
  std::vector<double> d(n);
  for (int i = 0; i < n; ++i) d[i] = std::sin(12.9898 * (i + 1) + phase);
  return d;
}

/// The cell residual with its Jacobian (SFad<N>) at x; with `dual`, the stress dual is used
/// (and moved to x first, as the assembler does).
template <int N>
std::vector<Sacado::Fad::SFad<double, N>> jacobian(const Cell& cell, const FlowKernelSettings& s,
                                                   const std::vector<double>& x, StressDualPoint* dual) {
  using Fad = Sacado::Fad::SFad<double, N>;
  std::vector<Fad> xf(N), r(N, Fad(0.0));
  for (int i = 0; i < N; ++i) xf[i] = Fad(N, i, x[i]);
  flowform::addFlowResidual(cell.rule, cell.centroid, cell.h, s, kPlastic, xf.data(), r.data(), dual);
  return r;
}

template <int N>
double jacobianGap(const std::vector<Sacado::Fad::SFad<double, N>>& a,
                   const std::vector<Sacado::Fad::SFad<double, N>>& b) {
  double gap = 0.0, scale = 0.0;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      gap = std::max(gap, std::abs(a[i].dx(j) - b[i].dx(j)));
      scale = std::max(scale, std::abs(b[i].dx(j)));
    }
  return gap / scale;
}

/// Claims (1)–(4) for the cell kernel on one cell and geometry.
template <int N>
void checkStressDual(const std::vector<XY>& nodes, CellType type, Geometry geometry, Teuchos::FancyOStream& out,
                     bool& success) {
  const Cell cell(type, nodes, geometry);
  const FlowKernelSettings s = makeSettings(geometry, 0.1, 0.0, 0.0);
  const auto x0 = scrambled(N, 0.3), d = scrambled(N, 1.7);
  StressDualPoint dual[flowform::kMaxQuadraturePoints];

  // (1), (2): a fresh dual gives the exact values and the exact Jacobian.
  const auto exact0 = jacobian<N>(cell, s, x0, nullptr);
  const auto fresh = jacobian<N>(cell, s, x0, dual);
  double valueGap = 0.0, valueScale = 0.0;
  for (int i = 0; i < N; ++i) {
    valueGap = std::max(valueGap, std::abs(fresh[i].val() - exact0[i].val()));
    valueScale = std::max(valueScale, std::abs(exact0[i].val()));
  }
  out << "fresh dual: value gap " << valueGap / valueScale << ", Jacobian gap " << jacobianGap<N>(fresh, exact0) << "\n";
  TEST_COMPARE(valueGap, <=, 1e-14 * valueScale);
  TEST_COMPARE(jacobianGap<N>(fresh, exact0), <=, 1e-12);

  // (3): after the dual has seen x0, the tangent at x1 = x0 + s d differs from the exact one
  // by O(s): τ_1 − D_1/e_1 is the linearization error of D/e_r, second order in s, plus the
  // part of τ the step did not update, first order. The gap must shrink at least linearly.
  double previous = 0.0;
  for (double step : {1e-1, 1e-2, 1e-3}) {
    StressDualPoint moved[flowform::kMaxQuadraturePoints];
    jacobian<N>(cell, s, x0, moved);
    std::vector<double> x1(N);
    for (int i = 0; i < N; ++i) x1[i] = x0[i] + step * d[i];
    const auto withDual = jacobian<N>(cell, s, x1, moved);
    const auto exact1 = jacobian<N>(cell, s, x1, nullptr);
    double vgap = 0.0;
    for (int i = 0; i < N; ++i) vgap = std::max(vgap, std::abs(withDual[i].val() - exact1[i].val()));
    TEST_COMPARE(vgap, <=, 1e-14 * valueScale);
    const double gap = jacobianGap<N>(withDual, exact1);
    out << "step " << step << ": Jacobian gap " << gap << "\n";
    if (step == 1e-1) TEST_COMPARE(gap, >, 1e-6);  // the dual really changes the tangent
    if (previous > 0.0) TEST_COMPARE(gap, <=, 0.2 * previous);  // ≥ 5× per decade (measured ~100×)
    previous = gap;
  }

  // (4): |τ| ≤ 1 after large random steps.
  StressDualPoint walk[flowform::kMaxQuadraturePoints];
  double largest = 0.0;
  for (int k = 0; k < 20; ++k) {
    std::vector<double> xk = scrambled(N, 0.37 * k);
    for (double& v : xk) v *= 1.0 + 5.0 * k;
    jacobian<N>(cell, s, xk, walk);
    for (int q = 0; q < cell.rule.numPoints; ++q)
      largest = std::max(largest, std::sqrt((2.0 / 3.0) * StressDualPoint::contract(walk[q].tau, walk[q].tau)));
  }
  out << "largest |tau| over 20 random steps: " << largest << "\n";
  TEST_COMPARE(largest, <=, 1.0 + 1e-15);
  TEST_COMPARE(largest, >, 0.5);  // the walk reaches the bound region (the check is not empty)
}

TEUCHOS_UNIT_TEST(StressDual, TrianglePlane) {
  checkStressDual<9>(kTriangle, CellType::Triangle3, Geometry::PlaneStrain, out, success);
}
TEUCHOS_UNIT_TEST(StressDual, TriangleAxisymmetric) {
  checkStressDual<9>(kTriangle, CellType::Triangle3, Geometry::Axisymmetric, out, success);
}
TEUCHOS_UNIT_TEST(StressDual, QuadPlane) {
  checkStressDual<12>(kQuad, CellType::Quadrilateral4, Geometry::PlaneStrain, out, success);
}
TEUCHOS_UNIT_TEST(StressDual, QuadAxisymmetric) {
  checkStressDual<12>(kQuad, CellType::Quadrilateral4, Geometry::Axisymmetric, out, success);
}

// ---------------------------------------------------------------------------------------
// The slip dual, through the Coulomb law (boundedFriction) with u_t and P as the two
// independent variables: dg/du_t = dx(0), dg/dP = dx(1).
// ---------------------------------------------------------------------------------------

using Fad2 = Sacado::Fad::SFad<double, 2>;

struct Friction {
  double g, dgdu, dgdP;
  flowform::FrictionBranch branch;
};

Friction coulomb(double ut, double P, double alpha, double nu, FrictionDualPoint* dual) {
  flowform::FrictionNodeData<Fad2> d{Fad2(2, 0, ut), Fad2(2, 1, P), 0.0, 0.0, alpha, dual};
  const flowform::FrictionParameters<double> fp{nu, 0.0};
  const auto f = flowform::CoulombFriction::force(d, fp, flowform::FrictionSettings{});
  return {f.g.val(), f.g.dx(0), f.g.dx(1), f.branch};
}

TEUCHOS_UNIT_TEST(FrictionDual, SlipAgreeingIsExact) {
  // α_t = 100, f̂ = ν P = 0.2: slip for |u_t| > 2e-3.
  FrictionDualPoint dual;
  const Friction exact = coulomb(0.5, 2.0, 100.0, 0.1, nullptr);
  const Friction first = coulomb(0.5, 2.0, 100.0, 0.1, &dual);  // (2) fresh: exact
  TEST_FLOATING_EQUALITY(first.g, exact.g, 1e-15);
  TEST_EQUALITY(first.dgdu, 0.0);
  TEST_FLOATING_EQUALITY(first.dgdP, exact.dgdP, 1e-15);
  const Friction again = coulomb(0.7, 2.0, 100.0, 0.1, &dual);  // (5) same sign: still exact
  TEST_EQUALITY(again.dgdu, 0.0);
  TEST_FLOATING_EQUALITY(again.dgdP, 0.1, 1e-14);  // ψ = 1: dg/dP = ν
  TEST_FLOATING_EQUALITY(dual.psi, 1.0, 1e-15);
}

TEUCHOS_UNIT_TEST(FrictionDual, SlipReversalGetsStiffness) {
  // u_t crosses zero between two iterates while slipping: the exact tangent has no
  // u_t-stiffness; the dual has f̂ (1 − ψ sign)/|u_t|, positive and at most 2 α_t.
  const double alpha = 100.0, nu = 0.1, P = 2.0, fHat = nu * P;
  FrictionDualPoint dual;
  coulomb(0.05, P, alpha, nu, &dual);                           // ψ = 1, slope (1 − 1)/|u| = 0
  const Friction reversed = coulomb(-0.01, P, alpha, nu, &dual);  // ψ = clip(1 + 0·du) = 1
  const Friction exact = coulomb(-0.01, P, alpha, nu, nullptr);
  TEST_FLOATING_EQUALITY(reversed.g, exact.g, 1e-15);  // (1) the value is the exact −f̂
  TEST_FLOATING_EQUALITY(reversed.g, -fHat, 1e-15);
  TEST_EQUALITY(exact.dgdu, 0.0);
  out << "dual slip stiffness " << reversed.dgdu << " (f̂ (1 − ψ sign)/|u_t| = " << fHat * 2.0 / 0.01
      << ", 2 α_t = " << 2 * alpha << ")\n";
  TEST_FLOATING_EQUALITY(reversed.dgdu, fHat * (1.0 - 1.0 * -1.0) / 0.01, 1e-14);
  TEST_COMPARE(reversed.dgdu, <=, 2.0 * alpha);
  TEST_FLOATING_EQUALITY(reversed.dgdP, nu * dual.psi, 1e-14);  // ψ_k df̂
  TEST_COMPARE(std::abs(dual.psi), <=, 1.0);                    // (4)
}

TEUCHOS_UNIT_TEST(FrictionDual, StickUnaffected) {
  const double alpha = 100.0, nu = 0.1, P = 2.0;
  FrictionDualPoint dual;
  coulomb(0.5, P, alpha, nu, &dual);  // slip first
  const Friction stick = coulomb(1e-3, P, alpha, nu, &dual);
  TEST_EQUALITY(int(stick.branch), int(flowform::FrictionBranch::Stick));
  TEST_FLOATING_EQUALITY(stick.dgdu, alpha, 1e-15);
  TEST_FLOATING_EQUALITY(stick.g, alpha * 1e-3, 1e-15);
  // The dual keeps to [−1, 1] through a long walk of large steps across both branches.
  double largest = 0.0;
  for (int k = 0; k < 50; ++k) {
    coulomb(0.3 * std::sin(1.3 * k) * (1 + k), P, alpha, nu, &dual);
    largest = std::max(largest, std::abs(dual.psi));
  }
  TEST_COMPARE(largest, <=, 1.0);
}

TEUCHOS_UNIT_TEST(FrictionDual, NoCompressionNoForce) {
  // P = 0: no friction (f̂ = 0), g = 0 with finite derivatives, the dual untouched or finite.
  FrictionDualPoint dual;
  const Friction f = coulomb(0.3, 0.0, 100.0, 0.1, &dual);
  TEST_EQUALITY(f.g, 0.0);
  TEST_ASSERT(std::isfinite(f.dgdu) && std::isfinite(f.dgdP));
}

TEUCHOS_UNIT_TEST(FrictionDual, ConvergesToExactAsStepVanishes) {
  // (3) for the slip dual: after a step du from a slipping u_t, ψ_{k+1} = ψ(u_k) + ψ'_k du
  // → ψ(u_{k+1}) as du → 0, so the tangent approaches the exact one.
  const double alpha = 100.0, nu = 0.1, P = 2.0;
  for (double du : {1e-1, 1e-3, 1e-5}) {
    FrictionDualPoint dual;
    coulomb(-0.5, P, alpha, nu, &dual);
    const Friction f = coulomb(-0.5 + du, P, alpha, nu, &dual);
    TEST_EQUALITY(f.dgdu, 0.0);  // same side of zero: exact
  }
  // From stick into slip: ψ_{k+1} = α u_k/f̂ + (α/f̂) du, clipped; the slip tangent is
  // f̂ (1 − ψ)/|u| ≥ 0 and vanishes when the linearized force reaches the bound.
  FrictionDualPoint dual;
  coulomb(1.9e-3, P, alpha, nu, &dual);  // stick, ψ = 0.95
  const Friction f = coulomb(2.5e-3, P, alpha, nu, &dual);
  TEST_EQUALITY(int(f.branch), int(flowform::FrictionBranch::Slip));
  TEST_FLOATING_EQUALITY(dual.psi, 1.0, 1e-15);  // 0.95 + (α/f̂) 6e-4 = 1.25, clipped at 1
  TEST_EQUALITY(f.dgdu, 0.0);
}

}  // namespace
