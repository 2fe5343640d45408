// The element residual of the stabilized flow (kernels/FlowResidual.hpp) on single cells:
//  - against closed-form integrals written out here for fields whose integrands the
//    kernel's quadrature integrates exactly (P1 and Q1, plane strain and axisymmetric);
//  - its Sacado Jacobian (SFad<double, 9> and <double, 12>, dof i seeded as dx(i), as the
//    assembler does) and its parameter derivatives against central finite differences;
//  - rigid motions give no residual (plane strain: translation + rotation; axisymmetric:
//    translation along the axis), while a radial translation in axisymmetry does.
//
//   R_u[a] = ∫ ( s : D(N_a e_i) − p div(N_a e_i) − N_a f_i ) dΩ,   s = 2 μ D(u)
//   R_p[a] = ∫ ( − N_a div u − τ grad N_a · (grad p − f) ) dΩ,   τ = β h² / (2 μ_K)
#include <Sacado.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flowform/physics/Material.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/discretization/ShapeFunctions.hpp"

namespace {

using flowform::CellQuadrature;
using flowform::CellType;
using flowform::FlowKernelSettings;
using flowform::Geometry;
constexpr int kDofsPerNode = flowform::EqualOrderLayout::kFieldsPerNode;  // the equal-order element layout
using flowform::MaterialParameters;

using XY = std::array<double, 2>;

const MaterialParameters<double> kNewtonian{0.0, 1.0, 1.0, 1e-3};  // μ = 1/(3γ) = 1/3
const MaterialParameters<double> kNonlinear{0.5, 1.0, 5.0, 1e-2};  // σ0, γ, n, e0

/// One cell with its quadrature, as the assembler sets it up: the centroid rule for P1 in
/// plane strain (constant integrands), the 3-point / 2×2 rule otherwise.
struct Cell {
  CellType type;
  std::vector<XY> xy;
  CellQuadrature rule, centroid;
  double h = 0.0;

  Cell(CellType t, std::vector<XY> nodes, Geometry geometry, int order = 0) : type(t), xy(std::move(nodes)) {
    if (order == 0) order = (type == CellType::Triangle3 && geometry == Geometry::PlaneStrain) ? 1 : 2;
    const bool ok = flowform::computeCellQuadrature(type, xy.data(), order, rule) &&
                    flowform::computeCellQuadrature(type, xy.data(), 1, centroid);
    if (!ok) throw std::logic_error("test cell is inverted");
    h = flowform::cellDiameter(type, xy.data());
  }
  int numDofs() const { return kDofsPerNode * static_cast<int>(xy.size()); }
};

template <typename Scalar, typename PScalar>
std::vector<Scalar> residual(const Cell& cell, const FlowKernelSettings& settings,
                             const MaterialParameters<PScalar>& material, const std::vector<Scalar>& dofs) {
  std::vector<Scalar> r(cell.numDofs(), Scalar(0.0));
  flowform::addFlowResidual(cell.rule, cell.centroid, cell.h, settings, material, dofs.data(), r.data());
  return r;
}

FlowKernelSettings makeSettings(Geometry geometry, double beta, double fx, double fy) {
  FlowKernelSettings s;
  s.geometry = geometry;
  s.beta = beta;
  s.bodyForce[0] = fx;
  s.bodyForce[1] = fy;
  return s;
}

/// μ(D:D) written out with pow (independent of Material.hpp's exp∘log form).
double handViscosity(double ddot, const MaterialParameters<double>& m) {
  const double er = std::sqrt(2.0 / 3.0 * ddot + m.cutoff * m.cutoff);
  return (m.yieldStress + std::pow(er / m.rateConstant, 1.0 / m.rateExponent)) / (3.0 * er);
}

double maxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// Every entry of `lib` equals `hand` to `tol` × max|hand| (entries may be near zero, so
/// the comparison is relative to the vector's scale, not entry by entry).
bool sameVector(const std::vector<double>& lib, const std::vector<double>& hand, double tol,
                Teuchos::FancyOStream& out) {
  const double scale = maxAbs(hand);
  bool ok = lib.size() == hand.size();
  for (size_t i = 0; ok && i < hand.size(); ++i) {
    const double err = std::abs(lib[i] - hand[i]);
    if (!(err <= tol * scale)) {
      out << "entry " << i << ": kernel " << lib[i] << ", hand " << hand[i] << ", |diff| " << err
          << " > " << tol << " * " << scale << "\n";
      ok = false;
    }
  }
  return ok;
}

// Hand values are the same integrals evaluated in a different order: entries are sums of
// ≤ 10 products of O(1) numbers, so both sides carry ~10 eps ≈ 2e-15 of the vector's scale
// (exp∘log vs pow in μ adds a few ulps). 1e-13 leaves a 50× margin; a wrong sign or factor
// in any term (e.g. forgetting 1/r, 2π, h², or using p at a node instead of the mean) moves
// entries by O(1e-2..1) of the scale.
constexpr double kHandTol = 1e-13;

// ---------------------------------------------------------------------------------------
// (a) Hand computations
// ---------------------------------------------------------------------------------------

TEUCHOS_UNIT_TEST(FlowKernel, TriangleP1PlaneStrainByHand) {
  const std::vector<XY> X = {{{0.1, 0.2}}, {{1.3, 0.4}}, {{0.5, 1.1}}};
  const double ux[3] = {0.3, -0.2, 0.7}, uy[3] = {-0.4, 0.1, 0.5}, p[3] = {1.2, -0.3, 0.4};
  const double beta = 0.1, fx = 0.3, fy = -0.7;
  std::vector<double> dofs;
  for (int a = 0; a < 3; ++a) dofs.insert(dofs.end(), {ux[a], uy[a], p[a]});

  // Constant-gradient triangle: 2A = (x1−x0)(y2−y0) − (x2−x0)(y1−y0),
  // grad N_a = (y_b − y_c, x_c − x_b) / (2A) with (a, b, c) cyclic.
  const double twoA = (X[1][0] - X[0][0]) * (X[2][1] - X[0][1]) - (X[2][0] - X[0][0]) * (X[1][1] - X[0][1]);
  const double A = 0.5 * twoA;
  double gx[3], gy[3];
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    gx[a] = (X[b][1] - X[c][1]) / twoA;
    gy[a] = (X[c][0] - X[b][0]) / twoA;
  }
  double dux[2] = {0, 0}, duy[2] = {0, 0}, dp[2] = {0, 0}, pMean = 0;
  for (int a = 0; a < 3; ++a) {
    dux[0] += gx[a] * ux[a]; dux[1] += gy[a] * ux[a];
    duy[0] += gx[a] * uy[a]; duy[1] += gy[a] * uy[a];
    dp[0] += gx[a] * p[a]; dp[1] += gy[a] * p[a];
    pMean += p[a] / 3.0;
  }
  const double Dxx = dux[0], Dyy = duy[1], Dxy = 0.5 * (dux[1] + duy[0]);
  const double divU = Dxx + Dyy;
  const double h = std::max({std::hypot(X[1][0] - X[0][0], X[1][1] - X[0][1]),
                             std::hypot(X[2][0] - X[1][0], X[2][1] - X[1][1]),
                             std::hypot(X[0][0] - X[2][0], X[0][1] - X[2][1])});

  for (const auto& material : {kNewtonian, kNonlinear}) {
    const double mu = handViscosity(Dxx * Dxx + Dyy * Dyy + 2 * Dxy * Dxy, material);
    if (flowform::isNewtonian(material)) TEST_FLOATING_EQUALITY(mu, 1.0 / 3.0, 1e-15);
    const double sxx = 2 * mu * Dxx, syy = 2 * mu * Dyy, sxy = 2 * mu * Dxy;
    const double tau = beta * h * h / (2 * mu);
    std::vector<double> hand(9);
    for (int a = 0; a < 3; ++a) {
      // R_u[a] = A (s·grad N_a) − A p̄ grad N_a − (A/3) f;  ∫ N_a = A/3, ∫ p = A p̄
      hand[3 * a + 0] = A * (sxx * gx[a] + sxy * gy[a]) - A * pMean * gx[a] - A / 3 * fx;
      hand[3 * a + 1] = A * (sxy * gx[a] + syy * gy[a]) - A * pMean * gy[a] - A / 3 * fy;
      // R_p[a] = −(A/3) div u − τ A grad N_a · (grad p − f)
      hand[3 * a + 2] = -A / 3 * divU - tau * A * (gx[a] * (dp[0] - fx) + gy[a] * (dp[1] - fy));
    }
    // The centroid rule (what the assembler uses) and the 3-point rule are both exact here.
    for (int order : {1, 2}) {
      const Cell cell(CellType::Triangle3, X, Geometry::PlaneStrain, order);
      TEST_FLOATING_EQUALITY(cell.rule.area, A, kHandTol);
      TEST_FLOATING_EQUALITY(cell.h, h, kHandTol);
      const auto lib = residual(cell, makeSettings(Geometry::PlaneStrain, beta, fx, fy), material, dofs);
      TEST_ASSERT(sameVector(lib, hand, kHandTol, out));
    }
  }
}

TEUCHOS_UNIT_TEST(FlowKernel, TriangleP1AxisymmetricByHand) {
  // Away from the axis. Field u_r = a r, u_z = −c z + b r + e, p = p0: D is constant
  // (D_rr = a, D_zz = −c, D_rz = b/2, D_θθ = u_r/r = a) and every integrand times r is at
  // most quadratic, which the 3-point rule integrates exactly:
  //   ∫ r dA = A r̄,   ∫ N_a r dA = A (3 r̄ + r_a) / 12,   ∫ N_a dA = A/3.
  const std::vector<XY> X = {{{1.1, 0.2}}, {{2.3, 0.4}}, {{1.5, 1.1}}};
  const double ca = 0.4, cb = -0.6, cc = 0.5, ce = 0.2, p0 = 0.7;
  const double beta = 0.1, fx = 0.3, fy = -0.7;
  std::vector<double> dofs;
  for (int a = 0; a < 3; ++a) dofs.insert(dofs.end(), {ca * X[a][0], -cc * X[a][1] + cb * X[a][0] + ce, p0});

  const double twoA = (X[1][0] - X[0][0]) * (X[2][1] - X[0][1]) - (X[2][0] - X[0][0]) * (X[1][1] - X[0][1]);
  const double A = 0.5 * twoA;
  const double rBar = (X[0][0] + X[1][0] + X[2][0]) / 3;
  double gx[3], gy[3];
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    gx[a] = (X[b][1] - X[c][1]) / twoA;
    gy[a] = (X[c][0] - X[b][0]) / twoA;
  }
  const double Drr = ca, Dzz = -cc, Drz = 0.5 * cb, Dtt = ca;
  const double divU = Drr + Dzz + Dtt;
  const double h = std::max({std::hypot(X[1][0] - X[0][0], X[1][1] - X[0][1]),
                             std::hypot(X[2][0] - X[1][0], X[2][1] - X[1][1]),
                             std::hypot(X[0][0] - X[2][0], X[0][1] - X[2][1])});
  const double twoPi = 2 * M_PI;

  for (const auto& material : {kNewtonian, kNonlinear}) {
    const double mu = handViscosity(Drr * Drr + Dzz * Dzz + 2 * Drz * Drz + Dtt * Dtt, material);
    const double srr = 2 * mu * Drr, szz = 2 * mu * Dzz, srz = 2 * mu * Drz, stt = 2 * mu * Dtt;
    const double tau = beta * h * h / (2 * mu);
    std::vector<double> hand(9);
    for (int a = 0; a < 3; ++a) {
      const double NrA = A * (3 * rBar + X[a][0]) / 12;  // ∫ N_a r dA
      // 2π ∫ [ s_rr N_r r + s_rz N_z r + s_θθ N − p (N_r r + N) − N f_r r ] dA
      hand[3 * a + 0] = twoPi * ((srr - p0) * gx[a] * A * rBar + srz * gy[a] * A * rBar +
                                 (stt - p0) * A / 3 - fx * NrA);
      // 2π ∫ [ s_rz N_r r + s_zz N_z r − p N_z r − N f_z r ] dA
      hand[3 * a + 1] = twoPi * ((srz * gx[a] + (szz - p0) * gy[a]) * A * rBar - fy * NrA);
      // 2π ∫ [ −N div u r − τ grad N · (0 − f) r ] dA
      hand[3 * a + 2] = twoPi * (-divU * NrA - tau * A * rBar * (gx[a] * (0 - fx) + gy[a] * (0 - fy)));
    }
    const Cell cell(CellType::Triangle3, X, Geometry::Axisymmetric);
    const auto lib = residual(cell, makeSettings(Geometry::Axisymmetric, beta, fx, fy), material, dofs);
    TEST_ASSERT(sameVector(lib, hand, kHandTol, out));
  }
}

/// Rectangle [x0, x0+Lx] × [y0, y0+Ly], nodes counter-clockwise from (x0, y0): node a is
/// at reference corner (sx_a, sy_a) and N_a = ¼(1 + sx_a ξ)(1 + sy_a η).
struct Rectangle {
  double x0, y0, Lx, Ly;
  static constexpr double sx[4] = {-1, 1, 1, -1};
  static constexpr double sy[4] = {-1, -1, 1, 1};
  std::vector<XY> nodes() const {
    std::vector<XY> X(4);
    for (int a = 0; a < 4; ++a) X[a] = {x0 + 0.5 * Lx * (1 + sx[a]), y0 + 0.5 * Ly * (1 + sy[a])};
    return X;
  }
  double xc() const { return x0 + 0.5 * Lx; }
  double yc() const { return y0 + 0.5 * Ly; }
};

TEUCHOS_UNIT_TEST(FlowKernel, RectangleQ1PlaneStrainByHand) {
  // Linear u and p (exactly in Q1), so D and μ are constant. With x = xc + ξ Lx/2,
  // y = yc + η Ly/2 and dA = Lx Ly/4 dξ dη:
  //   ∫ ∂N_a/∂x = sx_a Ly/2,   ∫ ∂N_a/∂y = sy_a Lx/2,   ∫ N_a = Lx Ly/4,
  //   ∫ p ∂N_a/∂x = sx_a Ly/2 (p_c + p_y Ly sy_a/6),  ∫ p ∂N_a/∂y = sy_a Lx/2 (p_c + p_x Lx sx_a/6)
  // (p_c at the centre), all exact for 2×2 Gauss (degree ≤ 2 per direction).
  const Rectangle R{0.3, -0.2, 1.5, 0.8};
  const auto X = R.nodes();
  const double u0 = 0.1, uxx = 0.4, uxy = -0.7, v0 = -0.3, uyx = 0.25, uyy = 0.15;  // not div-free
  const double p0 = 0.6, px = -0.8, py = 0.35;
  const double beta = 0.1, fx = 0.3, fy = -0.7;
  std::vector<double> dofs;
  for (const auto& x : X)
    dofs.insert(dofs.end(), {u0 + uxx * x[0] + uxy * x[1], v0 + uyx * x[0] + uyy * x[1], p0 + px * x[0] + py * x[1]});

  const double Dxx = uxx, Dyy = uyy, Dxy = 0.5 * (uxy + uyx), divU = Dxx + Dyy;
  const double pc = p0 + px * R.xc() + py * R.yc();
  const double A = R.Lx * R.Ly, h = std::hypot(R.Lx, R.Ly);
  for (const auto& material : {kNewtonian, kNonlinear}) {
    const double mu = handViscosity(Dxx * Dxx + Dyy * Dyy + 2 * Dxy * Dxy, material);
    const double sxx = 2 * mu * Dxx, syy = 2 * mu * Dyy, sxy = 2 * mu * Dxy;
    const double tau = beta * h * h / (2 * mu);
    std::vector<double> hand(12);
    for (int a = 0; a < 4; ++a) {
      const double Ix = R.sx[a] * R.Ly / 2, Iy = R.sy[a] * R.Lx / 2;  // ∫ grad N_a
      const double pIx = Ix * (pc + py * R.Ly * R.sy[a] / 6), pIy = Iy * (pc + px * R.Lx * R.sx[a] / 6);
      hand[3 * a + 0] = sxx * Ix + sxy * Iy - pIx - fx * A / 4;
      hand[3 * a + 1] = sxy * Ix + syy * Iy - pIy - fy * A / 4;
      hand[3 * a + 2] = -divU * A / 4 - tau * ((px - fx) * Ix + (py - fy) * Iy);
    }
    const Cell cell(CellType::Quadrilateral4, X, Geometry::PlaneStrain);
    TEST_FLOATING_EQUALITY(cell.h, h, kHandTol);
    const auto lib = residual(cell, makeSettings(Geometry::PlaneStrain, beta, fx, fy), material, dofs);
    TEST_ASSERT(sameVector(lib, hand, kHandTol, out));
  }
}

TEUCHOS_UNIT_TEST(FlowKernel, RectangleQ1AxisymmetricByHand) {
  // The axisymmetric field of the P1 test (constant D), p = p0. With r = xc + ξ Lx/2:
  //   I_r(a) = ∫ r ∂N_a/∂r = sx_a Ly xc/2,   I_z(a) = ∫ r ∂N_a/∂z = sy_a Lx/2 (xc + sx_a Lx/6),
  //   J(a) = ∫ N_a r = (Lx Ly/4)(xc + sx_a Lx/6),   ∫ N_a = Lx Ly/4 — exact for 2×2 Gauss.
  const Rectangle R{1.1, -0.2, 1.5, 0.8};
  const auto X = R.nodes();
  const double ca = 0.4, cb = -0.6, cc = 0.5, ce = 0.2, p0 = 0.7;
  const double beta = 0.1, fx = 0.3, fy = -0.7;
  std::vector<double> dofs;
  for (const auto& x : X) dofs.insert(dofs.end(), {ca * x[0], -cc * x[1] + cb * x[0] + ce, p0});

  const double Drr = ca, Dzz = -cc, Drz = 0.5 * cb, Dtt = ca, divU = Drr + Dzz + Dtt;
  const double A = R.Lx * R.Ly, h = std::hypot(R.Lx, R.Ly), xc = R.xc(), twoPi = 2 * M_PI;
  for (const auto& material : {kNewtonian, kNonlinear}) {
    const double mu = handViscosity(Drr * Drr + Dzz * Dzz + 2 * Drz * Drz + Dtt * Dtt, material);
    const double srr = 2 * mu * Drr, szz = 2 * mu * Dzz, srz = 2 * mu * Drz, stt = 2 * mu * Dtt;
    const double tau = beta * h * h / (2 * mu);
    std::vector<double> hand(12);
    for (int a = 0; a < 4; ++a) {
      const double Ir = R.sx[a] * R.Ly * xc / 2, Iz = R.sy[a] * R.Lx / 2 * (xc + R.sx[a] * R.Lx / 6);
      const double J = A / 4 * (xc + R.sx[a] * R.Lx / 6);
      hand[3 * a + 0] = twoPi * ((srr - p0) * Ir + srz * Iz + (stt - p0) * A / 4 - fx * J);
      hand[3 * a + 1] = twoPi * (srz * Ir + (szz - p0) * Iz - fy * J);
      hand[3 * a + 2] = twoPi * (-divU * J - tau * ((0 - fx) * Ir + (0 - fy) * Iz));
    }
    const Cell cell(CellType::Quadrilateral4, X, Geometry::Axisymmetric);
    const auto lib = residual(cell, makeSettings(Geometry::Axisymmetric, beta, fx, fy), material, dofs);
    TEST_ASSERT(sameVector(lib, hand, kHandTol, out));
  }
}

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
  const double values[4] = {kNonlinear.yieldStress, kNonlinear.rateConstant, kNonlinear.rateExponent,
                            kNonlinear.cutoff};
  for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric})
    for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
      const Cell cell(type, type == CellType::Triangle3 ? kTriangle : kQuad, geometry);
      const auto settings = makeSettings(geometry, 0.1, 0.3, -0.7);
      const auto x = scrambledDofs(cell.numDofs(), 0.7);
      std::vector<PFad> xf(x.begin(), x.end());
      const MaterialParameters<PFad> mf{PFad(4, 0, values[0]), PFad(4, 1, values[1]), PFad(4, 2, values[2]),
                                        PFad(4, 3, values[3])};
      const auto rf = residual(cell, settings, mf, xf);
      // e_r scale for the e0 step: the largest over the cell's points is ~|grad u| ~ 1.
      const double steps[4] = {1e-5 * values[0], 1e-5 * values[1], 1e-5 * values[2], 1e-5};
      for (int k = 0; k < 4; ++k) {
        MaterialParameters<double> mp = kNonlinear, mm = kNonlinear;
        double* vp[4] = {&mp.yieldStress, &mp.rateConstant, &mp.rateExponent, &mp.cutoff};
        double* vm[4] = {&mm.yieldStress, &mm.rateConstant, &mm.rateExponent, &mm.cutoff};
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
