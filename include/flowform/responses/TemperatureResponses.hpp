// The responses of the Temperature field (a case with Material/Thermal, docs/theory.md §10)
// besides its Mean Temperature (FluxWeightedMean.hpp):
//   Maximum Temperature  the largest nodal temperature (no derivative: the node that holds it may
//                        change with a parameter).
// It needs the field (kField): a case without it is refused before the solve
// (Responses::checkFields). temperatureComponent serves the temperature's responses (HeatFlow.hpp).
#pragma once

#include <algorithm>
#include <limits>
#include <string>

#include <Teuchos_CommHelpers.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

/// The Temperature component of the case (InputError naming `who` when it has none).
inline int temperatureComponent(const DofMap& dofMap, const std::string& who) {
  const int t = dofMap.fields().componentOf(kTemperatureField);
  if (t < 0) throw InputError("Responses: " + who + " needs a temperature field: give Material/Thermal");
  return t;
}

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
