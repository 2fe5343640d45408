#include "flowform/optimization/OptimizationSettings.hpp"

#include <algorithm>
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
  valid->set("Constrained Responses", Array<std::string>(),
             "responses held within bounds (constraints, docs/optimization.md §1): each between its Constraint "
             "Lower Bound and Constraint Upper Bound");
  valid->set("Constraint Lower Bounds", Array<double>(),
             "one per Constrained Response, or none (no lower bounds); a value at or below -1e30 means none");
  valid->set("Constraint Upper Bounds", Array<double>(),
             "one per Constrained Response, or none (no upper bounds); a value at or above 1e30 means none");
  valid->set("Constraint Tolerance", 1e-3,
             "a constraint counts as met when its response lies within its bounds to this fraction of the bound's "
             "magnitude (scaled constraint violation; the optimizer's feasibility tolerance)",
             inRange(1e-12, 1.0));
  Teuchos::setStringToIntegralParameter<int>(
      "Constraint Algorithm", "Trust Region SQP",
      "with Constrained Responses: Trust Region SQP (an S-l1-QP, one solve per iteration, its subproblems dense QPs "
      "that need no solve, docs/optimization.md section 1.1), or one of ROL's own algorithms for general "
      "constraints (each of their subproblems solved by the Algorithm on the design's bounds; on the shipped "
      "decisions they took many more solves and stopped infeasible)",
      Teuchos::tuple<std::string>("Trust Region SQP", "Augmented Lagrangian", "Stabilized LCL", "Moreau-Yosida",
                                  "Interior Point"),
      valid.get());
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
  constrained = vectorOf<std::string>(list, "Constrained Responses");
  constraintLower = vectorOf<double>(list, "Constraint Lower Bounds");
  constraintUpper = vectorOf<double>(list, "Constraint Upper Bounds");
  constraintTolerance = list.get<double>("Constraint Tolerance");
  constraintAlgorithm = list.get<std::string>("Constraint Algorithm");
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
  // Constraints: a missing side is ±infinity; a bound beyond ±1e30 is none (Teuchos arrays hold no inf).
  for (auto* bounds : {&constraintLower, &constraintUpper}) {
    const bool lowerSide = bounds == &constraintLower;
    if (bounds->empty()) bounds->assign(constrained.size(), lowerSide ? -kNoBound : kNoBound);
    if (bounds->size() != constrained.size())
      throw InputError(std::string("Optimization/Constraint ") + (lowerSide ? "Lower" : "Upper") +
                       " Bounds: one per Constrained Response (" + std::to_string(constrained.size()) +
                       ") or none, given " + std::to_string(bounds->size()));
    for (double& b : *bounds)
      if (std::isnan(b) || std::abs(b) >= 1e30) b = (lowerSide ? -1.0 : 1.0) * kNoBound;
  }
  for (std::size_t i = 0; i < constrained.size(); ++i) {
    const bool hasLower = constraintLower[i] > -kNoBound, hasUpper = constraintUpper[i] < kNoBound;
    if (!hasLower && !hasUpper)
      throw InputError("Optimization/Constrained Responses: '" + constrained[i] +
                       "' has neither a lower nor an upper bound (Constraint Lower Bounds, Constraint Upper Bounds)");
    if (hasLower && hasUpper && !(constraintLower[i] < constraintUpper[i]))
      throw InputError("Optimization: the constraint on '" + constrained[i] + "' needs its lower bound " +
                       std::to_string(constraintLower[i]) + " below its upper bound " +
                       std::to_string(constraintUpper[i]));
    for (std::size_t j = 0; j < i; ++j)
      if (constrained[j] == constrained[i])
        throw InputError("Optimization/Constrained Responses: '" + constrained[i] +
                         "' is named twice; give it both bounds once");
  }
  const ParameterList& responses = caseParams.sublist("Responses");
  for (const std::string& name : responsesRead())
    if (!responses.isSublist(name))
      throw InputError("Optimization: '" + name + "' is not one of the case's Responses");
}

std::vector<std::string> OptimizationSettings::responsesRead() const {
  std::vector<std::string> names = isMisfit() ? measured : std::vector<std::string>{objective};
  for (const std::string& name : constrained)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

}  // namespace flowform
