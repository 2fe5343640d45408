// A parameter h of the model that sensitivity analysis differentiates by (docs/theory.md §4, paper
// §3): the friction coefficient ν (every contact wall, or one), the shear factor m (the
// same), and the material's σ0, γ, n. The case names them in Sensitivity/Parameters:
//
//   "Friction Coefficient"              ν of every wall whose law uses it, moved together
//   "Friction Coefficient:<wall group>" ν of one wall
//   "Shear Factor", "Shear Factor:<wall group>"   m, likewise
//   "Yield Stress" σ0, "Rate Constant" γ, "Rate Exponent" n
//
// The AD seeding with such a parameter: EvaluationTypes.hpp.
#pragma once

#include <string>
#include <vector>

#include "flowform/physics/Material.hpp"
#include "flowform/contact/ContactWall.hpp"

namespace flowform {

struct FlowPhysics;

enum class ParameterKind { FrictionCoefficient, ShearFactor, YieldStress, RateConstant, RateExponent };

struct SensitivityParameter {
  std::string name;    ///< as the case gives it, e.g. "Friction Coefficient:<wall group>"
  std::string symbol;  ///< for field and column names: nu, nu_<wall group>, m, sigma0, gamma, n
  ParameterKind kind = ParameterKind::YieldStress;
  int wall = -1;       ///< friction parameters: the wall's index, −1 for every wall

  bool isFriction() const { return kind == ParameterKind::FrictionCoefficient || kind == ParameterKind::ShearFactor; }
  /// Whether this parameter enters wall `w`'s law.
  bool entersWall(int w, const ContactWall& wall) const {
    if (!isFriction() || (this->wall >= 0 && this->wall != w)) return false;
    return kind == ParameterKind::FrictionCoefficient ? wall.usesFrictionCoefficient() : wall.usesShearFactor();
  }
  /// The finite-difference step for a requested step s: absolute (δ = s) for the
  /// dimensionless friction parameters ν and m, which may be 0 (the paper's Δν = 2·10⁻⁴);
  /// relative (δ = s |h|) for σ0, γ, n, which carry units and scales; s if σ0 = 0.
  double finiteDifferenceStep(double s, const FlowPhysics& physics) const;
};

/// Parses a name of Sensitivity/Parameters. InputError naming the allowed names (those of
/// the case's walls included) for an unknown name, for a friction parameter when the case
/// has no contact wall, or when no wall's law uses it.
SensitivityParameter parseSensitivityParameter(const std::string& name, const std::vector<ContactWall>& walls);

/// The value of h in the case (for a friction parameter of every wall: the first using it).
double parameterValue(const SensitivityParameter& h, const FlowPhysics& physics, const std::vector<ContactWall>& walls);

/// h += delta (on every wall it enters), for the finite-difference runs.
void shiftParameter(const SensitivityParameter& h, double delta, FlowPhysics& physics, std::vector<ContactWall>& walls);

}  // namespace flowform
