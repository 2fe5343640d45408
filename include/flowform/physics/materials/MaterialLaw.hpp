// What every material law gets and gives (docs/theory.md §1; the laws themselves are one file
// each beside this one, registered in MaterialLaws.hpp).
//
// A law is the flow stress σ̄(e_r; h) of the regularized equivalent strain rate
//   e_r = sqrt(2/3 D:D + e0²)        (shared by every law: e0 > 0 keeps μ finite in rigid zones)
// and its parameters h; the viscosity μ = σ̄/(3 e_r) (Material.hpp) is the same for all laws.
// The parameters are values in the law's declared order, templated on the scalar type so
// that the same code gives values (double), the exact tangent (Sacado Fad of the element
// dofs) and parameter derivatives (Fad of one seeded parameter).
#pragma once

#include <array>

namespace flowform {

/// Parameters a law may declare (the registry checks each law against it).
inline constexpr int kMaxMaterialParameters = 11;

/// A law (its index in materialLaws()), its parameters in its declared order, and the
/// shared strain-rate cutoff e0.
template <typename Scalar>
struct MaterialParameters {
  int law = 0;
  std::array<Scalar, kMaxMaterialParameters> values{};
  Scalar cutoff{};  ///< e0 > 0, the strain-rate cutoff
};

/// One parameter of a law, as the Material sublist names it.
struct MaterialParameterInfo {
  enum class Range { Positive, NonNegative, Finite };
  const char* name;        ///< e.g. "Yield Stress"
  const char* symbol;      ///< for sensitivity field and column names, e.g. "sigma0"
  const char* doc;         ///< with its unit, for the valid-parameter list and --help
  double defaultValue;
  Range range;
  bool sensitivity;        ///< may be named in Sensitivity/Parameters
  bool relativeStep;       ///< finite-difference step δ = s |h| (true) or δ = s (false)
};

}  // namespace flowform
