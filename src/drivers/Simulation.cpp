#include "flowform/Simulation.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <nlohmann/json.hpp>

#include "flowform/BoundaryCurve.hpp"
#include "flowform/CaseParameters.hpp"
#include "flowform/InputError.hpp"
#include "flowform/Log.hpp"
#include "flowform/MeshReader.hpp"
#include "flowform/contact/ToolCorners.hpp"
#include "flowform/io/BoundaryCsvWriter.hpp"
#include "flowform/io/JsonSummary.hpp"
#include "flowform/io/XdmfWriter.hpp"

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
                       const Teuchos::RCP<const Comm>& comm)
    : m_params(caseParams), m_comm(comm) {
  const auto start = std::chrono::steady_clock::now();
  validateCase(m_params);
  const ParameterList& mat = m_params.sublist("Material");
  m_physics.material = {mat.get<double>("Yield Stress"), mat.get<double>("Rate Constant"),
                        mat.get<double>("Rate Exponent"), mat.get<double>("Strain Rate Cutoff")};
  const ParameterList& problem = m_params.sublist("Problem");
  m_physics.kernel.geometry =
      problem.get<std::string>("Geometry") == "Axisymmetric" ? Geometry::Axisymmetric : Geometry::PlaneStrain;
  m_physics.kernel.bodyForce[0] = problem.get<double>("Body Force X");
  m_physics.kernel.bodyForce[1] = problem.get<double>("Body Force Y");
  m_physics.kernel.beta = m_params.sublist("Stabilization").get<double>("Beta");

  m_mesh = readMesh(m_params.sublist("Mesh"), baseDir, *comm);
  if (m_physics.kernel.geometry == Geometry::Axisymmetric)
    for (const auto& xy : m_mesh.coords)
      if (xy[0] < -1e-12)
        throw InputError("Problem/Geometry is Axisymmetric but mesh '" + m_mesh.source +
                         "' has nodes at x = r < 0; the axis is x = 0 and the section must lie in x >= 0");

  // Contact walls first: the friction law couples wall neighbours, which the DofMap must know.
  const ParameterList& bcList = m_params.sublist("Boundary Conditions");
  std::vector<std::array<GO, 2>> couplings;
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name)) continue;  // BoundaryConditions reports it
    const ParameterList& group = bcList.sublist(name);
    if (!group.isType<std::string>("Type") || group.get<std::string>("Type") != "Contact Wall") continue;
    if (!m_mesh.hasBoundary(name))
      throw InputError("Boundary Conditions/" + name + ": mesh '" + m_mesh.source +
                       "' has no boundary group of that name; it has: " + m_mesh.boundaryNames());
    m_walls.emplace_back(name, group, m_mesh, m_physics.kernel.geometry);
    const auto pairs = m_walls.back().couplings();
    couplings.insert(couplings.end(), pairs.begin(), pairs.end());
  }
  markConvexToolCorners(m_walls);
  m_responses = std::make_unique<Responses>(m_params.sublist("Responses"), m_mesh);
  // Only a case with a Sensitivity sublist gets one: none means no work.
  m_sensitivity = std::make_unique<Sensitivity>(
      m_params.isSublist("Sensitivity") ? &m_params.sublist("Sensitivity") : nullptr, m_walls, *m_responses);

  m_dofMap = std::make_unique<DofMap>(m_mesh, comm, couplings);
  m_bcs = std::make_unique<BoundaryConditions>(bcList, m_mesh, *m_dofMap);
  m_assembler = std::make_unique<Assembler>(m_mesh, *m_dofMap, *m_bcs);
  m_assembler->setPhysics(m_physics);
  if (!m_walls.empty()) m_assembler->setContactWalls(&m_walls);
  m_model = std::make_unique<FlowModel>(*m_assembler, Teuchos::getIntegralValue<LinearSolver::Ordering>(
                                                          m_params.sublist("Solver").sublist("Linear Solver"), "Ordering"));
  m_statusLoop = std::make_unique<ContactStatusLoop>(m_params.sublist("Contact"), m_mesh, *m_dofMap);
  m_solution = Teuchos::rcp(new Vector(m_dofMap->ownedMap()));
  m_bcs->imposeOnSolution(*m_solution);
  m_setupSeconds = secondsSince(start);
}

Simulation::~Simulation() = default;

const SolveReport& Simulation::run() {
  const auto start = std::chrono::steady_clock::now();
  log() << "flowform: " << m_mesh.numNodes() << " nodes, " << m_mesh.numCells() << " "
        << cellTypeName(m_mesh.cellType) << " cells, " << m_dofMap->ownedMap()->getGlobalNumElements()
        << " dofs, " << m_comm->getSize() << " rank(s)\n";
  NonlinearSolver solver(*m_model, m_params.sublist("Solver"));
  if (!m_walls.empty()) {
    updateWallScales(*m_solution);
    solver.setBeforeNewton([this](const Vector& x) { updateWallScales(x); });
  }
  m_report = solver.solve(*m_solution, m_physics);
  if (m_report.converged && !m_walls.empty())
    m_contactChanges = m_statusLoop->run(solver, *m_solution, m_physics, m_walls, m_report);
  if (m_report.converged)
    m_functionals = m_responses->evaluate(*m_solution, m_mesh, *m_dofMap, *m_assembler, m_walls);
  m_solveSeconds = secondsSince(start);
  if (m_report.converged)
    log() << "flowform: converged (" << m_report.newtonIterations << " Newton iterations, "
          << m_report.continuationStages << " stages, |F| = " << m_report.residualNorm << ")\n";
  else
    log() << "flowform: NOT CONVERGED: " << m_report.message << "\n";
  if (m_report.converged && m_sensitivity->requested()) runSensitivity();
  return m_report;
}

int Simulation::exitStatus() const {
  if (!m_report.converged) return 3;
  if (m_sensitivity->requested() && !m_sensitivity->finite()) return 3;
  if (m_fdCheck && !m_fdCheck->allConverged()) return 3;
  return 0;
}

void Simulation::runSensitivity() {
  const auto start = std::chrono::steady_clock::now();
  m_sensitivity->compute(*m_model, *m_solution, *m_responses, m_mesh, *m_dofMap, m_walls);
  if (m_sensitivity->checkRequested() && m_sensitivity->finite()) {
    PerturbedRun base;
    base.converged = true;
    base.x = m_solution;
    base.functionals = m_functionals;
    base.states = m_statusLoop->states(m_walls, *m_solution);
    m_fdCheck = std::make_unique<FiniteDifferenceCheck>(
        *m_sensitivity, base, m_physics, m_walls, m_mesh,
        [this](const SensitivityParameter& h, double delta) { return solvePerturbed(h, delta); });
  }
  m_sensitivitySeconds = secondsSince(start);
}

PerturbedRun Simulation::solvePerturbed(const SensitivityParameter& h, double delta) {
  const std::vector<ContactWall> saved = m_walls;
  FlowPhysics physics = m_physics;
  shiftParameter(h, delta, physics, m_walls);
  for (ContactWall& wall : m_walls) wall.resetChangeCounts();
  // Held scales (the default) keep the walls' μ_k and σ̄_k of the base run, the problem the
  // DDM differentiates; Recomputed takes them from the start state at h ± δ, as a solve does.
  NonlinearSolver solver(*m_model, m_params.sublist("Solver"));
  if (!m_walls.empty() && !m_sensitivity->holdScalesInCheck())
    solver.setBeforeNewton([this](const Vector& x) { updateWallScales(x); });
  auto x = Teuchos::rcp(new Vector(*m_solution, Teuchos::Copy));
  PerturbedRun run;
  SolveReport report = solver.resolve(*x, physics);
  if (report.converged && !m_walls.empty()) run.contactChanges = m_statusLoop->run(solver, *x, physics, m_walls, report);
  run.converged = report.converged;
  run.message = report.message;
  run.newtonIterations = report.newtonIterations;
  run.x = x;
  if (run.converged) {
    run.functionals = m_responses->evaluate(*x, m_mesh, *m_dofMap, *m_assembler, m_walls);
    run.states = m_statusLoop->states(m_walls, *x);
  }
  m_walls = saved;
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
  const GO numNodes = m_mesh.numNodes(), numCells = m_mesh.numCells();
  const bool root = m_comm->getRank() == 0;

  // Nodal dofs to rank 0.
  auto rootDofs = Teuchos::rcp(new Map(kDofsPerNode * numNodes, root ? kDofsPerNode * numNodes : 0, 0, m_comm));
  Vector allDofs(rootDofs);
  allDofs.doImport(*m_solution, Import(m_dofMap->ownedMap(), rootDofs), Tpetra::INSERT);
  // Sensitivity fields only when sensitivities were asked for and computed.
  Teuchos::RCP<MultiVector> sensitivityDofs, differenceDofs;
  if (m_sensitivity->computed()) {
    const MultiVector& dqdh = m_sensitivity->solutionDerivatives();
    sensitivityDofs = Teuchos::rcp(new MultiVector(rootDofs, dqdh.getNumVectors()));
    sensitivityDofs->doImport(dqdh, Import(m_dofMap->ownedMap(), rootDofs), Tpetra::INSERT);
  }
  if (m_fdCheck) {
    const MultiVector& fd = m_fdCheck->solutionDifferences();
    differenceDofs = Teuchos::rcp(new MultiVector(rootDofs, fd.getNumVectors()));
    differenceDofs->doImport(fd, Import(m_dofMap->ownedMap(), rootDofs), Tpetra::INSERT);
  }

  // Cell values at the centroid, computed where the cell is assembled, then to rank 0:
  // e = sqrt(2/3 D:D), μ(e_r), σ_eq = sqrt(3/2 s:s) = 3 μ e.
  const auto& cells = m_dofMap->cells();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto ownedCells = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(cells), 0, m_comm));
  auto rootCells = Teuchos::rcp(new Map(numCells, root ? numCells : 0, 0, m_comm));
  MultiVector cellValues(ownedCells, 3), allCells(rootCells, 3);
  {
    Vector xOverlap(m_dofMap->overlapMap());
    xOverlap.doImport(*m_solution, *m_dofMap->importer(), Tpetra::INSERT);
    auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto v = cellValues.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const int npc = nodesPerCell(m_mesh.cellType);
    double dofs[kDofsPerNode * kMaxNodesPerCell];
    std::array<double, 2> xy[kMaxNodesPerCell];
    CellQuadrature centroid;
    for (size_t k = 0; k < cells.size(); ++k) {
      const LO* nodes = &m_dofMap->cellNodes()[npc * k];
      for (int a = 0; a < npc; ++a) {
        xy[a] = m_mesh.coords[m_dofMap->overlapNodes()[nodes[a]]];
        for (int c = 0; c < kDofsPerNode; ++c) dofs[kDofsPerNode * a + c] = x(kDofsPerNode * nodes[a] + c, 0);
      }
      computeCellQuadrature(m_mesh.cellType, xy, 1, centroid);
      const auto d = strainRateAt(centroid, 0, m_physics.kernel.geometry, dofs);
      const double e = std::sqrt(2.0 / 3.0 * d.ddot());
      const double mu = viscosity(regularizedStrainRate(d.ddot(), m_physics.material), m_physics.material);
      v(k, 0) = e;
      v(k, 1) = 3.0 * mu * e;
      v(k, 2) = mu;
    }
  }
  allCells.doImport(cellValues, Import(ownedCells, rootCells), Tpetra::INSERT);

  FieldSet fields;
  if (!root) return fields;
  auto d = allDofs.getLocalViewHost(Tpetra::Access::ReadOnly);
  Field velocity{"velocity", 2, std::vector<double>(2 * numNodes)};
  Field pressure{"pressure", 1, std::vector<double>(numNodes)};
  for (GO n = 0; n < numNodes; ++n) {
    velocity.values[2 * n] = d(kDofsPerNode * n + kUx, 0);
    velocity.values[2 * n + 1] = d(kDofsPerNode * n + kUy, 0);
    pressure.values[n] = d(kDofsPerNode * n + kP, 0);
  }
  fields.nodal = {velocity, pressure};
  if (!m_walls.empty()) {
    // 1 active, 0 free, -1 not on a contact wall
    Field status{"contact_status", 1, std::vector<double>(numNodes, -1.0)};
    for (const ContactWall& wall : m_walls)
      for (int k = 0; k < wall.numNodes(); ++k) status.values[wall.curve().nodes[k]] = wall.isActive(k) ? 1.0 : 0.0;
    fields.nodal.push_back(std::move(status));
  }
  // du/dh (also as du_t/dh, du_n/dh in the boundary CSVs) and dp/dh per parameter, by DDM
  // and, when the check ran, by central differences (suffix _fd).
  for (const auto& [dofs, suffix] : {std::make_pair(sensitivityDofs, ""), std::make_pair(differenceDofs, "_fd")}) {
    if (!dofs) continue;
    auto ds = dofs->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto& parameters = m_sensitivity->parameters();
    for (size_t j = 0; j < parameters.size(); ++j) {
      const std::string h = parameters[j].symbol + suffix;
      Field du{"du_d" + h, 2, std::vector<double>(2 * numNodes), "du_t_d" + h, "du_n_d" + h};
      Field dp{"dp_d" + h, 1, std::vector<double>(numNodes)};
      for (GO n = 0; n < numNodes; ++n) {
        du.values[2 * n] = ds(kDofsPerNode * n + kUx, j);
        du.values[2 * n + 1] = ds(kDofsPerNode * n + kUy, j);
        dp.values[n] = ds(kDofsPerNode * n + kP, j);
      }
      fields.nodal.push_back(std::move(du));
      fields.nodal.push_back(std::move(dp));
    }
  }
  auto c = allCells.getLocalViewHost(Tpetra::Access::ReadOnly);
  const char* names[3] = {"strain_rate", "equivalent_stress", "viscosity"};
  for (const auto& wanted : m_params.sublist("Output").get<Teuchos::Array<std::string>>("Cell Fields"))
    for (int j = 0; j < 3; ++j)
      if (wanted == names[j]) {
        Field f{names[j], 1, std::vector<double>(numCells)};
        for (GO k = 0; k < numCells; ++k) f.values[k] = c(k, j);
        fields.cell.push_back(std::move(f));
      }
  return fields;
}

void Simulation::writeOutput(const std::string& outDir) const {
  const auto start = std::chrono::steady_clock::now();
  const ParameterList& output = m_params.sublist("Output");
  const FieldSet fields = gatherFields();
  if (m_comm->getRank() != 0) return;
  std::filesystem::create_directories(outDir);

  if (output.get<bool>("Write Solution")) writeXdmf(outDir, "solution", m_mesh, fields);
  if (output.get<bool>("Boundary CSV"))
    for (const auto& group : m_mesh.boundaries) {
      try {
        writeBoundaryCsv(outDir, m_mesh, buildBoundaryCurve(m_mesh, group), fields);
      } catch (const std::exception& e) {  // a group that is not one simple curve, or an odd name
        log() << "flowform: no CSV for boundary group '" << group.name << "': " << e.what() << "\n";
      }
    }

  nlohmann::json summary;
  summary["converged"] = m_report.converged;
  summary["exit_status"] = exitStatus();
  summary["message"] = m_report.message;
  summary["newton_iterations"] = m_report.newtonIterations;
  summary["linear_problem"] = m_report.linear;
  summary["continuation_stages"] = m_report.continuationStages;
  summary["residual_norm"] = m_report.residualNorm;
  summary["contact_changes"] = m_contactChanges;
  summary["free_surface_iterations"] = 0;  // no free surfaces in this case
  summary["dofs"] = m_dofMap->ownedMap()->getGlobalNumElements();
  summary["mesh"] = {{"file", m_mesh.source}, {"nodes", m_mesh.numNodes()}, {"cells", m_mesh.numCells()},
                     {"cell_type", cellTypeName(m_mesh.cellType)}};
  summary["ranks"] = m_comm->getSize();
  summary["linear_solver"] = {{"factorizations", m_model->linearSolver().numFactorizations()},
                              {"solves", m_model->linearSolver().numSolves()},
                              {"residuals", m_model->numResiduals()},
                              {"jacobians", m_model->numJacobians()},
                              {"ordering", LinearSolver::orderingName(m_model->linearSolver().ordering())}};
  // Fill of the last factorization (rank 0 holds it), where the solver reports it.
  if (m_model->linearSolver().factorEntries() > 0.0)
    summary["linear_solver"]["factor_entries"] = m_model->linearSolver().factorEntries();
  const double assemblyResidual = timerSeconds("flowform: assembly (residual)");
  const double assemblyJacobian = timerSeconds("flowform: assembly (Jacobian)");
  summary["timings"] = {{"total", m_setupSeconds + m_solveSeconds + m_sensitivitySeconds + secondsSince(start)},
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
                        {"output", secondsSince(start)}};
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& s : m_report.stages)
    stages.push_back({{"rate_exponent", s.rateExponent}, {"cutoff", s.cutoff},
                      {"newton_iterations", s.newtonIterations}, {"converged", s.converged},
                      {"residual_norm", s.residualNorm}});
  summary["stages"] = stages;
  summary["functionals"] = nlohmann::json::object();
  for (const auto& [name, value] : m_functionals) summary["functionals"][name] = value;
  summary["fd_check"] = nlohmann::json::object();
  m_sensitivity->report(summary);  // "sensitivities", "sensitivity" (what it cost)
  summary["sensitivity"]["finite_difference"] = {{"runs", 0}};
  if (m_fdCheck) m_fdCheck->report(summary);  // "fd_check"
  if (m_report.converged && exitStatus() != 0)
    summary["message"] = !m_sensitivity->finite() ? "dq/dh is not finite (singular Jacobian?)"
                                                  : "a finite-difference run of the sensitivity check did not converge";
  summary["parameters"] = parameterListToJson(m_params);
  writeJsonFile(outDir + "/summary.json", summary);
}

}  // namespace flowform
