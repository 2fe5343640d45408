// The stress–velocity (primal–dual) Newton linearization of the viscoplastic law
// (docs/theory.md §9; Rudi, Shih & Stadler, "Advanced Newton methods for geodynamical models
// of Stokes flow with viscoplastic rheologies", Geochem. Geophys. Geosyst. 2020).
//
// The deviatoric stress is s = 2 μ(e_r) D. Its exact derivative is
//
//     ds = 2μ [ dD + β τ (g : dD) ],   g = ∂e_r/∂D = (2/3) D / e_r,   β = μ'(e_r) e_r / μ,
//
// with τ = D / e_r. For a nearly rigid-plastic law β → −1, and along D the tangent
// 2μ (1 + β e²/e_r²) is almost zero: the exact Newton step overshoots wherever the direction
// of D is still wrong, and Newton needs tens of damped steps per continuation stage.
//
// The dual method makes τ an unknown of its own, τ e_r(D) = D, linearizes the pair (u, τ)
// and eliminates dτ point by point. The velocity step solves the same residual with the
// tangent above, τ taken from the dual iterate τ_k instead of D/e_r; after the step,
//
//     τ_{k+1} = D_k / e_k + ( dD − τ_k (g_k : dD) ) / e_k,      dD = D(x_{k+1}) − D(x_k),
//
// scaled back to |τ| = sqrt(2/3 τ:τ) ≤ 1 (the bound of D/e_r, which keeps 1 + β g:τ ≥ 0).
// At convergence dD → 0 and τ → D/e_r: the tangent is the exact one again, so Newton still
// converges quadratically at the end and the converged state is the same. Only the Jacobian
// changes; residuals, responses and sensitivities never use τ.
#pragma once

#include <cmath>
#include <vector>

#include "flowform/discretization/ShapeFunctions.hpp"

namespace flowform {

/// The dual state at one quadrature point: τ and the D, e_r of the iterate it was built at.
struct StressDualPoint {
  double tau[4] = {0.0, 0.0, 0.0, 0.0};  ///< xx, yy, xy, θθ
  double strainRate[4] = {0.0, 0.0, 0.0, 0.0};
  double regularizedRate = 0.0;
  bool set = false;

  /// D:D with the tensor's off-diagonal counted twice (as StrainRate::ddot).
  static double contract(const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + 2.0 * a[2] * b[2] + a[3] * b[3];
  }

  /// Moves the dual to the iterate with strain rate D and e_r (the formula above); the
  /// first call sets τ = D / e_r, the exact linearization.
  void update(const double* D, double eReg) {
    if (set) {
      double dD[4];
      for (int i = 0; i < 4; ++i) dD[i] = D[i] - strainRate[i];
      const double gdD = (2.0 / 3.0) * contract(strainRate, dD) / regularizedRate;  // g_k : dD
      for (int i = 0; i < 4; ++i)
        tau[i] = (strainRate[i] + dD[i] - tau[i] * gdD) / regularizedRate;
      const double norm = std::sqrt((2.0 / 3.0) * contract(tau, tau));
      if (norm > 1.0)
        for (double& t : tau) t /= norm;
    } else {
      for (int i = 0; i < 4; ++i) tau[i] = D[i] / eReg;
    }
    for (int i = 0; i < 4; ++i) strainRate[i] = D[i];
    regularizedRate = eReg;
    set = true;
  }
};

/// The dual over this rank's cells (kMaxQuadraturePoints per cell), kept by the model
/// across the Newton iterations of one solve and cleared when a solve starts.
class StressDual {
 public:
  void clear() { m_points.clear(); }
  /// The points of cell k (allocated on first use for `numCells` cells).
  StressDualPoint* cell(size_t k, size_t numCells) {
    if (m_points.size() != numCells * kMaxQuadraturePoints) m_points.assign(numCells * kMaxQuadraturePoints, {});
    return m_points.data() + k * kMaxQuadraturePoints;
  }

 private:
  std::vector<StressDualPoint> m_points;
};

}  // namespace flowform
