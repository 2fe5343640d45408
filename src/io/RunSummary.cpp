#include "flowform/io/RunSummary.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/io/JsonSummary.hpp"

namespace flowform {

namespace {

double timerSeconds(const std::string& name) {
  auto t = Teuchos::TimeMonitor::lookupCounter(name);
  return t.is_null() ? 0.0 : t->totalElapsedTime();
}

}  // namespace

nlohmann::json runSummary(const Problem& problem, const RunRecord& record,
                          std::chrono::steady_clock::time_point start) {
  const Mesh& mesh = problem.mesh();
  const FreeSurfaces& freeSurfaces = problem.freeSurfaces();
  const Sensitivity& sensitivity = *record.sensitivity;
  const ErrorEstimate& estimate = *record.estimate;
  nlohmann::json summary;
  problem.report().report(summary);  // converged, message, newton_iterations, stages, ...
  if (budgetWasSpent()) summary["converged"] = false;  // the run was cut short (core/Budget.hpp)
  summary["exit_status"] = record.exitStatus;
  summary["contact_changes"] = problem.contactChanges();
  summary["free_surface_iterations"] = 0;
  if (!freeSurfaces.empty()) {
    problem.freeSurfaceReport().report(summary);  // and the "free_surface" block
    int selfDeciding = 0;
    for (const ContactWall& wall : problem.contactWalls()) selfDeciding += wall.selfDecidingNodes();
    summary["free_surface"]["self_deciding_contacts"] = selfDeciding;
    summary["free_surface"]["released_groups"] = problem.boundaryConditions().releasedGroups();
  }
  if (const RigidInflowReport& inflow = problem.rigidInflowReport(); !inflow.group.empty()) {
    nlohmann::json history = nlohmann::json::array();
    for (const auto& [speed, force] : inflow.history) history.push_back({{"speed", speed}, {"force", force}});
    summary["rigid_inflow"] = {{"group", inflow.group},          {"converged", inflow.converged},
                               {"start_speed", inflow.startSpeed}, {"speed", inflow.speed},
                               {"force", inflow.force},           {"force_scale", inflow.forceScale},
                               {"solves", inflow.solves},         {"newton_iterations", inflow.newtonIterations},
                               {"jump", inflow.jump},
                               {"history", history}};
  }
  for (const ContactWall& wall : problem.contactWalls()) {
    if (!wall.hasFrictionField()) continue;  // where a Friction Field's stations lie, and its values
    nlohmann::json stations = nlohmann::json::array(), values = nlohmann::json::array();
    for (int j = 0; j < wall.numFieldStations(); ++j) {
      const auto point = wall.stationPoint(j);
      stations.push_back({point[0], point[1]});
      values.push_back(wall.fieldValue(j));
    }
    summary["friction_fields"][wall.name()] = {{"stations", stations}, {"values", values}};
  }
  summary["dofs"] = problem.dofMap().ownedMap()->getGlobalNumElements();
  summary["mesh"] = {{"file", mesh.source}, {"nodes", mesh.numNodes()}, {"cells", mesh.numCells()},
                     {"cell_type", cellTypeName(mesh.cellType)}};
  summary["ranks"] = problem.comm()->getSize();
  problem.model().linearSolver().report(summary["linear_solver"]);
  summary["linear_solver"]["residuals"] = problem.model().numResiduals();
  summary["linear_solver"]["jacobians"] = problem.model().numJacobians();
  const double assemblyResidual = timerSeconds("flowform: assembly (residual)");
  const double assemblyJacobian = timerSeconds("flowform: assembly (Jacobian)");
  summary["timings"] = {{"total", record.setupSeconds + record.solveSeconds + record.sensitivitySeconds +
                                      estimate.seconds + secondsSince(start)},
                        {"setup", record.setupSeconds},
                        {"solve", record.solveSeconds},
                        {"coarser_levels", record.coarserLevelSeconds},
                        {"assembly", assemblyResidual + assemblyJacobian},
                        {"assembly_residual", assemblyResidual},
                        {"assembly_jacobian", assemblyJacobian},
                        {"factorization", timerSeconds("flowform: factorization")},
                        {"linear_solve", timerSeconds("flowform: linear solve")},
                        {"sensitivity", record.sensitivitySeconds},
                        {"sensitivity_ddm", timerSeconds("flowform: sensitivity")},
                        {"finite_difference_check", timerSeconds("flowform: finite-difference check")},
                        {"error_estimation", estimate.seconds},
                        {"output", secondsSince(start)}};
  summary["functionals"] = nlohmann::json::object();
  for (const auto& [name, value] : *record.functionals) summary["functionals"][name] = value;
  estimate.report(summary);  // functionals_error_estimate, ..., when estimated
  summary["fd_check"] = nlohmann::json::object();
  sensitivity.report(summary);  // "sensitivities", "sensitivity" (what it cost)
  summary["sensitivity"]["finite_difference"] = {{"runs", 0}};
  if (record.fdCheck) record.fdCheck->report(summary);  // "fd_check"
  if (!freeSurfaces.empty() && sensitivity.computed() && sensitivity.totalShapeRequested())
    record.shapeDerivative->report(summary);  // "sensitivities_total_shape", "shape_derivative"
  summary["message"] = record.message;
  for (const auto& [key, block] : record.extra->items()) summary[key] = block;
  summary["parameters"] = parameterListToJson(problem.parameters());
  return summary;
}

}  // namespace flowform
