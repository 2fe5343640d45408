// The case's Optimization sublist (docs/optimization.md): what the optimizer moves (design
// parameters with bounds), what it minimizes (a response, or a least-squares misfit to measured
// values), how (ROL's algorithm and tolerances). No sublist: nothing of this runs.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace flowform {

struct OptimizationSettings {
  /// The sublist's entries with their documentation and validators.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// Reads and checks the validated case's sublist (InputError naming the entry): bounds one per
  /// design parameter, finite, lower < upper; either an Objective or Measured Responses with as
  /// many values (and errors, > 0); every named response one of the case's Responses.
  explicit OptimizationSettings(const Teuchos::ParameterList& caseParams);

  std::vector<std::string> design;
  std::vector<double> lower, upper;
  std::string objective;   ///< a response to minimize or maximize, or empty (a misfit)
  bool maximize = false;
  std::vector<std::string> measured;  ///< the misfit's responses
  std::vector<double> values, errors;  ///< their measured values and standard errors
  /// Constraints: lower_i <= phi_i <= upper_i; a side without a bound holds ∓kNoBound.
  static constexpr double kNoBound = std::numeric_limits<double>::infinity();
  std::vector<std::string> constrained;
  std::vector<double> constraintLower, constraintUpper;
  double constraintTolerance = 1e-3;
  std::string constraintAlgorithm;  ///< ROL's TypeG algorithm ("Augmented Lagrangian", ...)
  std::string algorithm;  ///< "Trust Region" or "Line Search" (a constrained problem's subproblems)
  double gradientTolerance = 1e-6, stepTolerance = 1e-8, initialRadius = 1.0;
  int iterationLimit = 30;
  bool warmStart = true;
  int remeshingCycles = 3;

  bool isMisfit() const { return objective.empty(); }
  bool isConstrained() const { return !constrained.empty(); }
  /// Every response the objective and the constraints read (what each solve differentiates).
  std::vector<std::string> responsesRead() const;
};

/// Whether the case has an Optimization sublist.
bool optimizationRequested(const Teuchos::ParameterList& params);

}  // namespace flowform
