// The responses integrated over the cells (cellIntegrals, ResponseContext.hpp), with the kernel's
// own quadrature so that the powers match the discrete equations exactly:
//   Plastic Power        ∫ s:D dΩ = ∫ 2μ D:D dΩ, the viscoplastic dissipation (≈ ∫ σ̄ ė dΩ)
//   Stabilization Power  Σ_K τ_K ∫_K ∇p·(∇p − f) dΩ = −∫ p div u: the work of the pressure
//                        stabilization (vanishes as h → 0)
//   Dead Zone            the area (volume) of the cells where |u| < Fraction × Reference Speed;
//                        piecewise constant in q: no derivative
#pragma once

#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

/// The plastic power (`plastic`) or the stabilization power, summed over the ranks.
template <typename Scalar>
Scalar cellPower(const ResponseContext<Scalar>& c, bool plastic) {
  Scalar plasticPower, stabilizationPower;
  double dead;
  cellIntegrals(c.x, c.mesh, c.dofMap, c.physics, c.material, 0.0, plasticPower, stabilizationPower, dead);
  return sumOverRanks(*c.dofMap.comm(), plastic ? plasticPower : stabilizationPower);
}

struct PlasticPower {
  static constexpr const char* kName = "Plastic Power";
  static constexpr const char* kDescription = "integral of 2 mu D:D: the viscoplastic dissipation";
  static constexpr bool kNeedsBoundary = false, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList&) {}
  explicit PlasticPower(const Teuchos::ParameterList&) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return cellPower(c, true);
  }
};

struct StabilizationPower {
  static constexpr const char* kName = "Stabilization Power";
  static constexpr const char* kDescription =
      "sum_K tau_K integral of grad p.(grad p - f) = -integral of p div u: the work of the pressure stabilization";
  static constexpr bool kNeedsBoundary = false, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList&) {}
  explicit StabilizationPower(const Teuchos::ParameterList&) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return cellPower(c, false);
  }
};

struct DeadZone {
  static constexpr const char* kName = "Dead Zone";
  static constexpr const char* kDescription =
      "area (volume) of the cells where |u| < Fraction x Reference Speed (no derivative)";
  static constexpr bool kNeedsBoundary = false, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = false;

  static void declareParameters(Teuchos::ParameterList& list);
  explicit DeadZone(const Teuchos::ParameterList& p)
      : m_fraction(p.get<double>("Fraction")), m_referenceSpeed(p.get<double>("Reference Speed")) {}

  double evaluate(const ResponseContext<double>& c) const {
    double plastic, stabilization, dead;
    cellIntegrals(c.x, c.mesh, c.dofMap, c.physics, c.material, m_fraction * m_referenceSpeed, plastic,
                  stabilization, dead);
    return sumOverRanks(*c.dofMap.comm(), dead);
  }

 private:
  double m_fraction, m_referenceSpeed;
};

}  // namespace flowform
