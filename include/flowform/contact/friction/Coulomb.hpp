// Coulomb friction with a sticking bound (paper eqs. 17–19): f̂_k = ν P_k. Acts only under
// compression (P_k > 0): a node in tension carries no friction and ∂g/∂ν = 0 there (eq. 28);
// at ν = 0 a compressed node slips with g = 0 and ∂g/∂ν = P_k sign(u_t).
#pragma once

#include "flowform/contact/friction/FrictionLaw.hpp"

namespace flowform {

struct CoulombFriction {
  static constexpr const char* kName = "Coulomb";
  static constexpr const char* kDescription = "Coulomb (ν p, capped by sticking)";
  static constexpr bool kUsesFrictionCoefficient = true;
  static constexpr bool kUsesShearFactor = false;
  static constexpr bool kNeedsTributary = false;

  template <typename Scalar, typename PScalar>
  static FrictionForce<Scalar> force(const FrictionNodeData<Scalar>& d, const FrictionParameters<PScalar>& fp,
                                     const FrictionSettings& settings) {
    if (uncompressed(d, settings)) return {Scalar(0.0), FrictionBranch::NoFriction};
    return boundedFriction(d, Scalar(fp.frictionCoefficient * d.pressureIntegral), FrictionBranch::Slip);
  }
};

}  // namespace flowform
