// Mean Strain: the flux-weighted equivalent strain of the material crossing a group (a case with
// Material/Strain Field, docs/theory.md §1.1),
//
//   ε̄ = Σ_k ε_k (u_k·w_k) / Σ_k (u_k·w_k) ≈ ∫ ε u·n dΓ / ∫ u·n dΓ
//
// (w_k the Flow Rate's nodal weights; the sums of TemperatureResponses.hpp's crossing). At the
// product's outlet it is the strain the process gave the metal: with the inflow's strain ε_in and
// a divergence-free flow, (ε̄ − ε_in) Q = ∫ ė dΩ, the volume integral of the strain rate (the
// field's own balance), and ε̄ / ε_ideal (ε_ideal = (2/√3) ln R in plane strain, ln R
// axisymmetric, R the reduction's area ratio) is the redundant strain factor.
#pragma once

#include <string>

#include "flowform/responses/ResponseContext.hpp"
#include "flowform/responses/TemperatureResponses.hpp"

namespace flowform {

struct MeanStrain {
  static constexpr const char* kName = "Mean Strain";
  static constexpr const char* kDescription =
      "the flux-weighted equivalent strain of the material crossing the group: integral of eps u.n over integral of "
      "u.n; needs Material/Strain Field";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;
  static constexpr const char* kField = kStrainField;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the group the material crosses (the product's outlet)");
  }
  explicit MeanStrain(const Teuchos::ParameterList& p) : m_boundary(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const int e = c.dofMap.fields().component(kStrainField);
    const Crossing<Scalar> through = crossing(c, buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary)), e);
    return through.valueFlux / through.flux;
  }

 private:
  std::string m_boundary;
};

}  // namespace flowform
