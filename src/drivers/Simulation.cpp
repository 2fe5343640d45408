#include "flowform/drivers/Simulation.hpp"

#include <chrono>
#include <cmath>

#include "flowform/contact/WallStates.hpp"
#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/drivers/CaseParameters.hpp"
#include "flowform/drivers/OutputFields.hpp"
#include "flowform/estimation/CoarserMeshEstimate.hpp"
#include "flowform/estimation/EstimationMethods.hpp"
#include "flowform/io/BoundaryCsvWriter.hpp"
#include "flowform/io/JsonSummary.hpp"
#include "flowform/io/ResultDirectory.hpp"
#include "flowform/io/RunSummary.hpp"
#include "flowform/io/XdmfWriter.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/problem/EnergyBalance.hpp"
#include "flowform/sensitivity/BoundaryValuePartials.hpp"
#include "flowform/sensitivity/PerturbedSolve.hpp"

namespace flowform {

namespace {

using Teuchos::ParameterList;

/// The validated copy of a case (validateCase sets the defaults of its fixed sublists).
ParameterList validated(const ParameterList& caseParams) {
  ParameterList params(caseParams);
  validateCase(params);
  return params;
}

}  // namespace

Teuchos::RCP<const ParameterList> Simulation::validParameters() { return validCaseParameters(); }

CaseRunFactory Simulation::factory(const std::string& baseDir, const Teuchos::RCP<const Comm>& comm) {
  return [baseDir, comm](const ParameterList& caseParams, const SizeField* sizeField) -> std::unique_ptr<CaseRun> {
    return std::make_unique<Simulation>(caseParams, baseDir, comm, sizeField);
  };
}

Simulation::Simulation(const ParameterList& caseParams, const std::string& baseDir,
                       const Teuchos::RCP<const Comm>& comm, const SizeField* sizeField)
    : m_comm(comm), m_baseDir(baseDir), m_estimate(std::make_unique<ErrorEstimate>()) {
  const auto start = std::chrono::steady_clock::now();
  const ParameterList params = validated(caseParams);
  m_problem = std::make_unique<Problem>(params, physicsFromCase(params), baseDir, comm, sizeField);
  // Only a case with a Sensitivity sublist gets one: none means no work.
  const ParameterList& own = m_problem->parameters();
  m_sensitivity = std::make_unique<Sensitivity>(own.isSublist("Sensitivity") ? &own.sublist("Sensitivity") : nullptr,
                                                m_problem->contactWalls(), m_problem->responses(),
                                                m_problem->physics().material.law, givenGeoParameters(own),
                                                givenBoundaryValues(own),
                                                m_problem->dofMap().fields());
  m_sensitivity->checkMethod(!m_problem->boundaryConditions().rigidInflow().group.empty(),
                             !m_problem->freeSurfaces().empty());
  m_setupSeconds = secondsSince(start);
}

Simulation::~Simulation() = default;

void Simulation::solveCoarserLevelsFirst() {
  const ParameterList& estimation = parameters().sublist("Error Estimation");
  const std::string method = estimation.get<std::string>("Method");
  const bool adaptive = adaptivityRequested(parameters());
  const std::string used = adaptive ? adaptiveEstimationMethod(method) : method;
  if (used != CoarserMeshEstimate::kName || !estimation.get<bool>("Nested Start")) return;
  // The adaptive loop's indicators are wanted on every cycle but the last (free surfaces then
  // fall back to the two-level estimate: no levels to solve first).
  const int levels = CoarserMeshEstimate::levelsOf(*m_problem, adaptive);
  if (levels == 0) return;
  std::string failure;
  m_coarserLevels = CoarserMeshEstimate::solveLevels(*m_problem, levels, factory(m_baseDir, m_comm), failure,
                                                     m_levelSeconds);
  if (m_coarserLevels.empty()) {
    log() << "nested start: " << failure << "; the run solves from its own start, the estimate its levels after it\n";
    return;
  }
  m_problem->startFrom(m_coarserLevels.front()->problem());
  log() << "nested start: the coarser levels in " << m_levelSeconds << " s; the run starts from the finest\n";
}

const SolveReport& Simulation::run() {
  const auto start = std::chrono::steady_clock::now();
  solveCoarserLevelsFirst();
  const SolveReport& report = m_problem->solve();
  if (report.converged) m_functionals = m_problem->evaluateResponses(m_problem->solution());
  m_solveSeconds = secondsSince(start);
  if (report.converged)
    log() << "flowform: converged (" << report.newtonIterations << " Newton iterations, "
          << report.continuationStages << " stages, |F| = " << report.residualNorm << ")\n";
  else
    log() << "flowform: NOT CONVERGED: " << (budgetWasSpent() ? budgetMessage() : report.message) << "\n";
  if (report.converged && m_sensitivity->requested()) runSensitivity();
  // The adaptive loop estimates itself (with the indicators it needs).
  if (report.converged && exitStatus() == 0 && !adaptivityRequested(parameters()) &&
      parameters().sublist("Error Estimation").get<std::string>("Method") != "None")
    estimateErrors();
  return report;
}

void Simulation::estimateErrors(const std::vector<std::string>& indicatorResponses, const IndicatorsWanted& wanted) {
  // The case's method; the adaptive loop asks with Method = None too: then the registry's first.
  const int method = estimationMethodIndex(parameters().sublist("Error Estimation").get<std::string>("Method"));
  *m_estimate = flowform::estimateErrors(method < 0 ? 0 : method, *this, factory(m_baseDir, m_comm), indicatorResponses,
                                          wanted);
  if (!m_estimate->failure.empty()) {
    log() << "flowform: NO ERROR ESTIMATE: " << m_estimate->failure << "\n";
    return;
  }
  for (const auto& [name, eta] : m_estimate->functionals)
    log() << "flowform: " << name << " = " << m_functionals[name] << ", estimated error " << eta << " ("
          << 100.0 * std::abs(eta) / std::max(std::abs(m_functionals[name]), 1e-300) << " %)\n";
  for (const auto& [name, byParameter] : m_estimate->sensitivities)
    for (const auto& [parameter, eta] : byParameter)
      log() << "flowform: d" << name << "/d(" << parameter << ") estimated error " << eta << "\n";
  for (const auto& [name, byParameter] : m_estimate->sensitivitiesTotalShape)
    for (const auto& [parameter, eta] : byParameter)
      log() << "flowform: d" << name << "/d(" << parameter << ") through the free surfaces, estimated error " << eta
            << "\n";
  log() << "flowform: error estimate on the " << m_estimate->otherLevel << " mesh (" << m_estimate->refinedDofs << " dofs) in "
        << m_estimate->seconds << " s\n";
}

int Simulation::exitStatus() const {
  if (budgetWasSpent()) return 3;  // the run's wall-clock budget (core/Budget.hpp)
  if (!m_problem->report().converged || !m_notMet.empty() || !m_estimate->failure.empty()) return 3;
  if (m_sensitivity->requested() && !m_sensitivity->finite()) return 3;
  if (m_fdCheck && !m_fdCheck->allConverged()) return 3;
  return 0;
}

std::string Simulation::statusMessage() const {
  if (budgetWasSpent()) return budgetMessage();
  if (!m_notMet.empty()) return m_notMet;
  if (!m_estimate->failure.empty()) return "no error estimate: " + m_estimate->failure;
  if (!m_problem->report().converged) return m_problem->report().message;
  if (exitStatus() != 0)
    return !m_sensitivity->finite() ? "dq/dh is not finite (singular Jacobian?)"
                                    : "a finite-difference run of the sensitivity check did not converge";
  return m_problem->report().message;
}

void Simulation::runSensitivity() {
  const auto start = std::chrono::steady_clock::now();
  Problem& p = *m_problem;
  const std::optional<RigidInflowLinearization> inflow = p.rigidInflowLinearization();
  const GeoPartialsSource geo = geoPartialsOf(p);
  m_sensitivity->compute(p.model(), p.solution(), p.responses(), p.mesh(), p.dofMap(), p.contactWalls(),
                         inflow ? &*inflow : nullptr, &geo);
  if (!p.freeSurfaces().empty() && m_sensitivity->totalShapeRequested() && m_sensitivity->finite()) {
    m_shapeDerivative = totalShapeDerivative(p, *m_sensitivity);
    if (m_shapeDerivative.computed) m_sensitivity->setTotalShapeDerivatives(m_shapeDerivative.responses);
    else log() << "sensitivity: no total derivative through the free surfaces: " << m_shapeDerivative.failure << "\n";
  }
  m_sensitivitySeconds = secondsSince(start);
  if (!m_deferCheck) checkSensitivities();
}

void Simulation::checkSensitivities() {
  if (budgetWasSpent()) return;  // the run ends (core/Budget.hpp)
  if (!m_sensitivity->checkRequested() || !m_sensitivity->computed() || !m_sensitivity->finite()) return;
  const auto start = std::chrono::steady_clock::now();
  Problem& p = *m_problem;
  PerturbedRun base;
  base.converged = true;
  base.x = p.solutionPtr();
  base.functionals = m_functionals;
  base.states = wallStates(p.contactWalls(), p.dofMap(), p.solution());
  const bool holdScales = m_sensitivity->holdScalesInCheck();
  m_fdCheck = std::make_unique<FiniteDifferenceCheck>(
      *m_sensitivity, base, p.physics(), p.contactWalls(), p.mesh(), p.dofMap(),
      [&p, holdScales](const SensitivityParameter& h, double delta) { return solvePerturbed(p, h, delta, holdScales); });
  m_sensitivitySeconds += secondsSince(start);
}

FieldSet Simulation::gatherFields() const {
  return gatherOutputFields(m_problem->assembler(), m_problem->solution(), m_problem->contactWalls(), *m_sensitivity,
                            m_fdCheck.get(),
                            parameters().sublist("Output").get<Teuchos::Array<std::string>>("Cell Fields"));
}

void Simulation::writeOutput(const std::string& outDir) const {
  const auto start = std::chrono::steady_clock::now();
  const ParameterList& output = parameters().sublist("Output");
  const Mesh& mesh = m_problem->mesh();
  const FieldSet fields = gatherFields();
  // Where the heat goes (a case with a Temperature field; problem/EnergyBalance.hpp): on every
  // rank, its sums are collective.
  nlohmann::json extra = m_extraSummary;
  if (m_problem->dofMap().fields().contains(kTemperatureField)) energyBalance(*m_problem).report(extra);
  if (m_comm->getRank() != 0) return;
  ResultSet result(outDir);  // written whole, then put in place (io/ResultDirectory.hpp)
  const std::string& dir = result.stagingPath();

  if (output.get<bool>("Write Solution")) writeXdmf(dir, "solution", mesh, fields);
  if (output.get<bool>("Boundary CSV"))
    for (const auto& group : mesh.boundaries) {
      try {
        writeBoundaryCsv(dir, mesh, buildBoundaryCurve(mesh, group), fields);
      } catch (const std::exception& e) {  // a group that is not one simple curve, or an odd name
        log() << "flowform: no CSV for boundary group '" << group.name << "': " << e.what() << "\n";
      }
    }

  RunRecord record;
  record.exitStatus = exitStatus();
  record.message = statusMessage();
  record.functionals = &m_functionals;
  record.estimate = m_estimate.get();
  record.sensitivity = m_sensitivity.get();
  record.fdCheck = m_fdCheck.get();
  record.shapeDerivative = &m_shapeDerivative;
  record.setupSeconds = m_setupSeconds;
  record.solveSeconds = m_solveSeconds;
  record.coarserLevelSeconds = m_levelSeconds;
  record.sensitivitySeconds = m_sensitivitySeconds;
  record.extra = &extra;
  writeJsonFile(dir + "/summary.json", runSummary(*m_problem, record, start));
  result.publish();
}

}  // namespace flowform
