// summary.json of a run: each piece reports its own part (the solve, the free-surface loop, the
// linear solver, the responses, the error estimate, the sensitivities and their check, the
// total shape derivative), with the mesh, the timings, the exit status and message, the blocks a
// driver adds (the adaptive loop's cycles) and every parameter of the case.
#pragma once

#include <chrono>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "flowform/estimation/ErrorEstimate.hpp"
#include "flowform/problem/Problem.hpp"
#include "flowform/sensitivity/FiniteDifferenceCheck.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"
#include "flowform/sensitivity/ShapeDerivative.hpp"

namespace flowform {

/// What a run computed on its problem, as the summary reports it.
struct RunRecord {
  int exitStatus = 0;
  std::string message;  ///< the summary's "message"
  const std::map<std::string, double>* functionals = nullptr;
  const ErrorEstimate* estimate = nullptr;
  const Sensitivity* sensitivity = nullptr;
  const FiniteDifferenceCheck* fdCheck = nullptr;  ///< none when the check was not run
  const ShapeDerivative* shapeDerivative = nullptr;
  double setupSeconds = 0.0, solveSeconds = 0.0, sensitivitySeconds = 0.0;
  /// Of solveSeconds: the coarser levels solved before the run (Error Estimation/Nested Start).
  double coarserLevelSeconds = 0.0;
  /// Blocks carried as they are, by key.
  const nlohmann::json* extra = nullptr;
};

/// The summary of `problem` solved and `record`; `outputStart` is when writing the output began
/// (its time is the summary's timings/output).
nlohmann::json runSummary(const Problem& problem, const RunRecord& record,
                          std::chrono::steady_clock::time_point outputStart);

}  // namespace flowform
