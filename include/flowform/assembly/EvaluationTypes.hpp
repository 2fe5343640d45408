// The evaluation types of the templated residual loops (Albany's EvalT, without Phalanx):
//   Residual  double                      values
//   Jacobian  Sacado SFad<double, N>      N = the dofs of a cell (or a wall node's stencil)
//   Tangent   TangentFad = SFad<double, 1> x seeded along a direction dx and a parameter h
//             seeded (derivative 1): one pass gives J dx + ∂R/∂h, and with dx = 0 ∂R/∂h
// and the helpers that seed and read them. Only the Assembler and the Responses seed, and
// only through these.
#pragma once

#include <type_traits>

#include <Sacado.hpp>

#include "flowform/Material.hpp"
#include "flowform/SensitivityParameter.hpp"
#include "flowform/contact/ContactWall.hpp"

namespace flowform {

using TangentFad = Sacado::Fad::SFad<double, 1>;

/// The material with h seeded: T is an AD type with one derivative (Sacado SFad<double, 1>);
/// seeding a null or a friction parameter gives every entry a zero derivative.
template <typename T>
MaterialParameters<T> seededMaterial(const MaterialParameters<double>& m, const SensitivityParameter* h) {
  auto seed = [&](double value, ParameterKind kind) { return h && h->kind == kind ? T(1, 0, value) : T(value); };
  return {seed(m.yieldStress, ParameterKind::YieldStress), seed(m.rateConstant, ParameterKind::RateConstant),
          seed(m.rateExponent, ParameterKind::RateExponent), T(m.cutoff)};
}

/// Wall `w`'s ν and m with h seeded where h enters that wall.
template <typename T>
FrictionParameters<T> seededFriction(const ContactWall& wall, int w, const SensitivityParameter* h) {
  const FrictionParameters<double> fp = wall.frictionParameters();
  const bool seeded = h && h->entersWall(w, wall);
  auto seed = [&](double value, ParameterKind kind) { return seeded && h->kind == kind ? T(1, 0, value) : T(value); };
  return {seed(fp.frictionCoefficient, ParameterKind::FrictionCoefficient),
          seed(fp.shearFactor, ParameterKind::ShearFactor)};
}

/// A value with one directional derivative (val, d) for the tangent evaluations.
template <typename T>
T dual(double value, double derivative) {
  T t(1, value);
  t.fastAccessDx(0) = derivative;
  return t;
}

/// The two evaluation types that share one templated loop: Residual (double: values) and
/// tangent (T: x seeded along a direction dx, h seeded). Input: the value, and for T its
/// derivative; output: the value, or the derivative.
template <typename Scalar>
void setInput(Scalar& s, double value, double derivative) {
  if constexpr (std::is_same_v<Scalar, double>) s = value;
  else s = dual<Scalar>(value, derivative);
}
template <typename Scalar>
double output(const Scalar& s) {
  if constexpr (std::is_same_v<Scalar, double>) return s;
  else return s.dx(0);
}
template <typename Scalar>
MaterialParameters<Scalar> materialFor(const MaterialParameters<double>& m, const SensitivityParameter* h) {
  if constexpr (std::is_same_v<Scalar, double>) return m;
  else return seededMaterial<Scalar>(m, h);
}
template <typename Scalar>
FrictionParameters<Scalar> frictionFor(const ContactWall& wall, int w, const SensitivityParameter* h) {
  if constexpr (std::is_same_v<Scalar, double>) return wall.frictionParameters();
  else return seededFriction<Scalar>(wall, w, h);
}

}  // namespace flowform
