// A parameter h of the model that sensitivity analysis differentiates by (docs/theory.md §4, paper
// §3): the friction coefficient ν (every contact wall, or one), the shear factor m (the
// same), and the sensitivity parameters the case's material law declares
// (physics/materials/). The case names them in Sensitivity/Parameters:
//
//   "Friction Coefficient"              ν of every wall whose law uses it, moved together
//   "Friction Coefficient:<wall group>" ν of one wall
//   "Shear Factor", "Shear Factor:<wall group>"   m, likewise
//   "Friction Field:<wall group>/<j>"   ν_j, station j's value of a wall's Friction Field
//                                       (contact/ContactWall.hpp: ν linear between stations)
//   a material law's parameter, e.g. the power law's "Yield Stress" σ0, "Rate Constant" γ,
//   "Rate Exponent" n, or Sellars–Tegart's "Activation Energy" Q, "Temperature" T, ...
//   "Geo Parameter:<name>"              a shape parameter: a Mesh/Geo Parameters entry of the
//                                       case's .geo (a die angle, a roll radius); it moves the
//                                       mesh, not a coefficient (sensitivity/GeoParameterMotion)
//   "Thermal:<name>"                    a property of Material/Thermal: Conductivity, Density,
//                                       Specific Heat, Heat Fraction (seeded in the temperature rows)
//   "Boundary Value:<group>/<entry>"    a value a boundary group's condition gives: Velocity X,
//                                       Velocity Y (a ram speed), Temperature (a billet's),
//                                       Heat Transfer Coefficient, Ambient or Tool Temperature.
//                                       The residual is affine in each, so ∂R/∂h is the difference
//                                       of two assemblies one unit apart (sensitivity/
//                                       BoundaryValuePartials)
//
// The AD seeding with such a parameter: EvaluationTypes.hpp.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "flowform/contact/ContactWall.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/ThermalProperties.hpp"

namespace flowform {

struct FlowPhysics;

/// The friction parameters, one of the material law's (which: `material`), or a .geo constant.
enum class ParameterKind { FrictionCoefficient, ShearFactor, FrictionField, Material, GeoParameter, BoundaryValue, Thermal };

struct SensitivityParameter {
  std::string name;    ///< as the case gives it, e.g. "Friction Coefficient:<wall group>"
  std::string symbol;  ///< for field and column names: nu, nu_<wall group>, m, the law's (sigma0, gamma, n, ...)
  ParameterKind kind = ParameterKind::Material;
  int wall = -1;       ///< friction parameters: the wall's index, −1 for every wall
  int station = -1;    ///< a Friction Field's station
  int material = -1;   ///< material parameters: the index in MaterialParameters::values
  int thermal = -1;    ///< thermal properties: the index (ThermalParameter) in FlowPhysics::thermal
  bool relativeStep = false;  ///< the finite-difference step is relative (the law says)
  std::string geoName;        ///< a Geo Parameter: its name in Mesh/Geo Parameters
  double geoValue = 0.0;      ///< a Geo Parameter: its value in the case
  std::string group, entry;   ///< a Boundary Value: the group and the entry of its condition
  double boundaryValue = 0.0; ///< a Boundary Value: its value in the case

  bool isGeo() const { return kind == ParameterKind::GeoParameter; }
  bool isBoundaryValue() const { return kind == ParameterKind::BoundaryValue; }
  /// ∂R/∂h and ∂φ/∂h come from the problem (a moved mesh, a changed condition), not from the
  /// AD seeding of a coefficient.
  bool partialsFromProblem() const { return isGeo() || isBoundaryValue(); }

  bool isFriction() const {
    return kind == ParameterKind::FrictionCoefficient || kind == ParameterKind::ShearFactor ||
           kind == ParameterKind::FrictionField;
  }
  /// Whether this parameter enters wall `w`'s law.
  bool entersWall(int w, const ContactWall& wall) const {
    if (!isFriction() || (this->wall >= 0 && this->wall != w)) return false;
    if (kind == ParameterKind::FrictionField) return wall.hasFrictionField();
    return kind == ParameterKind::FrictionCoefficient ? wall.usesFrictionCoefficient() : wall.usesShearFactor();
  }
  /// The finite-difference step for a requested step s: absolute (δ = s) for the
  /// dimensionless friction parameters ν and m, which may be 0 (the paper's Δν = 2·10⁻⁴);
  /// for a material parameter as its law declares: relative (δ = s |h|; s if h = 0) for
  /// those that carry units and scales (all of today's laws' parameters), else absolute;
  /// relative for a Geo Parameter (a length or an angle in the .geo's units).
  double finiteDifferenceStep(double s, const FlowPhysics& physics) const;
};

/// The Mesh/Geo Parameters a case gives (name, value): what "Geo Parameter:<name>" may name.
using GeoParameterValues = std::vector<std::pair<std::string, double>>;
/// The boundary values a case gives ("<group>/<entry>", value): what "Boundary Value:..." may name.
using BoundaryValues = std::vector<std::pair<std::string, double>>;

/// Parses a name of Sensitivity/Parameters for a case with material law `law` (an index of
/// materialLaws()) and Geo Parameters `geo`. InputError naming the allowed names (those of the
/// case's walls, of its law and its Geo Parameters included) for an unknown name or another
/// law's parameter, for a friction parameter when the case has no contact wall, when no
/// wall's law uses it, or for a Geo Parameter the case does not give.
SensitivityParameter parseSensitivityParameter(const std::string& name, const std::vector<ContactWall>& walls,
                                               int law, const GeoParameterValues& geo = {},
                                               const BoundaryValues& boundary = {});

/// The value of h in the case (for a friction parameter of every wall: the first using it).
double parameterValue(const SensitivityParameter& h, const FlowPhysics& physics, const std::vector<ContactWall>& walls);

/// h += delta (on every wall it enters), for the finite-difference runs.
void shiftParameter(const SensitivityParameter& h, double delta, FlowPhysics& physics, std::vector<ContactWall>& walls);

}  // namespace flowform
