// The element residual of the stabilized flow (physics/FlowResidual.hpp) on single cells,
// against closed-form integrals written out here for fields whose integrands the kernel's
// quadrature integrates exactly (P1 and Q1, plane strain and axisymmetric). Its derivatives
// and rigid motions: FlowKernelDerivativeTest.cpp.
//
//   R_u[a] = ∫ ( s : D(N_a e_i) − p div(N_a e_i) − N_a f_i ) dΩ,   s = 2 μ D(u)
//   R_p[a] = ∫ ( − N_a div u − τ grad N_a · (grad p − f) ) dΩ,   τ = β h² / (2 μ_K)
#include "FlowKernelCell.hpp"

namespace {  // FlowKernelCell.hpp's, with its using-declarations

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

}  // namespace
