#include "flowform/sensitivity/PerturbedSolve.hpp"

#include "flowform/contact/WallStates.hpp"
#include "flowform/freesurface/FreeSurfaceLoop.hpp"
#include "flowform/problem/Problem.hpp"
#include "flowform/sensitivity/GeoParameterMotion.hpp"

namespace flowform {

PerturbedRun solvePerturbed(Problem& problem, const SensitivityParameter& h, double delta, bool holdScales) {
  std::vector<ContactWall>& walls = problem.contactWalls();
  const DofMap& dofMap = problem.dofMap();
  std::vector<ContactWall::State> saved;
  for (const ContactWall& wall : walls) saved.push_back(wall.state());
  FlowPhysics physics = problem.physics();
  shiftParameter(h, delta, physics, walls);
  // A Geo Parameter: the .geo meshed again at h + δ, the free surfaces' displacements carried over.
  const std::vector<std::array<double, 2>> baseShape = problem.mesh().coords;
  if (h.isGeo()) {
    const std::vector<std::array<double, 2>> madeThere = meshedAt(problem, h.geoName, h.geoValue + delta);
    std::vector<std::array<double, 2>> shape = madeThere;
    const Mesh made = problem.meshAsMade();
    for (size_t n = 0; n < shape.size(); ++n)
      for (int d = 0; d < 2; ++d) shape[n][d] += baseShape[n][d] - made.coords[n][d];
    problem.moveShape(madeThere, shape);  // the tools too
  }
  if (h.isBoundaryValue()) problem.shiftBoundaryValue(h.group, h.entry, delta);
  for (ContactWall& wall : walls) wall.resetChangeCounts();
  // Held scales (the default) keep the walls' μ_k and σ̄_k of the base run, the problem the
  // DDM differentiates; Recomputed takes them from the start state at h ± δ, as a solve does.
  NonlinearSolver solver = problem.newtonSolver(!holdScales);
  auto x = Teuchos::rcp(new Vector(problem.solution(), Teuchos::Copy));
  PerturbedRun run;
  SolveReport report = solver.resolve(*x, physics);
  if (report.converged && !walls.empty()) run.contactChanges = problem.statusLoop().run(solver, *x, physics, walls, report);
  // A Rigid Inflow's speed is an unknown of the flow: balanced again at h + δ (the DDM's bordered
  // system), and put back afterwards.
  const double baseSpeed = problem.boundaryConditions().rigidInflow().speed;
  const bool inflow = !problem.boundaryConditions().rigidInflow().group.empty();
  if (report.converged && inflow) {
    const RigidInflowReport balance = problem.balanceRigidInflow(solver, *x, physics);
    run.contactChanges += balance.contactChanges;
    report.newtonIterations += balance.newtonIterations;
    if (!balance.converged) {
      report.converged = false;
      report.message = balance.message;
    }
  }
  // Nodes left cycling (a wall whose released nodes are free surfaces) are accepted when they only
  // graze the tool, as in the free-surface loop.
  const bool cycling = !FreeSurfaceLoop::settled({report.unsettledContacts, report.unsettledContactRatio});
  run.converged = report.converged && !cycling;
  run.message = cycling ? std::to_string(report.unsettledContacts) + " contact node(s) cycle on the frozen shape"
                        : report.message;
  run.newtonIterations = report.newtonIterations;
  run.x = x;
  if (run.converged) {
    run.functionals = problem.evaluateResponses(*x);
    run.states = wallStates(walls, dofMap, *x);
  }
  if (run.converged && !problem.freeSurfaces().empty()) {
    // The same perturbation with the surfaces re-converged: the total derivative's difference.
    const std::vector<std::array<double, 2>> shape = problem.mesh().coords;
    Vector moving(*x, Teuchos::Copy);
    FreeSurfaceReport surfaces =
        problem.convergeFreeSurfaces(solver, moving, physics, {report.unsettledContacts, report.unsettledContactRatio},
                                     kFiniteDifferenceSurfaceTolerance);
    run.newtonIterations += surfaces.newtonIterations;
    // A Rigid Inflow's speed and the surfaces in turn, as the solve does, until the balance holds
    // on the re-converged shape.
    for (int round = 0; inflow && surfaces.converged; ++round) {
      const RigidInflowReport balance = problem.balanceRigidInflow(solver, moving, physics);
      run.newtonIterations += balance.newtonIterations;
      if (!balance.converged || round + 1 == Problem::kMaxInflowRounds) {
        surfaces.converged = false;
        surfaces.message = balance.converged ? "the Rigid Inflow's speed and the free surfaces did not settle"
                                             : balance.message;
        break;
      }
      if (balance.solves == 0) break;
      surfaces = problem.convergeFreeSurfaces(solver, moving, physics, {0, 0.0}, kFiniteDifferenceSurfaceTolerance);
      run.newtonIterations += surfaces.newtonIterations;
    }
    if (surfaces.converged) {
      run.movingFunctionals = problem.evaluateResponses(moving);
    } else {
      run.converged = false;
      run.message = "with re-converged free surfaces: " + surfaces.message;
    }
    problem.moveNodes(shape);
  }
  if (h.isGeo()) problem.moveShape(problem.meshAsMade().coords, baseShape);
  if (h.isBoundaryValue()) problem.shiftBoundaryValue(h.group, h.entry, -delta);
  if (inflow) problem.setRigidInflowSpeed(baseSpeed);
  for (size_t w = 0; w < walls.size(); ++w) walls[w].restore(saved[w]);
  problem.model().setPhysics(problem.physics());
  return run;
}

}  // namespace flowform
