#include "flowform/optimization/OptimizationSettings.hpp"

#include <cmath>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

using Teuchos::Array;
using Teuchos::ParameterList;

namespace {

void buildOptimizationParameters(const ValidList& valid) {
  valid->set("Design Parameters", Array<std::string>(),
             "the parameters the optimizer moves: names of Sensitivity/Parameters (docs/sensitivity.md: 'Geo "
             "Parameter:alpha', 'Friction Coefficient', 'Friction Coefficient:<wall>', 'Boundary Value:<group>/<entry>', "
             "a law's constant, 'Thermal:<property>'), each starting from the case's value");
  valid->set("Lower Bounds", Array<double>(), "one finite lower bound per design parameter");
  valid->set("Upper Bounds", Array<double>(), "one finite upper bound per design parameter, above the lower");
  valid->set("Objective", "", "a response of the case to minimize (or maximize: Sense); empty: the misfit of "
                              "Measured Responses");
  Teuchos::setStringToIntegralParameter<int>("Sense", "Minimize", "with an Objective: Minimize or Maximize it",
                                             Teuchos::tuple<std::string>("Minimize", "Maximize"), valid.get());
  valid->set("Measured Responses", Array<std::string>(),
             "the misfit's responses: minimize 1/2 sum ((phi_i - measured_i) / error_i)^2 (Gauss-Newton Hessian)");
  valid->set("Measured Values", Array<double>(), "one measured value per Measured Response");
  valid->set("Measurement Errors", Array<double>(),
             "the standard error of each measured value (> 0; empty: 1 each); the design's confidence interval "
             "comes from the Gauss-Newton Hessian with them");
  Teuchos::setStringToIntegralParameter<int>(
      "Algorithm", "Trust Region",
      "ROL's step: Trust Region (truncated CG, bounds by projection) or Line Search (quasi-Newton, projected)",
      Teuchos::tuple<std::string>("Trust Region", "Line Search"), valid.get());
  valid->set("Gradient Tolerance", 1e-6,
             "stop when the projected gradient's norm is below this, on the scaled problem (each design "
             "parameter mapped to [0, 1] by its bounds; a response objective divided by its initial |value|)",
             inRange(1e-14, 1.0));
  valid->set("Step Tolerance", 1e-8, "stop when a step is shorter than this (scaled design)", inRange(1e-16, 1.0));
  valid->set("Initial Trust Region Radius", 1.0, "the first trust region, in the scaled design (1 = a bound's range)",
             inRange(1e-6, 10.0));
  valid->set("Iteration Limit", 30, "optimizer iterations at most", intInRange(1, 1000));
  valid->set("Remeshing Cycles", 3,
             "with a shape parameter (Geo Parameter:<name>): the designs of a cycle are its start's mesh moved (one "
             "topology: the response varies smoothly with the design); a cycle that moved the design by more than 2 % "
             "of a bound's range is followed by one from a mesh made at its result, at most this many cycles",
             intInRange(1, 10));
  valid->set("Warm Start", true,
             "start each solve from the previous design's solution and contact statuses (else from scratch)");
}

template <typename T>
std::vector<T> vectorOf(const ParameterList& list, const std::string& name) {
  const auto a = list.get<Array<T>>(name);
  return std::vector<T>(a.begin(), a.end());
}

}  // namespace

Teuchos::RCP<const ParameterList> OptimizationSettings::validParameters() {
  return validListOnce<buildOptimizationParameters>("Optimization");
}

bool optimizationRequested(const ParameterList& params) { return params.isSublist("Optimization"); }

OptimizationSettings::OptimizationSettings(const ParameterList& caseParams) {
  const ParameterList& list = caseParams.sublist("Optimization");
  design = vectorOf<std::string>(list, "Design Parameters");
  lower = vectorOf<double>(list, "Lower Bounds");
  upper = vectorOf<double>(list, "Upper Bounds");
  objective = list.get<std::string>("Objective");
  maximize = list.get<std::string>("Sense") == "Maximize";
  measured = vectorOf<std::string>(list, "Measured Responses");
  values = vectorOf<double>(list, "Measured Values");
  errors = vectorOf<double>(list, "Measurement Errors");
  algorithm = list.get<std::string>("Algorithm");
  gradientTolerance = list.get<double>("Gradient Tolerance");
  stepTolerance = list.get<double>("Step Tolerance");
  initialRadius = list.get<double>("Initial Trust Region Radius");
  iterationLimit = list.get<int>("Iteration Limit");
  warmStart = list.get<bool>("Warm Start");
  remeshingCycles = list.get<int>("Remeshing Cycles");

  if (design.empty()) throw InputError("Optimization/Design Parameters: name at least one parameter to design");
  if (lower.size() != design.size() || upper.size() != design.size())
    throw InputError("Optimization/Lower Bounds, Upper Bounds: one each per design parameter (" +
                     std::to_string(design.size()) + "), given " + std::to_string(lower.size()) + " and " +
                     std::to_string(upper.size()));
  for (std::size_t i = 0; i < design.size(); ++i)
    if (!std::isfinite(lower[i]) || !std::isfinite(upper[i]) || !(lower[i] < upper[i]))
      throw InputError("Optimization/Lower Bounds, Upper Bounds: '" + design[i] + "' needs finite bounds, lower < " +
                       "upper; given [" + std::to_string(lower[i]) + ", " + std::to_string(upper[i]) + "]");
  if (objective.empty() == measured.empty())
    throw InputError("Optimization: give either an Objective (a response to minimize or maximize) or Measured "
                     "Responses (a misfit), not " + std::string(objective.empty() ? "neither" : "both"));
  if (!measured.empty()) {
    if (values.size() != measured.size())
      throw InputError("Optimization/Measured Values: one per Measured Response (" + std::to_string(measured.size()) +
                       "), given " + std::to_string(values.size()));
    if (errors.empty()) errors.assign(measured.size(), 1.0);
    if (errors.size() != measured.size())
      throw InputError("Optimization/Measurement Errors: one per Measured Response (" +
                       std::to_string(measured.size()) + ") or none, given " + std::to_string(errors.size()));
    for (std::size_t i = 0; i < measured.size(); ++i)
      if (!std::isfinite(values[i]) || !(errors[i] > 0.0) || !std::isfinite(errors[i]))
        throw InputError("Optimization: the measurement of '" + measured[i] + "' needs a finite value and an error > 0");
  }
  const ParameterList& responses = caseParams.sublist("Responses");
  std::vector<std::string> named = measured;
  if (!objective.empty()) named.push_back(objective);
  for (const std::string& name : named)
    if (!responses.isSublist(name))
      throw InputError("Optimization: '" + name + "' is not one of the case's Responses");
}

}  // namespace flowform
