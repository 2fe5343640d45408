// The exact fully developed channel flow of the law σ̄ = σ0 + (e/γ)^(1/n) (no cutoff),
// derived in docs/verification.md. Channel |y| <= H, pressure p = p_in − G x.
//
//   σ_xy = −G y (equilibrium),  |σ_xy| = σ̄(e)/√3 where sheared,  e = |u'|/√3
//   ⇒ e = γ (√3 G|y| − σ0)^n  for |y| > y_p = σ0/(√3 G), rigid plug for |y| < y_p
//   u(y) = γ / (G (n+1)) [ (√3 G H − σ0)^(n+1) − (√3 G|y| − σ0)_+^(n+1) ]
//
// Axisymmetric pipe of radius H (y → r, flow along the axis): equilibrium of a core of
// radius r gives σ_rz = −G r / 2, so the same profile holds with G/2 in place of G in the
// shear law:  u(r) = 2γ / (G (n+1)) [ (√3 G H/2 − σ0)^(n+1) − (√3 G r/2 − σ0)_+^(n+1) ].
#pragma once

#include <algorithm>
#include <cmath>

namespace flowform::verification {

struct ChannelExact {
  double G = 1.0;       ///< pressure gradient magnitude: p = pIn − G x
  double pIn = 4.0;
  double H = 1.0;       ///< half-width
  double sigma0 = 0.0;
  double gamma = 1.0;
  double n = 1.0;
  bool axisymmetric = false;  ///< pipe: y is the radius, p = pIn − G z

  double velocity(double y) const {
    const double Gs = axisymmetric ? 0.5 * G : G;  // shear stress gradient
    const double s3G = std::sqrt(3.0) * Gs;
    const double wall = std::max(s3G * H - sigma0, 0.0);
    const double here = std::max(s3G * std::abs(y) - sigma0, 0.0);
    return gamma / (Gs * (n + 1.0)) * (std::pow(wall, n + 1.0) - std::pow(here, n + 1.0));
  }
  double pressure(double x) const { return pIn - G * x; }
  double plugHalfWidth() const { return sigma0 / (std::sqrt(3.0) * (axisymmetric ? 0.5 * G : G)); }
};

}  // namespace flowform::verification
