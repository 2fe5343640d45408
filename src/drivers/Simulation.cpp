#include "flowform/drivers/Simulation.hpp"

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include <Teuchos_TimeMonitor.hpp>
#include <nlohmann/json.hpp>

#include "flowform/contact/ToolCorners.hpp"
#include "flowform/contact/WallStates.hpp"
#include "flowform/core/Budget.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/drivers/CaseParameters.hpp"
#include "flowform/drivers/OutputFields.hpp"
#include "flowform/drivers/UpdateLinearization.hpp"
#include "flowform/io/BoundaryCsvWriter.hpp"
#include "flowform/io/JsonSummary.hpp"
#include "flowform/io/ResultDirectory.hpp"
#include "flowform/io/XdmfWriter.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/mesh/MeshReader.hpp"
#include "flowform/solvers/LinearSolverRegistry.hpp"

namespace flowform {

namespace {

using Teuchos::ParameterList;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double timerSeconds(const std::string& name) {
  auto t = Teuchos::TimeMonitor::lookupCounter(name);
  return t.is_null() ? 0.0 : t->totalElapsedTime();
}

}  // namespace

Teuchos::RCP<const ParameterList> Simulation::validParameters() { return validCaseParameters(); }

Simulation::Simulation(const ParameterList& caseParams, const std::string& baseDir,
                       const Teuchos::RCP<const Comm>& comm, const SizeField* sizeField)
    : m_params(caseParams), m_comm(comm), m_estimate(std::make_unique<ErrorEstimate>()), m_baseDir(baseDir) {
  const auto start = std::chrono::steady_clock::now();
  validateCase(m_params);
  m_physics = physicsFromCase(m_params);
  if (sizeField) m_sizeField = *sizeField;

  m_mesh = readMesh(m_params.sublist("Mesh"), baseDir, *comm, sizeField);
  m_madeCoords = m_mesh.coords;
  if (m_physics.kernel.geometry == Geometry::Axisymmetric)
    for (const auto& xy : m_mesh.coords)
      if (xy[0] < -1e-12)
        throw InputError("Problem/Geometry is Axisymmetric but mesh '" + m_mesh.source +
                         "' has nodes at x = r < 0; the axis is x = 0 and the section must lie in x >= 0");

  // Contact walls first: the friction law couples wall neighbours, which the DofMap must know.
  const ParameterList& bcList = m_params.sublist("Boundary Conditions");
  m_walls = contactWallsFromCase(bcList, m_mesh, m_physics.kernel.geometry);
  std::vector<std::array<GO, 2>> couplings;
  for (const ContactWall& wall : m_walls) {
    const auto pairs = wall.couplings();
    couplings.insert(couplings.end(), pairs.begin(), pairs.end());
  }
  m_responses = std::make_unique<Responses>(m_params.sublist("Responses"), m_mesh);
  m_responses->checkWalls(m_walls);
  // Only a case with a Sensitivity sublist gets one: none means no work.
  m_sensitivity = std::make_unique<Sensitivity>(
      m_params.isSublist("Sensitivity") ? &m_params.sublist("Sensitivity") : nullptr, m_walls, *m_responses,
      m_physics.material.law);

  m_dofMap = std::make_unique<DofMap>(m_mesh, comm, couplings);
  m_bcs = std::make_unique<BoundaryConditions>(bcList, m_mesh, *m_dofMap);
  m_assembler = std::make_unique<Assembler>(m_mesh, *m_dofMap, *m_bcs);
  m_assembler->setPhysics(m_physics);
  if (!m_walls.empty()) m_assembler->setContactWalls(&m_walls);
  m_model = std::make_unique<FlowModel>(
      *m_assembler, createLinearSolver(m_params.sublist("Solver").sublist("Linear Solver"), *comm));
  m_statusLoop = std::make_unique<ContactStatusLoop>(m_params.sublist("Contact"), m_mesh, *m_dofMap);
  // A wall whose released nodes are a free surface: its separation point may cycle until the
  // surface has settled; a node that still cycles then decides by itself (ContactWall), and the
  // free-surface loop does not converge while any other cycles.
  for (const ContactWall& wall : m_walls) if (wall.releasedFreeSurface()) m_statusLoop->tolerateCycling(true);
  m_freeSurfaces = std::make_unique<FreeSurfaces>(bcList, m_mesh, m_walls);
  if (m_freeSurfaces->empty() && !m_bcs->heldGroups().empty())
    throw InputError("Boundary Conditions/" + m_bcs->heldGroups().front() +
                     ": 'Release After Free Surfaces' needs free surfaces, and the case has none");
  m_solution = Teuchos::rcp(new Vector(m_dofMap->ownedMap()));
  m_bcs->imposeOnSolution(*m_solution);
  m_setupSeconds = secondsSince(start);
}

Simulation::~Simulation() = default;

NonlinearSolver Simulation::newtonSolver(bool refreshScales) {
  NonlinearSolver solver(*m_model, m_params.sublist("Solver"));
  if (refreshScales && !m_walls.empty()) solver.setBeforeNewton([this](const Vector& x) { updateWallScales(x); });
  return solver;
}

const SolveReport& Simulation::run() {
  const auto start = std::chrono::steady_clock::now();
  log() << "flowform: " << m_mesh.numNodes() << " nodes, " << m_mesh.numCells() << " "
        << cellTypeName(m_mesh.cellType) << " cells, " << m_dofMap->ownedMap()->getGlobalNumElements()
        << " dofs, " << m_comm->getSize() << " rank(s)\n";
  NonlinearSolver solver = newtonSolver(true);
  if (!m_walls.empty()) updateWallScales(*m_solution);
  // The zero start puts every wall node at the kink of its friction law, and the predictor then
  // sees frictionless walls. Where friction dominates (ν ≳ 1) that start can fail, so with walls
  // it is tried with at most kFirstTryHalvings continuation halvings, then from walls that stick
  // at rest (FrictionSettings::stickAtRest), then from frictionless walls with every halving the
  // case allows (docs/contact.md).
  const Vector initial(*m_solution, Teuchos::Copy);
  const double caseMinimum = m_params.sublist("Solver").sublist("Continuation").get<double>("Minimum Step");
  const double firstMinimum = m_walls.empty() ? 0.0 : std::max(caseMinimum, std::ldexp(1.0, -kFirstTryHalvings));
  // From another mesh's converged state (startFrom): Newton at the target from there; resolve()
  // falls back to the predictor and the continuation itself if that fails.
  m_report = m_warmStart ? solver.resolve(*m_solution, m_physics) : solver.solve(*m_solution, m_physics, firstMinimum);
  auto again = [&](bool stick, const char* how) {
    log() << "flowform: the first solve failed (" << m_report.message << "); solving again " << how << "\n";
    Tpetra::deep_copy(*m_solution, initial);
    for (ContactWall& wall : m_walls) wall.setStickAtRest(stick);
    updateWallScales(*m_solution);
    SolveReport next = solver.solve(*m_solution, m_physics);
    for (ContactWall& wall : m_walls) wall.setStickAtRest(false);
    next.newtonIterations += m_report.newtonIterations;
    next.restarts = m_report.restarts + 1;
    m_report = next;
  };
  if (!m_report.converged && !m_walls.empty() && !budgetWasSpent()) again(true, "from walls that stick at rest");
  if (!m_report.converged && !m_walls.empty() && firstMinimum > caseMinimum && !budgetWasSpent())
    again(false, "from frictionless walls with every continuation halving");
  m_report.newtonPerSolve = {m_report.newtonIterations};
  if (!m_report.converged && !m_walls.empty() && !budgetWasSpent()) m_report.message += firstSolveHints();
  if (m_report.converged && !m_walls.empty())
    m_contactChanges = m_statusLoop->run(solver, *m_solution, m_physics, m_walls, m_report);
  if (m_report.converged && !m_freeSurfaces->empty()) {
    loopFreeSurfaces(solver, {m_report.unsettledContacts, m_report.unsettledContactRatio}, "");
    if (m_report.converged && m_bcs->releaseHeld(m_mesh)) releaseHeldAndGoOn(solver);
  }
  if (m_report.converged)
    m_functionals = m_responses->evaluate(*m_solution, m_mesh, *m_dofMap, *m_assembler, m_walls);
  m_solveSeconds = secondsSince(start);
  if (m_report.converged)
    log() << "flowform: converged (" << m_report.newtonIterations << " Newton iterations, "
          << m_report.continuationStages << " stages, |F| = " << m_report.residualNorm << ")\n";
  else
    log() << "flowform: NOT CONVERGED: " << (budgetWasSpent() ? budgetMessage() : m_report.message) << "\n";
  if (m_report.converged && m_sensitivity->requested()) runSensitivity();
  // The adaptive loop estimates itself (with the indicators it needs).
  if (m_report.converged && exitStatus() == 0 && !adaptivityRequested(m_params) &&
      m_params.sublist("Error Estimation").get<std::string>("Method") == "Two-Level")
    estimateErrors();
  return m_report;
}

std::string Simulation::firstSolveHints() const {
  // Measured on xml/extrusion.xml at ν = 2 on every wall (docs/theory.md §5, "Not-converged messages"): Tresca with m = 1 and
  // h = 0.05 converged; a smaller Minimum Step, 150 Newton iterations, the Exact linearization did not.
  double nu = 0.0;
  std::string coulomb;
  for (const ContactWall& wall : m_walls)
    if (wall.usesFrictionCoefficient() && wall.settings().frictionCoefficient > nu) {
      nu = wall.settings().frictionCoefficient;
      coulomb = wall.name();
    }
  std::string hints = ". The first solve failed from each start (zero, walls sticking at rest, frictionless walls). To try: ";
  if (!coulomb.empty())
    hints += "a smaller Friction Coefficient (" + (std::ostringstream() << std::setprecision(3) << nu).str() +
             " on wall '" + coulomb +
             "'), or Friction Law = Tresca with a Shear Factor <= 1 (the friction stress bounded by the flow stress); ";
  return hints + "a finer mesh (Mesh/Geo Parameters, Mesh/Uniform Refinements). A smaller "
                 "Solver/Continuation/Minimum Step, more Solver/Max Newton Iterations or Newton Linearization = "
                 "Exact may not help (they did not at friction coefficient 2 on the extrusion)";
}

void Simulation::estimateErrors(const std::vector<std::string>& indicatorResponses) {
  *m_estimate = twoLevelEstimate(*this, indicatorResponses);
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
  log() << "flowform: error estimate on the refined mesh (" << m_estimate->refinedDofs << " dofs) in "
        << m_estimate->seconds << " s\n";
}

void Simulation::startFrom(const Simulation& other, bool decideZoneLimits) {
  // The other mesh's free surfaces moved: this mesh, as made, takes their shape first (carryShape),
  // and the groups it released after its first loop are released here from the start.
  if (other.m_mesh.coords != other.m_madeCoords)
    moveNodes(carryShape(other.meshAsMade(), other.mesh(), meshAsMade()));
  if (!other.m_bcs->releasedGroups().empty()) m_bcs->releaseHeld(m_mesh);
  interpolate(other.mesh(), other.dofMap(), replicate(other.solution(), other.dofMap()), m_mesh, *m_dofMap,
              *m_solution);
  m_bcs->imposeOnSolution(*m_solution);
  // Statuses carried over; a node inside an old zone limit is decided by whether it penetrates.
  const double penetrationTolerance = m_params.sublist("Contact").get<double>("Penetration Tolerance");
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (ContactWall& wall : m_walls)
    for (const ContactWall& from : other.contactWalls())
      if (from.name() == wall.name()) {
        if (decideZoneLimits) wallValues(wall, *m_dofMap, *m_solution, p, u);  // collective
        wall.takeStatusesFrom(from, decideZoneLimits ? &u : nullptr, penetrationTolerance);
      }
  if (!m_walls.empty()) updateWallScales(*m_solution);
  m_warmStart = true;
}

FreeSurfaceReport Simulation::convergeFreeSurfaces(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics,
                                                   std::pair<int, double> unsettledAtStart,
                                                   double toleranceScale) {
  FreeSurfaceLoop::Hooks hooks;
  std::pair<int, double> unsettled = unsettledAtStart;  // contact nodes the last solve left cycling
  hooks.velocities = [&] { return replicate(x, *m_dofMap); };
  hooks.moveNodes = [&](const std::vector<std::array<double, 2>>& coords) {
    moveNodes(coords);
    m_bcs->imposeOnSolution(x);
  };
  hooks.release = [&](int w, int k) {
    m_walls[w].setActive(k, false);
    log() << "contact: " << m_walls[w].name() << " node " << m_walls[w].curve().nodes[k]
          << " released: the separated surface passes below it\n";
  };
  hooks.newtonMoves = [&](const FreeSurfaceStep&, std::vector<std::array<double, 2>>& moves, std::string& why) {
    // The linearization reads the run's own state: a perturbed run's (x ≠ m_solution) has none.
    if (&x != m_solution.get()) {
      why = "not in a finite-difference run";
      return false;
    }
    const UpdateLinearization lin(*this, false);
    why = lin.failure();
    return why.empty() && lin.newtonMoves(moves);
  };
  hooks.resolve = [&](int& newton, int& changes, std::string& why) {
    // Each shape is a new contact problem: the per-node change counts start again (the loop's
    // own cap stops a shape and a status that chase each other).
    for (ContactWall& wall : m_walls) wall.resetChangeCounts();
    SolveReport r = solver.resolve(x, physics);
    if (r.converged && !m_walls.empty()) changes = m_statusLoop->run(solver, x, physics, m_walls, r);
    newton = r.newtonIterations;
    why = r.message;
    unsettled = {r.unsettledContacts, r.unsettledContactRatio};
    return r.converged;
  };
  hooks.unsettledContacts = [&] { return unsettled; };
  return FreeSurfaceLoop(*m_freeSurfaces, m_params.sublist("Free Surface"))
      .run(m_mesh, *m_dofMap, m_walls, physics.kernel.geometry, hooks, toleranceScale);
}

void Simulation::releaseHeldAndGoOn(NonlinearSolver& solver) {
  log() << "flowform: the groups held until the free surfaces converged are released; the loop goes on\n";
  m_model->invalidateJacobian();
  for (ContactWall& wall : m_walls) wall.resetChangeCounts();
  SolveReport r = solver.resolve(*m_solution, m_physics);
  if (r.converged && !m_walls.empty()) m_contactChanges += m_statusLoop->run(solver, *m_solution, m_physics, m_walls, r);
  m_report.newtonIterations += r.newtonIterations;
  if (!r.converged) {
    m_report.converged = false;
    m_report.message = "the flow with the held groups released did not converge: " + r.message;
    return;
  }
  const FreeSurfaceReport held = m_freeSurfaceReport;  // the loop with the groups held
  loopFreeSurfaces(solver, {r.unsettledContacts, r.unsettledContactRatio}, "after the held groups were released: ");
  m_freeSurfaceReport.continueFrom(held);
}

void Simulation::loopFreeSurfaces(NonlinearSolver& solver, std::pair<int, double> unsettledAtStart,
                                  const std::string& context) {
  m_freeSurfaceReport = convergeFreeSurfaces(solver, *m_solution, m_physics, unsettledAtStart);
  m_report.newtonIterations += m_freeSurfaceReport.newtonIterations;
  m_contactChanges += m_freeSurfaceReport.contactChanges;
  if (!m_freeSurfaceReport.converged) {
    m_report.converged = false;
    m_report.message = context + m_freeSurfaceReport.message;
  }
}

void Simulation::moveNodes(const std::vector<std::array<double, 2>>& coords) {
  m_mesh.setCoordinates(coords);
  for (ContactWall& wall : m_walls) wall.refreshGeometry(m_mesh);
  markConvexToolCorners(m_walls);
  m_bcs->refreshGeometry(m_mesh);
  m_bcs->imposeOnSolution(*m_solution);  // symmetry directions may have turned
  m_model->invalidateJacobian();
}

int Simulation::exitStatus() const {
  if (budgetWasSpent()) return 3;  // the run's wall-clock budget (core/Budget.hpp)
  if (!m_report.converged || !m_notMet.empty() || !m_estimate->failure.empty()) return 3;
  if (m_sensitivity->requested() && !m_sensitivity->finite()) return 3;
  if (m_fdCheck && !m_fdCheck->allConverged()) return 3;
  return 0;
}

std::string Simulation::statusMessage() const {
  if (budgetWasSpent()) return budgetMessage();
  if (!m_notMet.empty()) return m_notMet;
  if (!m_estimate->failure.empty()) return "no error estimate: " + m_estimate->failure;
  if (!m_report.converged) return m_report.message;
  if (exitStatus() != 0)
    return !m_sensitivity->finite() ? "dq/dh is not finite (singular Jacobian?)"
                                    : "a finite-difference run of the sensitivity check did not converge";
  return m_report.message;
}

void Simulation::runSensitivity() {
  const auto start = std::chrono::steady_clock::now();
  m_sensitivity->compute(*m_model, *m_solution, *m_responses, m_mesh, *m_dofMap, m_walls);
  if (!m_freeSurfaces->empty() && m_sensitivity->totalShapeRequested() && m_sensitivity->finite()) {
    m_shapeDerivative = totalShapeDerivative(*this);
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
  PerturbedRun base;
  base.converged = true;
  base.x = m_solution;
  base.functionals = m_functionals;
  base.states = wallStates(m_walls, *m_dofMap, *m_solution);
  m_fdCheck = std::make_unique<FiniteDifferenceCheck>(
      *m_sensitivity, base, m_physics, m_walls, m_mesh, *m_dofMap,
      [this](const SensitivityParameter& h, double delta) { return solvePerturbed(h, delta); });
  m_sensitivitySeconds += secondsSince(start);
}

PerturbedRun Simulation::solvePerturbed(const SensitivityParameter& h, double delta) {
  std::vector<ContactWall::State> saved;
  for (const ContactWall& wall : m_walls) saved.push_back(wall.state());
  FlowPhysics physics = m_physics;
  shiftParameter(h, delta, physics, m_walls);
  for (ContactWall& wall : m_walls) wall.resetChangeCounts();
  // Held scales (the default) keep the walls' μ_k and σ̄_k of the base run, the problem the
  // DDM differentiates; Recomputed takes them from the start state at h ± δ, as a solve does.
  NonlinearSolver solver = newtonSolver(!m_sensitivity->holdScalesInCheck());
  auto x = Teuchos::rcp(new Vector(*m_solution, Teuchos::Copy));
  PerturbedRun run;
  SolveReport report = solver.resolve(*x, physics);
  if (report.converged && !m_walls.empty()) run.contactChanges = m_statusLoop->run(solver, *x, physics, m_walls, report);
  // Nodes left cycling (a wall whose released nodes are free surfaces) are accepted when they only
  // graze the tool, as in the free-surface loop.
  const bool cycling = !FreeSurfaceLoop::settled({report.unsettledContacts, report.unsettledContactRatio});
  run.converged = report.converged && !cycling;
  run.message = cycling ? std::to_string(report.unsettledContacts) + " contact node(s) cycle on the frozen shape"
                        : report.message;
  run.newtonIterations = report.newtonIterations;
  run.x = x;
  if (run.converged) {
    run.functionals = m_responses->evaluate(*x, m_mesh, *m_dofMap, *m_assembler, m_walls);
    run.states = wallStates(m_walls, *m_dofMap, *x);
  }
  if (run.converged && !m_freeSurfaces->empty()) {
    // The same perturbation with the surfaces re-converged: the total derivative's difference.
    const std::vector<std::array<double, 2>> shape = m_mesh.coords;
    Vector moving(*x, Teuchos::Copy);
    const FreeSurfaceReport surfaces =
        convergeFreeSurfaces(solver, moving, physics, {report.unsettledContacts, report.unsettledContactRatio},
                             kFiniteDifferenceSurfaceTolerance);
    run.newtonIterations += surfaces.newtonIterations;
    if (surfaces.converged) {
      run.movingFunctionals = m_responses->evaluate(moving, m_mesh, *m_dofMap, *m_assembler, m_walls);
    } else {
      run.converged = false;
      run.message = "with re-converged free surfaces: " + surfaces.message;
    }
    moveNodes(shape);
  }
  for (size_t w = 0; w < m_walls.size(); ++w) m_walls[w].restore(saved[w]);
  m_model->setPhysics(m_physics);
  return run;
}

void Simulation::updateWallScales(const Vector& x) {
  std::vector<double> mu, sigma;
  m_assembler->nodalCellMaxima(x, mu, sigma);
  for (ContactWall& wall : m_walls) {
    std::vector<double> wallMu(wall.numNodes(), 0.0), wallSigma(wall.numNodes(), 0.0);
    for (int k = 0; k < wall.numNodes(); ++k) {
      const LO n = m_dofMap->overlapIndex(wall.curve().nodes[k]);
      if (n < 0) continue;  // neither this rank's node nor a neighbour of one: not used here
      const double fixed = wall.settings().penaltyViscosity;
      wallMu[k] = fixed > 0.0 ? fixed : mu[n];
      wallSigma[k] = sigma[n];
    }
    wall.setScales(std::move(wallMu), std::move(wallSigma));
  }
  m_model->invalidateJacobian();
}

FieldSet Simulation::gatherFields() const {
  return gatherOutputFields(*m_assembler, *m_solution, m_walls, *m_sensitivity, m_fdCheck.get(),
                            m_params.sublist("Output").get<Teuchos::Array<std::string>>("Cell Fields"));
}

void Simulation::writeOutput(const std::string& outDir) const {
  const auto start = std::chrono::steady_clock::now();
  const ParameterList& output = m_params.sublist("Output");
  const FieldSet fields = gatherFields();
  if (m_comm->getRank() != 0) return;
  ResultSet result(outDir);  // written whole, then put in place (io/ResultDirectory.hpp)
  const std::string& dir = result.stagingPath();

  if (output.get<bool>("Write Solution")) writeXdmf(dir, "solution", m_mesh, fields);
  if (output.get<bool>("Boundary CSV"))
    for (const auto& group : m_mesh.boundaries) {
      try {
        writeBoundaryCsv(dir, m_mesh, buildBoundaryCurve(m_mesh, group), fields);
      } catch (const std::exception& e) {  // a group that is not one simple curve, or an odd name
        log() << "flowform: no CSV for boundary group '" << group.name << "': " << e.what() << "\n";
      }
    }

  // Each piece reports its own part.
  nlohmann::json summary;
  m_report.report(summary);  // converged, message, newton_iterations, stages, ...
  if (budgetWasSpent()) summary["converged"] = false;  // the run was cut short (core/Budget.hpp)
  summary["exit_status"] = exitStatus();
  summary["contact_changes"] = m_contactChanges;
  summary["free_surface_iterations"] = 0;
  if (!m_freeSurfaces->empty()) {
    m_freeSurfaceReport.report(summary);  // and the "free_surface" block
    int selfDeciding = 0;
    for (const ContactWall& wall : m_walls) selfDeciding += wall.selfDecidingNodes();
    summary["free_surface"]["self_deciding_contacts"] = selfDeciding;
    summary["free_surface"]["released_groups"] = m_bcs->releasedGroups();
  }
  summary["dofs"] = m_dofMap->ownedMap()->getGlobalNumElements();
  summary["mesh"] = {{"file", m_mesh.source}, {"nodes", m_mesh.numNodes()}, {"cells", m_mesh.numCells()},
                     {"cell_type", cellTypeName(m_mesh.cellType)}};
  summary["ranks"] = m_comm->getSize();
  m_model->linearSolver().report(summary["linear_solver"]);
  summary["linear_solver"]["residuals"] = m_model->numResiduals();
  summary["linear_solver"]["jacobians"] = m_model->numJacobians();
  const double assemblyResidual = timerSeconds("flowform: assembly (residual)");
  const double assemblyJacobian = timerSeconds("flowform: assembly (Jacobian)");
  summary["timings"] = {{"total", m_setupSeconds + m_solveSeconds + m_sensitivitySeconds + m_estimate->seconds +
                                      secondsSince(start)},
                        {"setup", m_setupSeconds},
                        {"solve", m_solveSeconds},
                        {"assembly", assemblyResidual + assemblyJacobian},
                        {"assembly_residual", assemblyResidual},
                        {"assembly_jacobian", assemblyJacobian},
                        {"factorization", timerSeconds("flowform: factorization")},
                        {"linear_solve", timerSeconds("flowform: linear solve")},
                        {"sensitivity", m_sensitivitySeconds},
                        {"sensitivity_ddm", timerSeconds("flowform: sensitivity")},
                        {"finite_difference_check", timerSeconds("flowform: finite-difference check")},
                        {"error_estimation", m_estimate->seconds},
                        {"output", secondsSince(start)}};
  summary["functionals"] = nlohmann::json::object();
  for (const auto& [name, value] : m_functionals) summary["functionals"][name] = value;
  m_estimate->report(summary);  // functionals_error_estimate, ..., when estimated
  summary["fd_check"] = nlohmann::json::object();
  m_sensitivity->report(summary);  // "sensitivities", "sensitivity" (what it cost)
  summary["sensitivity"]["finite_difference"] = {{"runs", 0}};
  if (m_fdCheck) m_fdCheck->report(summary);  // "fd_check"
  if (!m_freeSurfaces->empty() && m_sensitivity->computed() && m_sensitivity->totalShapeRequested())
    m_shapeDerivative.report(summary);  // "sensitivities_total_shape", "shape_derivative"
  summary["message"] = statusMessage();
  for (const auto& [key, block] : m_extraSummary.items()) summary[key] = block;
  summary["parameters"] = parameterListToJson(m_params);
  writeJsonFile(dir + "/summary.json", summary);
  result.publish();
}

}  // namespace flowform
