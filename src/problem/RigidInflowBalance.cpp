// Problem::balanceRigidInflow: the speed of a group that moves as one rigid body (docs/rolling.md,
// docs/theory.md §2 "Rigid inflow").
//
// The group Γ_in is the cut through a rigid body upstream (a rolled strip before the bite): on it
// u = U d, d the given direction, U one unknown shared by all its nodes. The equation that closes
// the system is the force balance of that rigid body: the force the model's material needs at the
// cut along d equals the load the body carries (its traction t̄, a back tension),
//
//   F(U) = d · Σ_{i ∈ Γ_in} R_i(q(U)) = 0,    R_i = the unconstrained momentum residual at node i
//                                              (it holds −∫ N_i t̄ ds: the traction load),
//
// q(U) the converged flow (with its contact statuses) at the prescribed speed U. This is the
// bordered system [f(q, U) = 0, F(q) = 0] with the one extra unknown eliminated by an outer scalar
// iteration instead of a bordered Newton: F(U) is continuous and, for a strip driven by friction,
// increasing (a faster strip moves the neutral point towards the entry: more of the arc drags it
// back), but only piecewise smooth (each wall node that crosses the stick zone adds a kink), and
// Newton's tangent at fixed statuses sees only the smooth part of its slope (a Coulomb node in slip
// has no tangential stiffness) — measured on xml/rolling.xml: the monolithic Newton from a released
// inlet diverged, its first step |dx| ~ 10³. Here: an outer scalar iteration, each trial a warm
// re-solve from the tangent predictor. Its proposals are Newton's, U − F/(dF/dU) with the slope of
// the bordered linearization at the last converged state (dF/dU = dF/dq g, J g = −∂f/∂U, the
// factors at hand), safeguarded: the root is first bracketed (Newton's step when it goes the right
// way, else steps that double), then Newton while it stays inside the bracket and halves |F|,
// else Illinois false position.
//
// No root below: when F stays > 0 (the material must be pushed in) as U falls to 10⁻³ of its
// start, the tool cannot draw it in (a roll that slips over the whole arc: ν below the steady
// rolling limit); the solve ends unconverged saying so.
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "flowform/contact/WallStates.hpp"
#include "flowform/core/Budget.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/problem/Problem.hpp"

namespace flowform {

namespace {

/// A bracket this narrow relative to U has collapsed.
constexpr double kCollapsed = 1e-12;
/// The imbalance accepted at a jump of F, relative to the force scale (Problem::balanceRigidInflow).
constexpr double kJumpTolerance = 1e-5;
/// A moving tool skids when every node in contact lags it by more than this share of its speed.
constexpr double kSkidLag = 0.05;

std::string number(double v) {
  std::ostringstream os;
  os << std::setprecision(4) << v;
  return os.str();
}

/// This rank's share of d · Σ_{i ∈ group} v_i over the group's owned nodes (v_i the velocity
/// entries of node i): the force balance's F on a residual, its tangent on a residual's tangent.
double alongGroup(const Vector& v, const BoundaryCurve& group, const std::array<double, 2>& d, const DofMap& dofMap) {
  auto view = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  double local = 0.0;
  for (GO node : group.nodes) {
    const LO n = dofMap.overlapIndex(node);
    if (n < 0 || !dofMap.ownsNode(n)) continue;
    local += d[0] * view(dofMap.dof(n, kUx), 0) + d[1] * view(dofMap.dof(n, kUy), 0);
  }
  return local;
}

/// Empty, or why the converged state is no steady rolling: a moving wall skids — every node in
/// contact lags its tool by more than kSkidLag of the tool's speed (no neutral point). Steady
/// rolling has one: some part of the contact moves with the tool or faster. Measured:
/// xml/rolling.xml at 40 % reduction with Coulomb on the mean pressure balances at U = 10⁻³ of
/// the start speed, the strip 99.9 % slower than the roll. Collective (wallValues).
std::string skiddingWall(const std::vector<ContactWall>& walls, const DofMap& dofMap, const Vector& x) {
  for (const ContactWall& wall : walls) {
    if (!wall.motion().moving()) continue;
    std::vector<double> p;
    std::vector<std::array<double, 2>> u;
    wallValues(wall, dofMap, x, p, u);
    double lead = -std::numeric_limits<double>::infinity(), toolSpeed = 0.0;
    int inContact = 0;
    for (int k = 0; k < wall.numNodes(); ++k) {
      const double along = wall.wallTangentialSpeed(k);  // v_w·t
      if (!wall.isActive(k) || along == 0.0) continue;
      // (u − v_w)·t in the tool's sense of motion, relative to its speed: −1 for material at rest.
      lead = std::max(lead, wall.relativeSlip(k, u[k].data()) / along);
      toolSpeed = std::max(toolSpeed, std::abs(along));
      ++inContact;
    }
    if (inContact > 0 && lead < -kSkidLag) {
      std::ostringstream os;
      os << "wall '" << wall.curve().name << "' skidding: every one of its " << inContact
         << " nodes in contact lags the tool by at least " << number(-100.0 * lead) << " % of its speed "
         << number(toolSpeed);
      return os.str();
    }
  }
  return "";
}

}  // namespace

RigidInflowReport Problem::balanceRigidInflow(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics) {
  const RigidInflow& inflow = m_bcs->rigidInflow();
  const Teuchos::ParameterList& solverList = m_params.sublist("Solver");
  const double tolerance = solverList.get<double>("Rigid Inflow Tolerance");
  const int maxSolves = solverList.get<int>("Rigid Inflow Max Solves");
  RigidInflowReport rep;
  rep.group = inflow.group;
  rep.startSpeed = rep.speed = inflow.speed;

  // F(U) at the current state, and the force scale.
  auto force = [&](double& scale) { return rigidInflowForce(x, &scale); };
  // g and the balance's slope dF/dU = dF/dq g at the current converged state (the smooth part of the
  // slope: at fixed contact statuses), with the exact tangent factored there (one factorization per
  // trial; the last Newton iterate's factors may belong to another linearization or contact state:
  // measured on xml/rolling.xml, a slope of −7·10⁻⁴ from them against 0.54 from the tangent). The
  // next trial's simplified Newton reuses these factors. Computed when a trial is proposed, so the
  // state the balance ends on is not linearized for nothing.
  Vector g(m_dofMap->ownedMap());
  double slope = 0.0;
  bool linearized = false;
  auto linearize = [&] {
    if (linearized) return;
    m_model->restartLinearization();
    m_model->computeJacobian(x);
    m_model->solve(*rigidInflowSpeedLoad(x), g);
    slope = rigidInflowForceTangent(x, g, nullptr);
    linearized = true;
  };
  // The converged flow at speed U from the last state; false when the re-solve failed. It starts
  // from the tangent predictor x + (U − U_x) g (the factors at x, one back-substitution): the
  // flow's first-order response to the new inflow speed. Imposing only the new speed on the
  // group's nodes instead leaves a jump across its first layer of cells that Newton must damp
  // away (measured on xml/rolling.xml at R = 20: |F| 1.3·10³ at the start, 340 Newton iterations
  // for a 5 % change of U).
  std::string failure;
  auto solveAt = [&](double U) {
    linearize();
    x.update(U - m_bcs->rigidInflow().speed, g, 1.0);
    m_bcs->setRigidInflowSpeed(m_mesh, U);
    m_bcs->imposeOnSolution(x);
    for (ContactWall& wall : m_walls) wall.resetChangeCounts();
    NewtonOptions options;
    options.reuseFactors = true;
    SolveReport r = solver.resolve(x, physics, options);
    if (r.converged && !m_walls.empty()) rep.contactChanges += m_statusLoop->run(solver, x, physics, m_walls, r);
    ++rep.solves;
    rep.newtonIterations += r.newtonIterations;
    rep.newtonPerSolve.push_back(r.newtonIterations);
    if (!r.converged) failure = r.message;
    linearized = false;  // x moved
    return r.converged;
  };
  // Newton's proposal U − F/(dF/dU) from the current state, when the slope says F rises with U (a
  // strip driven by friction) and the step is less than half the speed; NaN otherwise.
  auto newtonProposal = [&](double U, double F) {
    linearize();
    const double step = -F / slope;
    return slope > 0.0 && std::isfinite(step) && std::abs(step) < 0.5 * std::abs(U)
               ? U + step
               : std::numeric_limits<double>::quiet_NaN();
  };
  auto fail = [&](const std::string& why) {
    rep.speed = m_bcs->rigidInflow().speed;
    if (!rep.history.empty()) rep.force = rep.history.back()[1];
    rep.converged = false;
    rep.message = "Rigid Inflow '" + inflow.group + "': " + why;
    warn() << "flowform: " << rep.message << "\n";
    return rep;
  };

  double scale = 0.0;
  double Fa = force(scale), Ua = inflow.speed;
  rep.history.push_back({Ua, Fa});
  auto done = [&](double F) { return std::abs(F) <= tolerance * scale; };
  log() << "rigid inflow '" << inflow.group << "': U = " << number(Ua) << ", force " << number(Fa) << " (scale "
        << number(scale) << ")\n";
  const double U0 = Ua;
  double Ub = Ua, Fb = Fa;
  // Bracket: F < 0 (the body must be held back) → faster; F > 0 (pushed) → slower.
  if (!done(Fa)) {
    const double dir = Fa < 0.0 ? 1.0 : -1.0;
    double step = 0.05 * U0;
    while (true) {
      if (rep.solves >= maxSolves) return fail("no bracket of the balance in " + std::to_string(maxSolves) +
                                               " solves (Solver/Rigid Inflow Max Solves)");
      if (budgetSpent()) return fail(budgetMessage());
      // Newton's step when it goes the bracket's way, else the doubling step.
      const double newton = newtonProposal(Ua, Fa);
      double U = std::isfinite(newton) && (newton - Ua) * dir > 0.0 ? newton : Ua + dir * step;
      if (dir < 0.0 && U <= 1e-3 * U0) U = 0.5 * Ua;
      if (dir < 0.0 && Ua <= 1e-3 * U0) {
        std::ostringstream os;
        os << "the material must still be pushed in at speed " << number(Ua) << " (force " << number(Fa)
           << " along the inflow, started at " << number(U0)
           << "): the tools cannot draw it in — a roll whose friction cannot balance the pressure on its arc "
              "slips over the whole arc (Friction Coefficient too small for the bite, or too much back tension; "
              "docs/rolling.md)";
        return fail(os.str());
      }
      if (!solveAt(U)) return fail("the re-solve at speed " + number(U) + " failed: " + failure);
      const double F = force(scale);
      rep.history.push_back({U, F});
      log() << "rigid inflow: U = " << number(U) << ", force " << number(F) << "\n";
      Ub = U;
      Fb = F;
      if (done(F) || (F > 0.0) != (Fa > 0.0)) break;
      Ua = U;
      Fa = F;
      step *= 2.0;
    }
  }
  // Illinois false position on [Ua, Ub] (F of opposite signs), unless the last trial is the root.
  double Flast = Fb, Ulast = Ub, Fprevious = Fa;
  bool newtonLast = false;
  int side = 0;
  while (!done(Flast)) {
    if (rep.solves >= maxSolves)
      return fail("the force balance " + number(Flast) + " is above its tolerance " + number(tolerance * scale) +
                  " after " + std::to_string(maxSolves) + " solves (Solver/Rigid Inflow Max Solves)");
    if (budgetSpent()) return fail(budgetMessage());
    // Newton from the last trial when it stays inside the bracket and, after a Newton trial, that
    // trial at least halved |F| (a kink of F stalls Newton); else Illinois' false position.
    const double newton = newtonProposal(Ulast, Flast);
    const double lo = std::min(Ua, Ub), hi = std::max(Ua, Ub);
    const bool useNewton = std::isfinite(newton) && newton > lo && newton < hi &&
                           (!newtonLast || std::abs(Flast) <= 0.5 * std::abs(Fprevious));
    const double U = useNewton ? newton : (Ua * Fb - Ub * Fa) / (Fb - Fa);
    newtonLast = useNewton;
    Fprevious = Flast;
    Ulast = U;
    if (!solveAt(U)) return fail("the re-solve at speed " + number(U) + " failed: " + failure);
    const double F = force(scale);
    rep.history.push_back({U, F});
    log() << "rigid inflow: U = " << std::setprecision(10) << U << ", force " << std::setprecision(4) << F << "\n";
    Flast = F;
    if ((F > 0.0) == (Fb > 0.0)) {  // U replaces Ub; Ua kept (its weight halved when kept twice)
      Ub = U;
      Fb = F;
      if (side == -1) Fa *= 0.5;
      side = -1;
    } else {
      Ua = U;
      Fa = F;
      if (side == 1) Fb *= 0.5;
      side = 1;
    }
    if (std::abs(Ub - Ua) <= kCollapsed * std::abs(Ub)) break;
  }
  Fb = Flast;
  // A bracket that collapsed on a jump of F (a contact node that switches between the two sides;
  // measured at ν = 0.3 on xml/rolling.xml: 2.4e-6 of the scale 4.5 across 1e-14 of U): the
  // state at the end of the smaller imbalance, accepted below kJumpTolerance × scale with a warning.
  if (!done(Fb) && std::abs(Ub - Ua) <= kCollapsed * std::abs(Ub)) {
    // The trial of the smallest imbalance at the jump (Illinois scales the kept end's F: the
    // history has the true ones).
    std::array<double, 2> best = rep.history.back();
    for (const auto& h : rep.history)
      if (std::abs(h[0] - Ub) <= 10 * kCollapsed * std::abs(Ub) && std::abs(h[1]) < std::abs(best[1])) best = h;
    if (best != rep.history.back()) {
      if (!solveAt(best[0])) return fail("the re-solve at speed " + number(best[0]) + " failed: " + failure);
      rep.history.push_back({best[0], force(scale)});
    }
    Fb = rep.history.back()[1];
    if (std::abs(Fb) <= kJumpTolerance * scale) {
      rep.jump = true;
      warn() << "rigid inflow '" << inflow.group << "': the force balance jumps across speed " << number(Ub)
             << " (a contact node switching); taken with the imbalance " << number(Fb) << " of the scale "
             << number(scale) << "\n";
      Fb = 0.0;  // accepted (rep.force keeps the imbalance)
    }
  }
  // The state is the last solve's.
  rep.speed = m_bcs->rigidInflow().speed;
  rep.force = rep.history.back()[1];
  rep.forceScale = scale;
  rep.converged = done(Fb);
  if (!rep.converged)
    return fail("the force balance " + number(Fb) + " stalls above its tolerance " + number(tolerance * scale));
  const std::string skid = skiddingWall(m_walls, *m_dofMap, x);
  if (!skid.empty())
    return fail("the balance holds at speed " + number(rep.speed) + " with " + skid +
                " (no neutral point): the tool cannot draw the material in at a steady state (Friction Coefficient "
                "too small for the bite, too much back tension, or a Coulomb law on the mean pressure where the "
                "normal traction is meant: Coulomb Normal Force = Contact Force; docs/rolling.md)");
  log() << "rigid inflow '" << inflow.group << "': speed " << std::setprecision(10) << rep.speed << std::setprecision(6)
        << " (force " << Fb << ", " << rep.solves << " re-solves, " << rep.newtonIterations
        << " Newton iterations)\n";
  return rep;
}

void Problem::balanceRigidInflow(NonlinearSolver& solver) {
  RigidInflowReport rep = balanceRigidInflow(solver, *m_solution, m_physics);
  // Its counts are for this call; the run's report sums the calls (rounds with free surfaces).
  m_contactChanges += rep.contactChanges;
  m_report.newtonIterations += rep.newtonIterations;
  for (int n : rep.newtonPerSolve) m_report.newtonPerSolve.push_back(n);
  if (!m_rigidInflowReport.group.empty()) {
    const RigidInflowReport& before = m_rigidInflowReport;
    rep.startSpeed = before.startSpeed;
    rep.solves += before.solves;
    rep.newtonIterations += before.newtonIterations;
    rep.contactChanges += before.contactChanges;
    rep.history.insert(rep.history.begin(), before.history.begin(), before.history.end());
  }
  m_rigidInflowReport = rep;
  if (!rep.converged) {
    m_report.converged = false;
    m_report.message = rep.message;
  }
}

void Problem::setRigidInflowSpeed(double speed) { m_bcs->setRigidInflowSpeed(m_mesh, speed); }

Teuchos::RCP<Vector> Problem::rigidInflowSpeedLoad(const Vector& x) {
  const double speed = m_bcs->rigidInflow().speed;
  auto load = Teuchos::rcp(new Vector(m_dofMap->ownedMap()));
  Vector shifted(m_dofMap->ownedMap());
  m_assembler->residual(x, *load);
  m_bcs->setRigidInflowSpeed(m_mesh, speed + 1.0);
  m_assembler->residual(x, shifted);
  m_bcs->setRigidInflowSpeed(m_mesh, speed);
  load->update(-1.0, shifted, 1.0);
  return load;
}

std::optional<RigidInflowLinearization> Problem::rigidInflowLinearization() {
  const RigidInflow inflow = m_bcs->rigidInflow();
  if (inflow.group.empty()) return std::nullopt;
  RigidInflowLinearization lin;
  lin.minusDfDU = rigidInflowSpeedLoad(*m_solution);
  lin.dForce = [this](const Vector& dq, const SensitivityParameter* h) {
    return rigidInflowForceTangent(*m_solution, dq, h);
  };
  return lin;
}

double Problem::rigidInflowForceFrom(const Vector& reactions) {
  const RigidInflow& inflow = m_bcs->rigidInflow();
  const BoundaryCurve curve = buildBoundaryCurve(m_mesh, m_mesh.boundary(inflow.group));
  const double local = alongGroup(reactions, curve, inflow.direction, *m_dofMap);
  double global = 0.0;
  Teuchos::reduceAll(*m_comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

double Problem::rigidInflowForce(const Vector& x, double* scale) {
  Vector r(m_dofMap->ownedMap());
  m_assembler->residual(x, r, false);
  if (scale) {  // Σ|R_i| over the nodes with a prescribed component
    auto view = r.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto& constraints = m_bcs->constraints();
    double local = 0.0;
    for (LO n = 0; n < m_dofMap->numOwnedNodes(); ++n)
      if (constraints[n].kind != NodeConstraint::Kind::None)
        local += std::hypot(view(m_dofMap->dof(n, kUx), 0), view(m_dofMap->dof(n, kUy), 0));
    Teuchos::reduceAll(*m_comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(*scale));
  }
  return rigidInflowForceFrom(r);
}

double Problem::rigidInflowForceTangent(const Vector& x, const Vector& dq, const SensitivityParameter* h) {
  // dF = d · Σ_{i ∈ group} dR_i, dR the unconstrained residual's tangent along (dq, h).
  Vector dR(m_dofMap->ownedMap());
  m_assembler->tangent(x, &dq, h, dR, false);
  return rigidInflowForceFrom(dR);
}

}  // namespace flowform
