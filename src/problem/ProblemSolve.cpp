// Problem::solve and the free-surface loop's wiring (Problem.hpp).
#include <cmath>
#include <iomanip>
#include <sstream>

#include "flowform/core/Budget.hpp"
#include "flowform/contact/WallStates.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/core/ParameterRamp.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/problem/Problem.hpp"

namespace flowform {

const SolveReport& Problem::solve() {
  log() << "flowform: " << m_mesh.numNodes() << " nodes, " << m_mesh.numCells() << " "
        << cellTypeName(m_mesh.cellType) << " cells, " << m_dofMap->ownedMap()->getGlobalNumElements()
        << " dofs, " << m_comm->getSize() << " rank(s)\n";
  NonlinearSolver solver = newtonSolver(true);
  if (!m_walls.empty()) updateWallScales(*m_solution);
  // The zero start puts every wall node at the kink of its friction law, and the predictor then
  // sees frictionless walls. Where friction dominates (ν ≳ 1) that start can fail, so with walls
  // it is tried with at most kFirstTryHalvings continuation halvings, then from walls that stick
  // at rest (FrictionSettings::stickAtRest), then by continuation in the friction coefficients
  // (continueInFriction), then from frictionless walls with every halving the case allows
  // (docs/contact.md).
  Vector initial(*m_solution, Teuchos::Copy);  // the starts below begin here
  // From another mesh's converged state the complementarity walls decide from the start.
  if (m_warmStart && m_statusLoop->complementarity())
    for (ContactWall& wall : m_walls) wall.enterComplementarity();
  const double caseMinimum = m_params.sublist("Solver").sublist("Continuation").get<double>("Minimum Step");
  const double firstMinimum = m_walls.empty() ? 0.0 : std::max(caseMinimum, std::ldexp(1.0, -kFirstTryHalvings));
  // From another mesh's converged state (startFrom): Newton at the target from there, then the
  // residual homotopy (NonlinearSolver::resolve).
  // With complementarity walls the first solve's state is only where their Newton starts: its
  // last stage stops at kLooseFirstSolve (enterComplementarity converges it tightly).
  const double looseTolerance = m_assembler->hasFrictionHeat() ? kLooseFirstSolveFrictionHeat : kLooseFirstSolve;
  const double loose = m_statusLoop->complementarity() && !m_walls.empty() ? looseTolerance : 0.0;
  NewtonOptions warm;
  warm.predictorRestart = false;  // its fallback is this problem's own start, below
  m_report = m_warmStart ? solver.resolve(*m_solution, m_physics, warm)
                         : solver.solve(*m_solution, m_physics, firstMinimum, loose);
  // The complementarity Newton continues a converged first solve. Should it fail, and the status
  // loop's tight re-solve too (a loose first state that was no good start), the first solve
  // counts as failed and the next start below is tried.
  bool looseStart = loose > 0.0 && !m_warmStart;
  auto complement = [&] {
    if (!m_report.converged || m_walls.empty() || !m_statusLoop->complementarity()) return;
    m_report.newtonPerSolve = {m_report.newtonIterations};
    enterComplementarity(solver, looseStart);
    looseStart = false;
  };
  complement();
  // A warm start that fails (the other mesh's contact zones or branch not this mesh's: the
  // extrusion at ν ≳ 1, docs/contact.md) gives way to this problem's own start: the solve a run
  // from scratch on this mesh makes, with its restarts below.
  if (!m_report.converged && m_warmStart && !budgetWasSpent()) {
    log() << "flowform: the start from the other mesh's state failed (" << m_report.message
          << "); solving from this mesh's own start, as a run from scratch\n";
    const int spent = m_report.newtonIterations;
    restoreColdStart();
    Tpetra::deep_copy(initial, *m_solution);
    updateWallScales(*m_solution);
    m_report = solver.solve(*m_solution, m_physics, firstMinimum, loose);
    m_report.newtonIterations += spent;
    m_report.restarts += 1;
    looseStart = loose > 0.0;
    complement();
  }
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
    complement();
  };
  if (!m_report.converged && !m_walls.empty() && !budgetWasSpent()) again(true, "from walls that stick at rest");
  if (!m_report.converged && !budgetWasSpent() && continueInFriction(solver, initial)) complement();
  if (!m_report.converged && !m_walls.empty() && firstMinimum > caseMinimum && !budgetWasSpent())
    again(false, "from frictionless walls with every continuation halving");
  if (m_report.newtonPerSolve.empty()) m_report.newtonPerSolve = {m_report.newtonIterations};
  if (!m_report.converged && !m_walls.empty() && !budgetWasSpent()) m_report.message += firstSolveHints();
  if (m_report.converged && !m_walls.empty())
    m_contactChanges = m_statusLoop->run(solver, *m_solution, m_physics, m_walls, m_report);
  // From another mesh's converged state (a refined run) the surfaces go first: that state's speed
  // belongs to its shape, and a balance on this mesh's unconverged surfaces would be undone.
  const bool surfacesFirst = m_warmStart && !m_freeSurfaces->empty();
  if (m_report.converged && !m_bcs->rigidInflow().group.empty() && !surfacesFirst) balanceRigidInflow(solver);
  if (m_report.converged && !m_freeSurfaces->empty()) {
    loopFreeSurfaces(solver, {m_report.unsettledContacts, m_report.unsettledContactRatio}, "");
    // A Rigid Inflow's speed and the surfaces in turn, until the balance holds on the converged shape.
    for (int round = 0; round < kMaxInflowRounds && m_report.converged && !m_bcs->rigidInflow().group.empty();
         ++round) {
      const int before = m_rigidInflowReport.solves;
      balanceRigidInflow(solver);
      if (!m_report.converged || m_rigidInflowReport.solves == before) break;
      if (round + 1 == kMaxInflowRounds) {
        m_report.converged = false;
        m_report.message = "the Rigid Inflow's speed and the free surfaces did not settle in " +
                           std::to_string(kMaxInflowRounds) + " rounds";
        break;
      }
      const FreeSurfaceReport earlier = m_freeSurfaceReport;  // the rounds' loops count as one
      loopFreeSurfaces(solver, {0, 0.0}, "after the Rigid Inflow's speed changed: ");
      m_freeSurfaceReport.continueFrom(earlier);
    }
    if (m_report.converged && releaseHeldConditions()) releaseHeldAndGoOn(solver);
  }
  return m_report;
}

void Problem::enterComplementarity(NonlinearSolver& solver, bool looseStart) {
  // The first solve converged with the walls' initial statuses (every node active by default: a
  // smooth problem, reached by the continuation); from there the complementarity walls decide
  // their contact zones inside Newton (ContactWall::enterComplementarity). Should that Newton
  // fail (a contact zone that does not settle), the walls go back to their statuses and the
  // status loop decides them, one node at a time (the paper's reference strategy).
  std::vector<ContactWall::State> before;
  for (const ContactWall& wall : m_walls) before.push_back(wall.state());
  const double pressureTolerance = m_params.sublist("Contact").get<double>("Pressure Tolerance");
  int corners = 0;
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (ContactWall& wall : m_walls) {
    wallValues(wall, *m_dofMap, *m_solution, p, u);
    corners += wall.releaseCornersInTension(p, pressureTolerance);
  }
  if (corners > 0) log() << "contact: " << corners << " node(s) at convex tool corners in tension released\n";
  int nodes = 0;
  for (ContactWall& wall : m_walls) nodes += wall.enterComplementarity();
  if (nodes == 0 && corners == 0 && m_warmStart) return;  // the warm re-solve was tight
  const Vector converged(*m_solution, Teuchos::Copy);
  NewtonOptions options;
  options.restart = false;  // its fallback is the status loop below, not the predictor
  const SolveReport r = solver.resolve(*m_solution, m_physics, options);
  m_report.newtonIterations += r.newtonIterations;
  m_report.newtonPerSolve.push_back(r.newtonIterations);
  m_report.restarts += r.restarts;
  m_report.residualNorm = r.residualNorm;
  if (r.converged) {
    log() << "contact: " << nodes << " wall node(s) decide their contact by complementarity; Newton converged in "
          << r.newtonIterations << " iteration(s)\n";
    return;
  }
  for (size_t w = 0; w < m_walls.size(); ++w) {
    m_walls[w].leaveComplementarity();
    m_walls[w].restore(before[w]);
  }
  Tpetra::deep_copy(*m_solution, converged);
  // The first solve's state converged tightly with its statuses: where the status loop starts,
  // and, from a loose first state (kLooseFirstSolve), where the complementarity Newton is tried
  // once more (the extrusion at ν = 1.5 on the shipped mesh converges from there, not from the
  // loose state).
  const SolveReport tight = solver.resolve(*m_solution, m_physics);
  m_report.newtonIterations += tight.newtonIterations;
  m_report.newtonPerSolve.push_back(tight.newtonIterations);
  if (tight.converged && looseStart) {
    log() << "contact: Newton with the complementarity walls did not converge from the loose first state; again "
             "from the tight one\n";
    m_report.residualNorm = tight.residualNorm;
    enterComplementarity(solver, false);
    return;
  }
  warn() << "contact: Newton with the complementarity walls did not converge (" << r.message
         << "); the status loop decides the contact zones instead (Contact/Status Update = Certain Iterate)\n";
  m_statusLoop->fallBackToStatuses();
  m_report.converged = tight.converged;
  m_report.residualNorm = tight.residualNorm;
  if (!tight.converged) m_report.message = tight.message;
}

bool Problem::continueInFriction(NonlinearSolver& solver, const Vector& initial) {
  // The last start of a sticking-dominated case (Coulomb ν ≳ 1): the friction coefficients
  // scaled by s = 1/8 (halved down to 1/64 until that solve converges), then raised towards the
  // case's values, s doubling after each converged Newton at the target material from the last
  // state and bisected back towards it after a failure (a homotopy in ν: at a small ν the
  // first solve is the friction-light problem every start handles; each step moves the stick
  // and slip zones a little). Measured on xml/extrusion.xml at ν = 2 (docs/contact.md).
  std::vector<double> nu;
  std::vector<std::vector<double>> fields;  // a Friction Field's values
  bool coulomb = false;
  for (const ContactWall& wall : m_walls) {
    nu.push_back(wall.settings().frictionCoefficient);
    fields.push_back(wall.settings().frictionField);
    coulomb = coulomb || (wall.usesFrictionCoefficient() && wall.largestFrictionCoefficient() > 0.0);
  }
  if (!coulomb) return false;
  auto scale = [&](double s) {
    for (size_t w = 0; w < m_walls.size(); ++w) {
      m_walls[w].setFrictionCoefficient(s * nu[w]);
      for (size_t j = 0; j < fields[w].size(); ++j) m_walls[w].setFieldValue(static_cast<int>(j), s * fields[w][j]);
    }
  };
  const SolveReport failed = m_report;
  int iterations = m_report.newtonIterations;
  SolveReport r;
  double s = kFrictionContinuationStart;
  for (; s >= kFrictionContinuationStart / 8.0 && !budgetWasSpent(); s /= 2.0) {
    log() << "flowform: the first solve failed (" << m_report.message
          << "); solving again with the friction coefficients scaled by " << s << ", then raising them\n";
    Tpetra::deep_copy(*m_solution, initial);
    scale(s);
    updateWallScales(*m_solution);
    r = solver.solve(*m_solution, m_physics);
    iterations += r.newtonIterations;
    if (r.converged) break;
  }
  NewtonOptions options;
  options.restart = false;
  ParameterRamp ramp{s, s};
  while (r.converged && !ramp.reachedEnd() && !budgetWasSpent()) {
    const Vector last(*m_solution, Teuchos::Copy);
    const double next = ramp.next();
    scale(next);
    const SolveReport raised = solver.resolve(*m_solution, m_physics, options);
    iterations += raised.newtonIterations;
    log() << "  friction scale " << next << ": " << (raised.converged ? "converged" : "failed") << " in "
          << raised.newtonIterations << " Newton iteration(s)\n";
    if (raised.converged) {
      ramp.accept(next);
      r.residualNorm = raised.residualNorm;
      continue;
    }
    Tpetra::deep_copy(*m_solution, last);
    ramp.reject(next);
    if (ramp.step < kFrictionContinuationStart / 64.0) {
      r.converged = false;
      r.message = raised.message + " (friction continuation stalled at scale " + std::to_string(ramp.t) + ")";
    }
  }
  scale(1.0);
  if (!r.converged || !ramp.reachedEnd()) {
    m_report = failed;
    m_report.newtonIterations = iterations;
    if (!r.message.empty()) m_report.message = r.message;
    return false;
  }
  r.newtonIterations = iterations;
  r.restarts = failed.restarts + 1;
  m_report = r;
  return true;
}

std::string Problem::firstSolveHints() const {
  // Measured on xml/extrusion.xml at ν = 2 on every wall before the friction continuation existed
  // (docs/theory.md §5, "Not-converged messages"): Tresca with m = 1 and h = 0.05 converged; a
  // smaller Minimum Step, 150 Newton iterations, the Exact linearization did not.
  double nu = 0.0;
  std::string coulomb;
  for (const ContactWall& wall : m_walls)
    if (wall.usesFrictionCoefficient() && wall.largestFrictionCoefficient() > nu) {
      nu = wall.largestFrictionCoefficient();
      coulomb = wall.name();
    }
  std::string hints =
      ". The first solve failed from each start (zero, walls sticking at rest, continuation in the friction "
      "coefficients, frictionless walls). To try: ";
  if (!coulomb.empty())
    hints += "a smaller Friction Coefficient (" + (std::ostringstream() << std::setprecision(3) << nu).str() +
             " on wall '" + coulomb +
             "'), or Friction Law = Tresca with a Shear Factor <= 1 (the friction stress bounded by the flow stress); ";
  return hints + "a finer mesh (Mesh/Geo Parameters, Mesh/Uniform Refinements). A smaller "
                 "Solver/Continuation/Minimum Step, more Solver/Max Newton Iterations or Newton Linearization = "
                 "Exact may not help";
}

void Problem::turnWallVelocities(Vector& x, const std::vector<std::vector<std::array<double, 2>>>& normalsBefore) const {
  // A wall node that a surface's attachment point slid along a roll has a turned normal: its
  // velocity turns with it, so that its normal and tangential velocity relative to the tool (what
  // the contact penalty and the friction law see) are as they were. Newton's start after the move
  // then has no penalty residual of |u| times the turn at every dragged node.
  auto values = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (size_t w = 0; w < m_walls.size(); ++w) {
    const ContactWall& wall = m_walls[w];
    for (int k = 0; k < wall.numNodes(); ++k) {
      const auto& a = normalsBefore[w][k];
      const auto& b = wall.curve().normals[k];
      const double sine = a[0] * b[1] - a[1] * b[0], cosine = a[0] * b[0] + a[1] * b[1];
      if (sine == 0.0) continue;
      const LO n = m_dofMap->overlapIndex(wall.curve().nodes[k]);
      if (!m_dofMap->ownsNode(n)) continue;
      double& ux = values(m_dofMap->dof(n, kUx), 0);
      double& uy = values(m_dofMap->dof(n, kUy), 0);
      const double vx = cosine * ux - sine * uy, vy = sine * ux + cosine * uy;
      ux = vx;
      uy = vy;
    }
  }
}

FreeSurfaceReport Problem::convergeFreeSurfaces(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics,
                                                std::pair<int, double> unsettledAtStart, double toleranceScale) {
  FreeSurfaceLoop::Hooks hooks;
  std::pair<int, double> unsettled = unsettledAtStart;  // contact nodes the last solve left cycling
  hooks.velocities = [&] { return replicate(x, *m_dofMap); };
  hooks.moveNodes = [&](const std::vector<std::array<double, 2>>& coords) {
    std::vector<std::vector<std::array<double, 2>>> normalsBefore;
    for (const ContactWall& wall : m_walls) normalsBefore.push_back(wall.curve().normals);
    moveNodes(coords);
    turnWallVelocities(x, normalsBefore);
    m_bcs->imposeOnSolution(x);
  };
  hooks.release = [&](int w, int k) {
    m_walls[w].setActive(k, false);
    log() << "contact: " << m_walls[w].name() << " node " << m_walls[w].curve().nodes[k]
          << " released: the separated surface passes below it\n";
  };
  hooks.newtonMoves = [&](const FreeSurfaceStep&, std::vector<std::array<double, 2>>& moves, std::string& why) {
    // The linearization reads the problem's own state: a perturbed run's (x ≠ m_solution) has none.
    if (&x != m_solution.get()) {
      why = "not in a finite-difference run";
      return false;
    }
    const UpdateLinearization lin(linearizationState(), false);
    why = lin.failure();
    return why.empty() && lin.newtonMoves(moves);
  };
  hooks.resolve = [&](int& newton, int& changes, std::string& why) {
    // Each shape is a new contact problem: the per-node change counts start again (the loop's
    // own cap stops a shape and a status that chase each other).
    for (ContactWall& wall : m_walls) wall.resetChangeCounts();
    // The last factors are the Jacobian's before the move: after a small move their simplified
    // Newton iteration converges without a new factorization (NewtonOptions::reuseFactors).
    NewtonOptions options;
    options.reuseFactors = true;
    SolveReport r = solver.resolve(x, physics, options);
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

void Problem::releaseHeldAndGoOn(NonlinearSolver& solver) {
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

void Problem::loopFreeSurfaces(NonlinearSolver& solver, std::pair<int, double> unsettledAtStart,
                               const std::string& context) {
  m_freeSurfaceReport = convergeFreeSurfaces(solver, *m_solution, m_physics, unsettledAtStart);
  m_report.newtonIterations += m_freeSurfaceReport.newtonIterations;
  m_contactChanges += m_freeSurfaceReport.contactChanges;
  if (!m_freeSurfaceReport.converged) {
    m_report.converged = false;
    m_report.message = context + m_freeSurfaceReport.message;
  }
}

}  // namespace flowform
