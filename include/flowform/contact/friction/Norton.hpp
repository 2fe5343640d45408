// Norton (viscous) friction: g_k = α_f K A_k (u_t² + ε²)^((q−1)/2) u_t, smooth in u_t (ε > 0
// keeps pow differentiable at u_t = 0), no sticking bound and no dependence on ν or m.
#pragma once

#include <cmath>

#include "flowform/contact/friction/FrictionLaw.hpp"

namespace flowform {

struct NortonFriction {
  static constexpr const char* kName = "Norton";
  static constexpr const char* kDescription = "Norton (α_f K |u_t|^(q-1) u_t)";
  static constexpr bool kUsesFrictionCoefficient = false;
  static constexpr bool kUsesShearFactor = false;
  static constexpr bool kNeedsTributary = true;

  template <typename Scalar, typename PScalar>
  static FrictionForce<Scalar> force(const FrictionNodeData<Scalar>& d, const FrictionParameters<PScalar>&,
                                     const FrictionSettings& s) {
    using std::pow;
    const Scalar& ut = d.tangentialVelocity;
    const double eps = s.nortonRegularization;
    return {s.nortonCoefficient * d.tributary * pow(ut * ut + eps * eps, 0.5 * (s.nortonExponent - 1.0)) * ut,
            FrictionBranch::Slip};
  }
};

}  // namespace flowform
