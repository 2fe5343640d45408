// What every friction law of a contact wall gets and gives (docs/theory.md §2; the laws
// themselves are one file each beside this one, registered in FrictionLaws.hpp).
//
// At an active wall node k with tangent t_k and u_t = u_k·t_k, the wall lumps the segment
// integrals the laws need over the node's active segments s (2-point Gauss, exact here):
//   P_k = Σ_s ∫_s N_k p⁺_h W ds    (compression: Coulomb-type laws),
//   S_k = Σ_s ∫_s N_k σ̄_h W ds     (flow stress: Tresca-type laws),
//   A_k = Σ_s ∫_s N_k W ds         (tributary area: viscous laws),
// W = 2π r axisymmetric, 1 in plane strain. A law returns the tangential force g_k (along
// t_k) and its branch. The bounded laws share the sticking rule boundedFriction():
//   g_k = α_t u_t if α_t |u_t| ≤ f̂_k (stick),  f̂_k sign(u_t) otherwise (slip),
// with α_t = κ_t μ_k W_k. Templated on the dof scalar (S) and the friction parameters'
// scalar (P): values, the AD tangent and ∂/∂ν, ∂/∂m from one code.
#pragma once

#include <type_traits>

#include <Sacado.hpp>

#include "flowform/contact/friction/FrictionDual.hpp"

namespace flowform {

/// The friction parameters that sensitivity analysis may seed as AD variables.
template <typename PScalar>
struct FrictionParameters {
  PScalar frictionCoefficient;  ///< ν (Coulomb, Orowan)
  PScalar shearFactor;          ///< m (Tresca, Orowan)
  /// A wall with a Friction Field: the station whose value is seeded (the derivative by it), −1 none.
  int seededStation = -1;
};

/// Which branch of the law a wall node is on (a kink of the law lies between branches):
/// Free (not in contact), NoFriction (active but not compressed, or law None), Stick,
/// Slip (Coulomb-limited, or Tresca/Norton), SlipTresca (Orowan limited by m σ̄/√3).
enum class FrictionBranch { Free, NoFriction, Stick, Slip, SlipTresca };
const char* frictionBranchName(FrictionBranch b);

/// The law's own constants (from the wall's parameter sublist).
struct FrictionSettings {
  double nortonCoefficient = 0.0;  ///< α_f K
  double nortonExponent = 1.0;     ///< q
  double nortonRegularization = 1e-6;
  /// A node at rest without compression sticks (uncompressed()): set for the second start of
  /// a first solve that failed from frictionless walls (Simulation::run).
  bool stickAtRest = false;
};

/// What the wall gives a law at one active node.
template <typename Scalar>
struct FrictionNodeData {
  Scalar tangentialVelocity;    ///< u_t
  Scalar pressureIntegral;      ///< P_k (0 unless the law needs it)
  Scalar stressIntegral;        ///< S_k (0 unless the law needs it)
  Scalar tributary;             ///< A_k (0 unless the law needs it)
  double stickingStiffness;     ///< α_t
  FrictionDualPoint* dual = nullptr;  ///< Jacobian only: the dual slip linearization (FrictionDual.hpp)
};

template <typename Scalar>
struct FrictionForce {
  Scalar g;
  FrictionBranch branch;
};

/// Whether a Coulomb-type law carries no friction at the node: no compression (P_k = 0, as
/// P_k sums p⁺). A node at rest (u_t = 0 exactly, as every wall node is in the zero start of
/// the Newtonian predictor) is at the kink of every branch. By default it carries none, so the
/// first linearization sees frictionless walls; with `stickAtRest` it takes the sticking
/// branch (g = α_t u_t = 0 with the derivative α_t), so it sees sticking walls — the start
/// that lets the sticking-dominated cases (ν = 2, 5) converge (docs/contact.md).
template <typename Scalar>
bool uncompressed(const FrictionNodeData<Scalar>& d, const FrictionSettings& s) {
  return !(d.pressureIntegral > 0.0) && !(s.stickAtRest && d.tangentialVelocity == 0.0);
}

/// The sticking rule of the bounded laws: stick while α_t |u_t| ≤ f̂, else slip at f̂
/// against u_t. In stick g = α_t u_t does not depend on ν or m (∂g/∂ν = ∂g/∂m = 0).
template <typename Scalar>
FrictionForce<Scalar> boundedFriction(const FrictionNodeData<Scalar>& d, const Scalar& fHat, FrictionBranch slip) {
  const Scalar& ut = d.tangentialVelocity;
  const Scalar stick = d.stickingStiffness * ut;  // f* = α_t |u_t|, the sticking bound
  const bool sticks = (stick >= 0.0 ? stick : Scalar(-stick)) <= fHat;
  if constexpr (!std::is_same_v<Scalar, double>) {
    if (d.dual) {
      // g = f̂ sign(u_t) in value; derivative ψ_k df̂ + f̂ (1 − ψ_k sign)/|u_t| du_t in slip
      const double utV = Sacado::ScalarValue<Scalar>::eval(ut), fV = Sacado::ScalarValue<Scalar>::eval(fHat);
      const double psi = d.dual->update(utV, fV, d.stickingStiffness, sticks);
      if (sticks) return {stick, FrictionBranch::Stick};
      const double sign = utV >= 0.0 ? 1.0 : -1.0;
      return {sign * fV + psi * (fHat - fV) + d.dual->slope * fV * (ut - utV), slip};
    }
  }
  if (sticks) return {stick, FrictionBranch::Stick};
  return {ut >= 0.0 ? fHat : Scalar(-fHat), slip};
}

}  // namespace flowform
