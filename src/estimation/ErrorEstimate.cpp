#include "flowform/estimation/ErrorEstimate.hpp"

#include <nlohmann/json.hpp>

namespace flowform {

void ErrorEstimate::report(nlohmann::json& summary) const {
  if (!failure.empty()) summary["error_estimation"] = {{"method", method}, {"failure", failure}};
  if (!estimated) return;
  summary["functionals_error_estimate"] = nlohmann::json::object();
  for (const auto& [name, eta] : functionals) summary["functionals_error_estimate"][name] = eta;
  if (!sensitivities.empty()) summary["sensitivities_error_estimate"] = sensitivities;
  summary["error_estimation"] = {{"method", method},
                                 {"order", order},
                                 {otherLevel + "_dofs", refinedDofs},
                                 {otherLevel + "_functionals", refinedFunctionals},
                                 {"seconds", seconds},
                                 {"timings", timings}};
  if (!details.empty()) summary["error_estimation"]["details"] = details;
  if (!refinedSensitivities.empty()) summary["error_estimation"][otherLevel + "_sensitivities"] = refinedSensitivities;
  if (!sensitivitiesTotalShape.empty()) {
    summary["sensitivities_total_shape_error_estimate"] = sensitivitiesTotalShape;
    summary["error_estimation"][otherLevel + "_sensitivities_total_shape"] = refinedSensitivitiesTotalShape;
  }
  if (refinedSurfaceUpdates >= 0)
    summary["error_estimation"][otherLevel + "_free_surface_iterations"] = refinedSurfaceUpdates;
}

}  // namespace flowform
