// Shear Angle: φ from the chip ratio r (Thickness Ratio) and the tool's Rake Angle α by the thin
// shear plane's kinematics, tan φ = r cos α / (1 − r sin α), in degrees.
#pragma once

#include <cmath>

#include "flowform/responses/ThicknessRatio.hpp"

namespace flowform {

struct ShearAngle {
  static constexpr const char* kName = "Shear Angle";
  static constexpr const char* kDescription =
      "phi from the chip ratio r and the Rake Angle alpha by the thin shear plane's kinematics, tan phi = r cos "
      "alpha / (1 - r sin alpha), in degrees";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  /// Thickness Ratio's entries and the Rake Angle.
  static void declareParameters(Teuchos::ParameterList& list);
  explicit ShearAngle(const Teuchos::ParameterList& p)
      : m_boundary(p.get<std::string>("Boundary")),
        m_referenceThickness(p.get<double>("Reference Thickness")),
        m_rakeAngle(p.get<double>("Rake Angle")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const Scalar ratio = streamThicknessRatio(c, m_boundary, m_referenceThickness);
    const double alpha = m_rakeAngle * M_PI / 180.0;
    return std::atan2(ratio * std::cos(alpha), 1.0 - ratio * std::sin(alpha)) * (180.0 / M_PI);
  }

 private:
  std::string m_boundary;
  double m_referenceThickness, m_rakeAngle;  ///< [length], [degrees]
};

}  // namespace flowform
