// Tresca (shear) friction with a sticking bound: f̂_k = m S_k/√3, the fraction m of the
// shear flow stress σ̄/√3. Acts wherever a segment is active (S_k > 0), under tension too.
#pragma once

#include <cmath>

#include "flowform/contact/friction/FrictionLaw.hpp"

namespace flowform {

struct TrescaFriction {
  static constexpr const char* kName = "Tresca";
  static constexpr const char* kDescription = "Tresca (m σ̄/√3)";
  static constexpr bool kUsesFrictionCoefficient = false;
  static constexpr bool kUsesShearFactor = true;
  static constexpr bool kNeedsTributary = false;

  template <typename Scalar, typename PScalar>
  static FrictionForce<Scalar> force(const FrictionNodeData<Scalar>& d, const FrictionParameters<PScalar>& fp,
                                     const FrictionSettings&) {
    if (!(d.stressIntegral > 0.0)) return {Scalar(0.0), FrictionBranch::NoFriction};
    return boundedFriction(d, Scalar(fp.shearFactor * (d.stressIntegral / std::sqrt(3.0))), FrictionBranch::Slip);
  }
};

}  // namespace flowform
