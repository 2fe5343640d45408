// The flux-weighted (mixing-cup) mean of a scalar field over the material crossing a group:
//
//   φ̄ = Σ_k φ_k (u_k·w_k) / Σ_k (u_k·w_k) ≈ ∫ φ u·n dΓ / ∫ u·n dΓ
//
// w_k = Σ_s n_s ∫ N_k dΓ the Flow Rate's nodal weights (FlowRate.hpp), φ lumped at the nodes
// (second order, like φ_h itself). At the product's outlet: its exit value; an inflow's φ̄ is its
// own. Two responses, one per field (a case without the field is refused before the solve,
// Responses::checkFields):
//   Mean Temperature  the product's exit temperature (Material/Thermal, docs/theory.md §10);
//   Mean Strain       the product's equivalent strain (Material/Strain Field, docs/theory.md §1.1):
//                     with the inflow's strain ε_in and ∇·u = 0, (ε̄ − ε_in) Q = ∫ ė dΩ, and
//                     ε̄ / ε_homogeneous (ε_homogeneous = ln(A_in/A_out) axisymmetric, (2/√3) times
//                     it in plane strain) is the redundant strain factor.
#pragma once

#include <string>

#include "flowform/core/InputError.hpp"
#include "flowform/responses/FlowRate.hpp"
#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

/// What crosses a boundary curve, summed over the ranks: the flux Q = Σ_k u_k·w_k and the flux of
/// a scalar field φ, Σ_k φ_k u_k·w_k (each node by its owner; `component` the field's).
template <typename Scalar>
struct Crossing {
  Scalar flux, valueFlux;
};
template <typename Scalar>
Crossing<Scalar> crossing(const ResponseContext<Scalar>& c, const BoundaryCurve& curve, int component) {
  const auto w = FlowRate::fluxWeights(c.mesh, curve, c.geometry());
  Scalar carried = 0.0, flux = 0.0;
  for (size_t k = 0; k < curve.nodes.size(); ++k) {
    const LO n = c.dofMap.overlapIndex(curve.nodes[k]);
    if (!c.dofMap.ownsNode(n)) continue;  // each node by its owner
    const Scalar q = w[k][0] * c.u(c.x, n, kUx) + w[k][1] * c.u(c.x, n, kUy);
    flux += q;
    carried += q * c.u(c.x, n, component);
  }
  return {sumOverRanks(*c.dofMap.comm(), flux), sumOverRanks(*c.dofMap.comm(), carried)};
}

/// `Of`: kName, kDescription, kField (the field's FieldRegistry name).
template <typename Of>
struct FluxWeightedMean {
  static constexpr const char* kName = Of::kName;
  static constexpr const char* kDescription = Of::kDescription;
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;
  static constexpr const char* kField = Of::kField;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the group the material crosses (the product's outlet)");
  }
  explicit FluxWeightedMean(const Teuchos::ParameterList& p) : m_boundary(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const int component = c.dofMap.fields().componentOf(kField);
    if (component < 0)
      throw InputError("Responses: the " + std::string(kName) + " of '" + m_boundary + "' needs the " + kField +
                       " field");
    const Crossing<Scalar> through = crossing(c, buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary)), component);
    return through.valueFlux / through.flux;
  }

 private:
  std::string m_boundary;
};

struct MeanTemperatureOf {
  static constexpr const char* kName = "Mean Temperature";
  static constexpr const char* kDescription =
      "the flux-weighted (mixing-cup) temperature of the material crossing the group: integral of T u.n over "
      "integral of u.n; needs Material/Thermal";
  static constexpr const char* kField = kTemperatureField;
};
using MeanTemperature = FluxWeightedMean<MeanTemperatureOf>;

struct MeanStrainOf {
  static constexpr const char* kName = "Mean Strain";
  static constexpr const char* kDescription =
      "the flux-weighted equivalent strain of the material crossing the group: integral of eps u.n over integral of "
      "u.n; needs Material/Strain Field";
  static constexpr const char* kField = kStrainField;
};
using MeanStrain = FluxWeightedMean<MeanStrainOf>;

}  // namespace flowform
