// The flow kernel's derivatives and invariances on single cells: its Sacado Jacobian
// (SFad<double, 9> and <double, 12>, dof i seeded as dx(i), as the assembler does) and its
// parameter derivatives against central finite differences; rigid motions give no residual
// (plane strain: translation + rotation; axisymmetric: translation along the axis), while a
// radial translation in axisymmetry does.
#include <Sacado.hpp>

#include "FlowKernelCell.hpp"

namespace {  // FlowKernelCell.hpp's, with its using-declarations

// ---------------------------------------------------------------------------------------
// (b) AD derivatives against central finite differences
// ---------------------------------------------------------------------------------------

// Cells away from the axis (x ≥ 0.9), so they serve both geometries; the quadrilateral is
// a general (non-parallelogram) one, so its Jacobian map varies over the cell.
const std::vector<XY> kTriangle = {{{1.1, 0.2}}, {{2.3, 0.4}}, {{1.5, 1.1}}};
const std::vector<XY> kQuad = {{{1.0, 0.0}}, {{2.1, 0.2}}, {{2.3, 1.3}}, {{0.9, 1.0}}};

/// Deterministic "random" dofs in [−1, 1] (portable, unlike <random>'s distributions).
std::vector<double> scrambledDofs(int n, double phase) {
  std::vector<double> d(n);
  for (int i = 0; i < n; ++i) d[i] = std::sin(12.9898 * (i + 1) + phase);
  return d;
}

/// Largest |J_AD − J_FD| over the cell matrix, relative to max |J_AD|. N = the dof count.
template <int N>
double jacobianFdError(const Cell& cell, const FlowKernelSettings& settings,
                       const MaterialParameters<double>& material, const std::vector<double>& x,
                       double delta, Teuchos::FancyOStream& out) {
  using Fad = Sacado::Fad::SFad<double, N>;
  std::vector<Fad> xf(N);
  for (int i = 0; i < N; ++i) xf[i] = Fad(N, i, x[i]);
  const auto rf = residual(cell, settings, material, xf);
  double scale = 0.0, err = 0.0;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) scale = std::max(scale, std::abs(rf[i].dx(j)));
  // The value part of the Fad evaluation is the double residual (same operations; 1e-14
  // of the scale allows for a different contraction of the arithmetic by the compiler).
  const auto r = residual(cell, settings, material, x);
  for (int i = 0; i < N; ++i)
    if (!(std::abs(rf[i].val() - r[i]) <= 1e-14 * maxAbs(r))) {
      out << "value of the Fad residual differs from the double residual at " << i << "\n";
      return 1.0;
    }
  for (int j = 0; j < N; ++j) {
    auto xp = x, xm = x;
    xp[j] += delta;
    xm[j] -= delta;
    const auto rp = residual(cell, settings, material, xp), rm = residual(cell, settings, material, xm);
    for (int i = 0; i < N; ++i) err = std::max(err, std::abs(rf[i].dx(j) - (rp[i] - rm[i]) / (2 * delta)));
  }
  out << "max |J_AD - J_FD| / max |J| = " << err / scale << " (max |J| = " << scale << ")\n";
  return err / scale;
}

// Central FD with δ = 1e-5 on dofs of size ≤ 1 in cells of size ~1: the truncation error
// is (δ²/6)|R'''|; with velocity gradients O(1) the strain rate e is O(1) ≫ e0 and each
// further derivative of μ(e) ∝ e^(1/n − 1) brings a factor O(1/e) = O(1), so |R'''| is
// within ~10²·max|J| and the truncation ≈ 2e-9 of max|J|. Round-off: eps·max|R|/δ ≈ 1e-11
// relative. Tolerance 1e-7 of max|J|: 50× above both, while an AD tangent missing one
// dependence (e.g. τ's dependence on μ_K(u), or μ's on D) errs by 1e-3..1 of max|J|.
constexpr double kFdDelta = 1e-5;
constexpr double kJacobianTol = 1e-7;

TEUCHOS_UNIT_TEST(FlowKernel, JacobianMatchesFiniteDifferences) {
  for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
    const auto settings = makeSettings(geometry, 0.1, 0.3, -0.7);
    out << (geometry == Geometry::PlaneStrain ? "plane strain" : "axisymmetric") << "\n";
    for (double phase : {0.0, 1.3}) {
      const Cell tri(CellType::Triangle3, kTriangle, geometry);
      TEST_COMPARE(jacobianFdError<9>(tri, settings, kNonlinear, scrambledDofs(9, phase), kFdDelta, out),
                   <=, kJacobianTol);
      const Cell quad(CellType::Quadrilateral4, kQuad, geometry);
      TEST_COMPARE(jacobianFdError<12>(quad, settings, kNonlinear, scrambledDofs(12, phase), kFdDelta, out),
                   <=, kJacobianTol);
    }
  }
}

TEUCHOS_UNIT_TEST(FlowKernel, JacobianNearRigidZoneMatchesFiniteDifferences) {
  // Velocity gradients ~1e-3 (e ~ 1e-3, below e0 = 1e-2): the regularized branch. μ varies
  // there on the scale of velocities ~e0·h, so the FD step is scaled down with the dofs
  // (δ = 1e-5 × 1e-3) and the truncation argument above holds in the scaled variables.
  for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
    const auto settings = makeSettings(geometry, 0.1, 0.3, -0.7);
    auto x9 = scrambledDofs(9, 0.4), x12 = scrambledDofs(12, 0.4);
    for (int i = 0; i < 9; ++i) if (i % 3 != 2) x9[i] *= 1e-3;
    for (int i = 0; i < 12; ++i) if (i % 3 != 2) x12[i] *= 1e-3;
    const Cell tri(CellType::Triangle3, kTriangle, geometry);
    const Cell quad(CellType::Quadrilateral4, kQuad, geometry);
    // The regime is the intended one: e = sqrt(2/3 D:D) < e0 at the centroids.
    for (const auto* c : {&tri, &quad}) {
      const auto d = flowform::strainRateAt(c->centroid, 0, geometry, (c == &tri ? x9 : x12).data());
      TEST_COMPARE(std::sqrt(2.0 / 3.0 * d.ddot()), <, kNonlinear.cutoff);
    }
    TEST_COMPARE(jacobianFdError<9>(tri, settings, kNonlinear, x9, 1e-8, out), <=, kJacobianTol);
    TEST_COMPARE(jacobianFdError<12>(quad, settings, kNonlinear, x12, 1e-8, out), <=, kJacobianTol);
  }
}

TEUCHOS_UNIT_TEST(FlowKernel, ParameterDerivativesMatchFiniteDifferences) {
  // ∂R/∂h for h = σ0, γ, n, e0 (docs/theory.md §4): parameters seeded, dofs constant of the same
  // Fad type. Steps as in MaterialTest: 1e-5 of the scale on which R varies with h (the
  // parameter itself; e_r for e0, which enters only through e_r² = 2/3 D:D + e0²).
  // Truncation ≤ 1e-9, round-off ≤ eps·|R|/(δ |∂R/∂h|) ≈ 1e-8 for the weakest (e0).
  // Compared relative to max_i |∂R_i/∂h| at 1e-6.
  using PFad = Sacado::Fad::SFad<double, 4>;
  const double values[4] = {kNonlinear.values[0], kNonlinear.values[1], kNonlinear.values[2],  // σ0, γ, n
                            kNonlinear.cutoff};
  for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric})
    for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
      const Cell cell(type, type == CellType::Triangle3 ? kTriangle : kQuad, geometry);
      const auto settings = makeSettings(geometry, 0.1, 0.3, -0.7);
      const auto x = scrambledDofs(cell.numDofs(), 0.7);
      std::vector<PFad> xf(x.begin(), x.end());
      const MaterialParameters<PFad> mf = flowform::powerLaw(PFad(4, 0, values[0]), PFad(4, 1, values[1]),
                                                             PFad(4, 2, values[2]), PFad(4, 3, values[3]));
      const auto rf = residual(cell, settings, mf, xf);
      // e_r scale for the e0 step: the largest over the cell's points is ~|grad u| ~ 1.
      const double steps[4] = {1e-5 * values[0], 1e-5 * values[1], 1e-5 * values[2], 1e-5};
      for (int k = 0; k < 4; ++k) {
        MaterialParameters<double> mp = kNonlinear, mm = kNonlinear;
        double* vp[4] = {&mp.values[0], &mp.values[1], &mp.values[2], &mp.cutoff};
        double* vm[4] = {&mm.values[0], &mm.values[1], &mm.values[2], &mm.cutoff};
        *vp[k] += steps[k];
        *vm[k] -= steps[k];
        const auto rp = residual(cell, settings, mp, x), rm = residual(cell, settings, mm, x);
        double scale = 0.0, err = 0.0;
        for (int i = 0; i < cell.numDofs(); ++i) scale = std::max(scale, std::abs(rf[i].dx(k)));
        for (int i = 0; i < cell.numDofs(); ++i)
          err = std::max(err, std::abs(rf[i].dx(k) - (rp[i] - rm[i]) / (2 * steps[k])));
        out << "parameter " << k << ": max |dR/dh| " << scale << ", rel. FD error " << err / scale << "\n";
        TEST_COMPARE(scale, >, 0.0);
        TEST_COMPARE(err, <=, 1e-6 * scale);
      }
    }
}

// ---------------------------------------------------------------------------------------
// (c), (d) Rigid motions
// ---------------------------------------------------------------------------------------

/// max |R| over the cell for the nodal velocity field `u(x, y)`, p = 0, f = 0, relative
/// to the size S the momentum residual would have if round-off did not cancel in D:
/// S = max_a ∫|grad N_a| · 2 μ(e0) · max_a|grad N_a| · max|u|. D is a sum of terms
/// grad N_a u_a of size |grad N|·|u| that cancel for a rigid motion; μ(e0) is the largest
/// viscosity (μ decreases with e).
template <class Field>
double rigidResidual(const Cell& cell, Geometry geometry, Field u) {
  std::vector<double> dofs;
  double uMax = 0.0, rMax = 0.0;
  for (const auto& x : cell.xy) {
    rMax = std::max(rMax, x[0]);
    const auto v = u(x[0], x[1]);
    dofs.insert(dofs.end(), {v[0], v[1], 0.0});
    uMax = std::max({uMax, std::abs(v[0]), std::abs(v[1])});
  }
  const auto r = residual(cell, makeSettings(geometry, 0.1, 0.0, 0.0), kNonlinear, dofs);
  double gradN = 0.0;
  for (int q = 0; q < cell.rule.numPoints; ++q)
    for (size_t a = 0; a < cell.xy.size(); ++a)
      gradN = std::max(gradN, std::hypot(cell.rule.dNdx[q][a], cell.rule.dNdy[q][a]));
  const double measure = geometry == Geometry::Axisymmetric ? 2 * M_PI * rMax * cell.rule.area : cell.rule.area;
  const double S = measure * gradN * 2 * handViscosity(0.0, kNonlinear) * gradN * uMax;
  return maxAbs(r) / S;
}

// Round-off only: each strain-rate component is a sum of ≤ 8 terms of size |grad N||u|,
// so D ≈ 8 eps |grad N||u| and the residual ≈ 1e-15 S; 1e-13 leaves a 100× margin. A
// non-rigid field of the same size (checked below) gives O(1e-3..1) S.
constexpr double kRigidTol = 1e-13;

TEUCHOS_UNIT_TEST(FlowKernel, PlaneStrainRigidMotionHasNoResidual) {
  const double a = 0.7, b = -1.1, w = 0.9;
  auto rigid = [&](double x, double y) { return std::array<double, 2>{a - w * y, b + w * x}; };
  // Negative control: the same field with 1 % more spin in u_y is a (small) shear.
  auto sheared = [&](double x, double y) { return std::array<double, 2>{a - w * y, b + 1.01 * w * x}; };
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    const Cell cell(type, type == CellType::Triangle3 ? kTriangle : kQuad, Geometry::PlaneStrain);
    const double rel = rigidResidual(cell, Geometry::PlaneStrain, rigid);
    out << flowform::cellTypeName(type) << ": rigid motion max|R|/S = " << rel << "\n";
    TEST_COMPARE(rel, <=, kRigidTol);
    TEST_COMPARE(rigidResidual(cell, Geometry::PlaneStrain, sheared), >, 1e-6);
  }
}

TEUCHOS_UNIT_TEST(FlowKernel, AxisymmetricAxialTranslationHasNoResidual) {
  // u = (0, c) is the only rigid motion of an axisymmetric body; u = (c, 0) is not one
  // (D_θθ = c/r: a radial expansion) and must give a residual.
  const double c = -1.3;
  auto axial = [&](double, double) { return std::array<double, 2>{0.0, c}; };
  auto radial = [&](double, double) { return std::array<double, 2>{c, 0.0}; };
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    const Cell cell(type, type == CellType::Triangle3 ? kTriangle : kQuad, Geometry::Axisymmetric);
    const double rel = rigidResidual(cell, Geometry::Axisymmetric, axial);
    out << flowform::cellTypeName(type) << ": axial translation max|R|/S = " << rel << "\n";
    TEST_COMPARE(rel, <=, kRigidTol);
    TEST_COMPARE(rigidResidual(cell, Geometry::Axisymmetric, radial), >, 1e-6);
  }
}

}  // namespace
