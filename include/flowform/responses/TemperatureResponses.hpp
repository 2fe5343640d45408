// The responses of the Temperature field (a case with Material/Thermal, docs/theory.md §10):
//   Mean Temperature     the flux-weighted (mixing-cup) temperature of the material crossing a
//                        group: T̄ = Σ_k T_k (u_k·w_k) / Σ_k (u_k·w_k), w_k = Σ_s n_s ∫ N_k dΓ the
//                        Flow Rate's nodal weights (FlowRate.hpp): ∫ T u·n dΓ / ∫ u·n dΓ with T
//                        lumped at the nodes (second order, like T_h itself). The product's exit
//                        temperature; an inflow's T̄ is its own.
//   Maximum Temperature  the largest nodal temperature (no derivative: the node that holds it may
//                        change with a parameter).
// Each needs the field (kField): a case without it is refused before the solve
// (Responses::checkFields).
#pragma once

#include <algorithm>
#include <limits>
#include <string>

#include <Teuchos_CommHelpers.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/responses/FlowRate.hpp"
#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

/// The Temperature component of the case (InputError naming `who` when it has none).
inline int temperatureComponent(const DofMap& dofMap, const std::string& who) {
  const int t = dofMap.fields().componentOf(kTemperatureField);
  if (t < 0) throw InputError("Responses: " + who + " needs a temperature field: give Material/Thermal");
  return t;
}

/// What crosses a boundary curve, summed over the ranks: the flux Q = Σ_k u_k·w_k and the flux of
/// a scalar field φ, Σ_k φ_k u_k·w_k (w_k the Flow Rate's nodal weights, FlowRate.hpp; each node by
/// its owner; t the field's component: the temperature's, the strain's).
template <typename Scalar>
struct Crossing {
  Scalar flux, valueFlux;
};
template <typename Scalar>
Crossing<Scalar> crossing(const ResponseContext<Scalar>& c, const BoundaryCurve& curve, int t) {
  const auto w = FlowRate::fluxWeights(c.mesh, curve, c.geometry());
  Scalar heat = 0.0, flux = 0.0;
  for (size_t k = 0; k < curve.nodes.size(); ++k) {
    const LO n = c.dofMap.overlapIndex(curve.nodes[k]);
    if (!c.dofMap.ownsNode(n)) continue;  // each node by its owner
    const Scalar q = w[k][0] * c.u(c.x, n, kUx) + w[k][1] * c.u(c.x, n, kUy);
    flux += q;
    heat += q * c.u(c.x, n, t);
  }
  return {sumOverRanks(*c.dofMap.comm(), flux), sumOverRanks(*c.dofMap.comm(), heat)};
}

struct MeanTemperature {
  static constexpr const char* kName = "Mean Temperature";
  static constexpr const char* kDescription =
      "the flux-weighted (mixing-cup) temperature of the material crossing the group: integral of T u.n over "
      "integral of u.n; needs Material/Thermal";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;
  static constexpr const char* kField = kTemperatureField;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the group the material crosses (the product's outlet)");
  }
  explicit MeanTemperature(const Teuchos::ParameterList& p) : m_boundary(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const int t = temperatureComponent(c.dofMap, std::string("the Mean Temperature of '") + m_boundary + "'");
    const Crossing<Scalar> through = crossing(c, buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary)), t);
    return through.valueFlux / through.flux;
  }

 private:
  std::string m_boundary;
};

struct MaximumTemperature {
  static constexpr const char* kName = "Maximum Temperature";
  static constexpr const char* kDescription = "the largest nodal temperature (no derivative); needs Material/Thermal";
  static constexpr bool kNeedsBoundary = false, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = false;
  static constexpr const char* kField = kTemperatureField;

  static void declareParameters(Teuchos::ParameterList&) {}
  explicit MaximumTemperature(const Teuchos::ParameterList&) {}

  double evaluate(const ResponseContext<double>& c) const {
    const int t = temperatureComponent(c.dofMap, "a Maximum Temperature response");
    double local = -std::numeric_limits<double>::infinity();
    for (LO n = 0; n < c.dofMap.numOwnedNodes(); ++n) local = std::max(local, c.u(c.x, n, t));
    double global = local;
    Teuchos::reduceAll(*c.dofMap.comm(), Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
    return global;
  }
};

}  // namespace flowform
