// The dual (normalized friction force) linearization of the sticking rule, the friction
// counterpart of physics/StressDual.hpp (docs/theory.md §9; the primal–dual treatment of the
// slip direction of Hüeber, Stadler & Wohlmuth, SIAM J. Sci. Comput. 2008).
//
// The bounded laws give g = f̂ ψ with ψ = α_t u_t / f̂ in stick (|ψ| ≤ 1) and ψ = sign(u_t) in
// slip. In slip the exact derivative ∂g/∂u_t is 0: the Newton model does not see the force
// reverse when u_t crosses zero, so near-rigid zones along a wall (the dead metal at the die
// corner, where u_t ~ 1e-4) flip between +f̂ and −f̂ from one iterate to the next and the line
// search crawls. With ψ an unknown of its own, ψ |u_t| = u_t, linearized and eliminated,
//
//     dg = ψ_k df̂ + f̂ (1 − ψ_k sign(u_t)) / |u_t| du_t        (slip),
//
// which is the exact derivative when ψ_k = sign(u_t) and a stiffness of at most 2 f̂/|u_t|
// < 2 α_t (slip means α_t |u_t| > f̂) when the dual disagrees. After the step the dual is
// its linearized value, clipped to [−1, 1]:
//
//     ψ_{k+1} = clip( ψ(u_k) + ψ'_k (u_{k+1} − u_k) ),   ψ'_k = α_t / f̂ (stick), (1 − ψ_k sign u_k)/|u_k| (slip).
//
// At convergence the step vanishes, ψ → ψ(u), and the tangent is the exact one: the values
// and the converged state do not change, only the Newton path.
#pragma once

#include <algorithm>
#include <cmath>

namespace flowform {

/// The dual at one wall node, kept across the iterations of one Newton solve.
struct FrictionDualPoint {
  double psi = 0.0;       ///< ψ_k, the dual used by this iterate's tangent
  double psiExact = 0.0;  ///< ψ(u_k) of the last iterate
  double slope = 0.0;     ///< ψ'_k of the last iterate
  double ut = 0.0;        ///< u_t of the last iterate
  bool set = false;

  /// Moves the dual to the iterate with tangential velocity `ut`, bound `fHat`, sticking
  /// stiffness `alpha` on branch `stick`, and returns ψ_k. The first call is exact.
  double update(double ut, double fHat, double alpha, bool stick) {
    const double sign = ut >= 0.0 ? 1.0 : -1.0;
    const double exact = fHat > 0.0 && stick ? alpha * ut / fHat : sign;
    psi = set ? std::clamp(psiExact + slope * (ut - this->ut), -1.0, 1.0) : exact;
    if (!(fHat > 0.0))
      slope = 0.0;  // no bound: g = 0 whatever ψ is
    else if (stick)
      slope = alpha / fHat;
    else
      slope = (1.0 - psi * sign) / std::max(std::abs(ut), fHat / alpha);
    psiExact = exact;
    this->ut = ut;
    set = true;
    return psi;
  }
};

}  // namespace flowform
