// No friction: an active node carries only the normal penalty (a frictionless tool).
#pragma once

#include "flowform/contact/friction/FrictionLaw.hpp"

namespace flowform {

struct NoFriction {
  static constexpr const char* kName = "None";
  static constexpr const char* kDescription = "None";
  static constexpr bool kUsesFrictionCoefficient = false;
  static constexpr bool kUsesShearFactor = false;
  static constexpr bool kNeedsTributary = false;

  template <typename Scalar, typename PScalar>
  static FrictionForce<Scalar> force(const FrictionNodeData<Scalar>&, const FrictionParameters<PScalar>&,
                                     const FrictionSettings&) {
    return {Scalar(0.0), FrictionBranch::NoFriction};
  }
};

}  // namespace flowform
