// One flowform run, the driver: it validates the case, makes the problem (problem/Problem: the
// mesh, the discretization, the walls, the free surfaces, the model, the solution), has it
// solved, then computes what the case asks on the converged state — the responses, the
// sensitivities (sensitivity/) with their total shape derivative and finite-difference check, the
// error estimate (estimation/) — and writes the results (io/). It holds no algorithm of its own.
// main.cpp is a command-line layer over this; tests drive it too.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <nlohmann/json.hpp>

#include "flowform/estimation/CaseRun.hpp"
#include "flowform/estimation/ErrorEstimate.hpp"
#include "flowform/io/FieldSet.hpp"
#include "flowform/mesh/SizeField.hpp"
#include "flowform/problem/Problem.hpp"
#include "flowform/sensitivity/FiniteDifferenceCheck.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"
#include "flowform/sensitivity/ShapeDerivative.hpp"

namespace flowform {

class Simulation final : public CaseRun {
 public:
  /// Every parameter a case may have, with doc strings and validators (`--help` prints it).
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// Makes Simulations of cases whose relative paths are against `baseDir` (the adaptive loop's
  /// cycles, the two-level estimate's refined run).
  static CaseRunFactory factory(const std::string& baseDir, const Teuchos::RCP<const Comm>& comm);

  /// Validates `caseParams` (InputError naming the parameter and the allowed ones) and makes the
  /// problem: reads the mesh (relative paths against `baseDir`), builds maps, conditions and the
  /// model. Nothing is written.
  /// `sizeField`: mesh the case's .geo with these sizes instead of its own (the adaptive loop).
  Simulation(const Teuchos::ParameterList& caseParams, const std::string& baseDir,
             const Teuchos::RCP<const Comm>& comm, const SizeField* sizeField = nullptr);
  ~Simulation() override;

  /// Solves the problem (Problem::solve: the flow with its contact-status loop and, when the case
  /// has free surfaces, the free-surface loop), evaluates the responses, then, when the case asks,
  /// the sensitivities (DDM, on the converged shape), their finite-difference check and the error
  /// estimate. The report says whether the flow solve converged.
  const SolveReport& run() override;

  /// summary.json, solution.h5/.xdmf and the boundary CSVs in `outDir` (created).
  void writeOutput(const std::string& outDir) const override;

  /// The state of the solve: mesh, dof map, walls, free surfaces, model, solution, report.
  Problem& problem() override { return *m_problem; }
  const Problem& problem() const override { return *m_problem; }
  const Teuchos::ParameterList& parameters() const { return m_problem->parameters(); }
  /// The error estimate of the responses (its `estimated` false when none was made).
  const ErrorEstimate& errorEstimate() const override { return *m_estimate; }
  /// The coarser levels run() solved before the problem (Error Estimation/Nested Start), the
  /// finer first, until the estimate takes them.
  std::vector<std::unique_ptr<CaseRun>>& coarserLevels() override { return m_coarserLevels; }
  /// Estimates the responses' errors now (by the case's Error Estimation/Method, the registry's first when
  /// None: estimation/EstimationMethods.hpp), with nodal indicators for
  /// `indicatorResponses` (the adaptive loop's targets). run() calls it when the case's
  /// Error Estimation/Method asks.
  void estimateErrors(const std::vector<std::string>& indicatorResponses = {},
                      const IndicatorsWanted& wanted = {}) override;
  /// The run met its numbers but not what was asked of it (the adaptive loop's target): exit
  /// status 3 with `why` as the summary's message.
  void setNotMet(const std::string& why) override { m_notMet = why; }
  /// run() computes the DDM sensitivities but leaves their finite-difference check to a later
  /// checkSensitivities() (the adaptive loop checks the last cycle's only).
  void deferFiniteDifferenceCheck() override { m_deferCheck = true; }
  /// The finite-difference check of the computed sensitivities, when the case asks for it.
  void checkSensitivities() override;
  /// A block the summary carries as it is under `key` (the adaptive loop's cycles).
  void addSummaryBlock(const std::string& key, const nlohmann::json& block) override { m_extraSummary[key] = block; }
  /// 0; 3 when the flow solve did not converge, dq/dh is not finite, or a run of the
  /// finite-difference check did not converge (the results are written all the same).
  int exitStatus() const override;
  /// Why the run is not converged (summary.json "message", and stderr at exit 3); the
  /// solve's message (empty) when it is.
  std::string statusMessage() const override;
  /// The case's responses at the current solution (empty before run()).
  const std::map<std::string, double>& functionals() const override { return m_functionals; }
  const Sensitivity& sensitivity() const override { return *m_sensitivity; }
  /// The total derivatives through the moving free surfaces (computed false when not made).
  const ShapeDerivative& shapeDerivative() const override { return m_shapeDerivative; }

  /// Nodal velocity and pressure, and the cell fields the case asks for, gathered on rank 0
  /// (other ranks get empty arrays).
  FieldSet gatherFields() const;

 private:
  /// DDM sensitivities at the converged solution and, when asked, their FD check.
  void runSensitivity();
  /// Nested iteration before the solve, when the case's estimate is the coarser mesh's and asks
  /// for it: the levels solved coarse to fine, the problem started from the finest.
  void solveCoarserLevelsFirst();

  Teuchos::RCP<const Comm> m_comm;
  std::string m_baseDir;
  std::unique_ptr<Problem> m_problem;
  std::unique_ptr<Sensitivity> m_sensitivity;
  std::unique_ptr<FiniteDifferenceCheck> m_fdCheck;
  std::map<std::string, double> m_functionals;
  std::unique_ptr<ErrorEstimate> m_estimate;
  bool m_deferCheck = false;  ///< run() leaves the FD check to checkSensitivities()
  std::string m_notMet;       ///< why the run did not meet what was asked (setNotMet), or empty
  nlohmann::json m_extraSummary = nlohmann::json::object();
  ShapeDerivative m_shapeDerivative;  ///< derivatives through the moving surfaces, when made
  std::vector<std::unique_ptr<CaseRun>> m_coarserLevels;  ///< solveCoarserLevelsFirst()'s, finer first
  double m_levelSeconds = 0.0;  ///< their time (part of the solve's)
  double m_setupSeconds = 0.0;
  double m_solveSeconds = 0.0;
  double m_sensitivitySeconds = 0.0;
};

}  // namespace flowform
