// A run of a case as the two-level estimate and the adaptive loop see it: its problem (the state
// of the solve), what was computed on it, and what the loop asks of it. The driver
// (drivers/Simulation) is the one implementation; through this interface estimation/ makes and
// runs cases (a refined mesh, the next cycle's mesh) without reaching up to the driver.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <nlohmann/json.hpp>

#include "flowform/estimation/ErrorEstimate.hpp"
#include "flowform/mesh/SizeField.hpp"
#include "flowform/problem/Problem.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"
#include "flowform/sensitivity/ShapeDerivative.hpp"

namespace flowform {

class CaseRun {
 public:
  virtual ~CaseRun() = default;

  /// Solves the problem, then what the case asks after it (sensitivities, their check, the
  /// error estimate); the report says whether the flow solve converged.
  virtual const SolveReport& run() = 0;
  /// 0, or 3 when the run did not converge or did not meet what was asked of it.
  virtual int exitStatus() const = 0;
  /// Why the run is not converged, or the solve's message.
  virtual std::string statusMessage() const = 0;

  virtual Problem& problem() = 0;
  virtual const Problem& problem() const = 0;
  /// The case's responses at the converged solution (empty before run()).
  virtual const std::map<std::string, double>& functionals() const = 0;
  virtual const Sensitivity& sensitivity() const = 0;
  /// The total derivatives through the moving free surfaces (computed false when not made).
  virtual const ShapeDerivative& shapeDerivative() const = 0;
  /// The error estimate of the responses (its `estimated` false when none was made).
  virtual const ErrorEstimate& errorEstimate() const = 0;
  /// The case on the meshes one and two refinements coarser, solved before this run and its
  /// start (CoarserMeshEstimate::solveLevels, Error Estimation/Nested Start), the finer first;
  /// empty when the run was not started that way. The coarser-mesh estimate takes them.
  virtual std::vector<std::unique_ptr<CaseRun>>& coarserLevels() = 0;

  /// Estimates the responses' errors now, with nodal indicators for `indicatorResponses` (a
  /// method that can decide after the estimate asks `wanted` first).
  virtual void estimateErrors(const std::vector<std::string>& indicatorResponses = {},
                              const IndicatorsWanted& wanted = {}) = 0;
  /// run() computes the DDM sensitivities but leaves their finite-difference check to a later
  /// checkSensitivities().
  virtual void deferFiniteDifferenceCheck() = 0;
  virtual void checkSensitivities() = 0;
  /// The run met its numbers but not what was asked of it: exit status 3 with `why`.
  virtual void setNotMet(const std::string& why) = 0;
  /// A block the summary carries as it is under `key`.
  virtual void addSummaryBlock(const std::string& key, const nlohmann::json& block) = 0;
  /// The results (summary.json, fields) in `outDir`.
  virtual void writeOutput(const std::string& outDir) const = 0;
};

/// Makes a run of the validated case `caseParams`, meshed with `sizeField` (nullptr: the
/// case's own sizes).
using CaseRunFactory =
    std::function<std::unique_ptr<CaseRun>(const Teuchos::ParameterList& caseParams, const SizeField* sizeField)>;

}  // namespace flowform
