// Orowan friction: the smaller of Coulomb's and Tresca's bounds, f̂_k = min(ν P_k, m S_k/√3),
// with the sticking bound; under compression only (P_k > 0), like Coulomb. Where the Tresca
// bound is the smaller the branch is SlipTresca (the kink between the two is a branch change).
#pragma once

#include <cmath>

#include "flowform/contact/friction/FrictionLaw.hpp"

namespace flowform {

struct OrowanFriction {
  static constexpr const char* kName = "Orowan";
  static constexpr const char* kDescription = "Orowan (min of Coulomb and Tresca)";
  static constexpr bool kUsesFrictionCoefficient = true;
  static constexpr bool kUsesShearFactor = true;
  static constexpr bool kNeedsTributary = false;

  template <typename Scalar, typename PScalar>
  static FrictionForce<Scalar> force(const FrictionNodeData<Scalar>& d, const FrictionParameters<PScalar>& fp,
                                     const FrictionSettings& settings) {
    if (uncompressed(d, settings)) return {Scalar(0.0), FrictionBranch::NoFriction};
    const Scalar fCoulomb = fp.frictionCoefficient * d.pressureIntegral;
    const Scalar fTresca = fp.shearFactor * (d.stressIntegral / std::sqrt(3.0));
    const bool trescaLimited = !(fCoulomb < fTresca);
    return boundedFriction(d, trescaLimited ? fTresca : fCoulomb,
                           trescaLimited ? FrictionBranch::SlipTresca : FrictionBranch::Slip);
  }
};

}  // namespace flowform
