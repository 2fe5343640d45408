#include "flowform/solvers/NonlinearSolver.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

#include <NOX.H>
#include <NOX_Observer.hpp>
#include <NOX_Solver_LineSearchBased.H>
#include <NOX_StatusTest_Generic.H>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/core/NumberRange.hpp"
#include <nlohmann/json.hpp>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/core/ParameterRamp.hpp"
#include "flowform/solvers/FlowGroup.hpp"
#include "flowform/solvers/NewtonStatusTests.hpp"
#include "flowform/solvers/LinearSolverRegistry.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

namespace {

/// Continuation stages (converged or not) at most per solve.
constexpr int kMaxStageAttempts = 1000;

bool isFinite(const Vector& v) { return std::isfinite(v.norm2()); }

/// A number for a message: 3 significant digits, never "0.000000" for a small one.
std::string formatNumber(double v) {
  std::ostringstream os;
  os << std::setprecision(3) << v;
  return os.str();
}

}  // namespace

void SolveReport::report(nlohmann::json& summary) const {
  summary["converged"] = converged;
  summary["message"] = message;
  summary["newton_iterations"] = newtonIterations;
  summary["linear_problem"] = linear;
  summary["continuation_stages"] = continuationStages;
  summary["residual_norm"] = residualNorm;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : stages)
    list.push_back({{"rate_exponent", s.rateExponent}, {"cutoff", s.cutoff}, {"newton_iterations", s.newtonIterations},
                    {"converged", s.converged}, {"residual_norm", s.residualNorm}});
  summary["stages"] = list;
  summary["solves"] = {{"newton_iterations", newtonPerSolve}, {"restarts", restarts}};
}

static void buildValidParameters(const ValidList& valid) {
  valid->set("Max Newton Iterations", 40, "Newton iterations per continuation stage", intInRange(1, 10000));
  // Converged when ||F|| <= max(absolute, relative ||F_0||): either may be 0 (not used), and a
  // relative tolerance of 1 or more would call the start converged.
  valid->set("Time Limit", 0.0,
             "wall-clock budget of the whole run [s], from the start of the process; 0 = none. Checked at every "
             "Newton iteration, continuation stage, contact-status change, free-surface update, adaptivity cycle and "
             "finite-difference run: when spent, the run ends not converged (exit 3) with the last state written and "
             "the message saying where it was (docs/theory.md §5)",
             nonNegative());
  valid->set("Rigid Inflow Tolerance", 1e-9,
             "a Rigid Inflow group's speed is found when its force balance |d·Σ R_i| is at most this × Σ|R_i| over "
             "every node with a prescribed component (Problem::balanceRigidInflow, docs/rolling.md)",
             inRange(1e-14, 1.0));
  valid->set("Rigid Inflow Max Solves", 40, "re-solves at most while a Rigid Inflow group's speed is sought",
             intInRange(1, 10000));
  valid->set("Absolute Residual Tolerance", 1e-10, "||F||_2 below this is converged", nonNegative());
  valid->set("Relative Residual Tolerance", 1e-9, "||F||_2 / ||F_0||_2 below this is converged",
             inRange(0.0, 1.0, false, true));
  valid->set("Update Tolerance", 1e-8, "and ||dx||_2 <= this × (||x||_2 + this)", positive());
  Teuchos::setStringToIntegralParameter<int>(
      "Line Search", "Backtrack", "NOX line search: Backtrack (halving on ||F||), Polynomial, Full Step",
      Teuchos::tuple<std::string>("Backtrack", "Polynomial", "Full Step"), valid.get());
  Teuchos::setStringToIntegralParameter<int>(
      "Newton Linearization", "Stress-Velocity",
      "Stress-Velocity: the viscoplastic stress linearized with a dual stress variable (docs/theory.md §9; "
      "same converged state, fewer iterations); Exact: the exact tangent",
      Teuchos::tuple<std::string>("Stress-Velocity", "Exact"), valid.get());
  valid->set("Linear Solver", *validLinearSolverParameters(), "the direct solver of the Newton systems");
  Teuchos::ParameterList& cont = valid->sublist("Continuation", false, "continuation in n and e0");
  cont.set("Start Exponent", 1.0, "n at the first stage", positive());
  cont.set("Start Cutoff", 0.1, "e0 at the first stage (if larger than the target's)", positive());
  cont.set("Initial Step", 1.0,
           "first step in the continuation parameter λ ∈ (0, 1]; 1 tries the target at once and halves on failure "
           "(docs/verification.md §6)",
           inRange(1e-6, 1.0));
  cont.set("Minimum Step", 1.0 / 256, "give up when a failed stage halves the step below this",
           inRange(1e-12, 1.0));
  cont.set("Growth Factor", 2.0, "step growth after a stage that took at most 5 Newton iterations",
           inRange(1.0, 100.0));
}

Teuchos::RCP<const Teuchos::ParameterList> NonlinearSolver::validParameters() {
  return validListOnce<buildValidParameters>("Solver");
}

NonlinearSolver::NonlinearSolver(FlowModel& model, const Teuchos::ParameterList& params)
    : m_model(model), m_params(params) {
  m_params.validateParametersAndSetDefaults(*validParameters());
  m_model.useDualLinearization(m_params.get<std::string>("Newton Linearization") == "Stress-Velocity");
}

double NonlinearSolver::linearSolve(Vector& x, const FlowPhysics& physics) {
  m_model.setPhysics(physics);
  Vector f(x.getMap()), dx(x.getMap());
  m_model.residual(x, f);
  try {
    m_model.computeJacobian(x);
  } catch (const std::exception& e) {
    // A singular matrix: reported as not converged (NaN residual), never an abort.
    log() << "  linear solve failed: " << e.what() << "\n";
    return std::numeric_limits<double>::quiet_NaN();
  }
  m_model.solve(f, dx);
  x.update(-1.0, dx, 1.0);
  m_model.residual(x, f);
  return f.norm2();
}

StageReport NonlinearSolver::newton(Vector& x, const FlowPhysics& physics, const NewtonOptions& options) {
  const double looseTolerance = options.looseTolerance;
  if (!options.continuing) {
    m_model.setPhysics(physics);
    m_model.restartLinearization();
    if (m_beforeNewton) m_beforeNewton(x);
  }
  StageReport report{rateExponent(physics.material), physics.material.cutoff, 0, false, 0.0};

  auto group = Teuchos::rcp(new FlowGroup(m_model, x));
  // A loose solve (looseTolerance > 0) stops at ||F|| ≤ looseTolerance ||F_0|| with the
  // update test relaxed alike; the tight tolerances otherwise.
  const bool loose = looseTolerance > 0.0;
  auto residualTest = Teuchos::rcp(new ResidualAndStepTest(
      m_params.get<double>("Absolute Residual Tolerance"),
      loose ? looseTolerance : m_params.get<double>("Relative Residual Tolerance"),
      loose ? std::max(looseTolerance, m_params.get<double>("Update Tolerance")) : m_params.get<double>("Update Tolerance")));
  const int cap = options.maxIterations > 0 ? options.maxIterations : m_params.get<int>("Max Newton Iterations");
  residualTest->setReference(options.referenceResidual);
  auto maxIters = Teuchos::rcp(new NOX::StatusTest::MaxIters(cap));
  auto finite = Teuchos::rcp(new NOX::StatusTest::FiniteValue);
  auto budget = Teuchos::rcp(new BudgetTest);
  std::ostringstream where;
  where << "Newton at n = " << formatNumber(rateExponent(physics.material)) << ", e0 = "
        << formatNumber(physics.material.cutoff);
  const BudgetScope scope(where.str(), [&] { return std::to_string(budget->iterations()) + " iteration(s)"; });
  auto tests = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  tests->addStatusTest(budget);
  tests->addStatusTest(finite);
  tests->addStatusTest(Teuchos::rcp(new DivergenceTest(options.divergenceGrowth > 0.0 ? options.divergenceGrowth
                                                                                    : DivergenceTest::kGrowth)));
  tests->addStatusTest(residualTest);
  tests->addStatusTest(maxIters);

  auto noxParams = Teuchos::rcp(new Teuchos::ParameterList("NOX"));
  noxParams->set("Nonlinear Solver", "Line Search Based");
  noxParams->sublist("Direction").set("Method", "Newton");
  const std::string lineSearch = m_params.get<std::string>("Line Search");
  Teuchos::ParameterList& ls = noxParams->sublist("Line Search");
  ls.set("Method", lineSearch);
  if (lineSearch == "Backtrack") {
    ls.sublist("Backtrack").set("Max Iters", 12);
    ls.sublist("Backtrack").set("Minimum Step", 1e-4);
  }
  noxParams->sublist("Printing").set("Output Information", NOX::Utils::Error);
  noxParams->sublist("Solver Options").set<Teuchos::RCP<NOX::Observer>>("Observer",
                                                                           Teuchos::rcp(new NewtonLogger(*residualTest)));
  auto solver = NOX::Solver::buildSolver(group, tests, noxParams);
  // NOX throws (a const char*, or a std::exception) when a step cannot be computed, e.g.
  // a singular Jacobian the factorization refused (FlowGroup logs why): that is a failed
  // solve, reported as such, never an abort.
  NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
  try {
    status = solver->solve();
  } catch (const char* what) {
    log() << "  Newton stopped: " << what << "\n";
  } catch (const std::exception& e) {
    log() << "  Newton stopped: " << e.what() << "\n";
  }

  report.newtonIterations = solver->getNumIterations();
  report.residualNorm = solver->getSolutionGroup().getNormF();
  report.initialResidualNorm = residualTest->initialNorm();
  report.lastStep = residualTest->step();
  report.startResidualNorm = residualTest->startNorm();
  report.converged = status == NOX::StatusTest::Converged && std::isfinite(report.residualNorm);
  report.stoppedAtCap = !report.converged && !budgetWasSpent() && options.maxIterations > 0 &&
                        maxIters->checkStatus(*solver, NOX::StatusTest::Minimal) == NOX::StatusTest::Failed &&
                        std::isfinite(report.residualNorm) && report.residualNorm < report.initialResidualNorm;
  if (report.converged || report.stoppedAtCap) Tpetra::deep_copy(x, *tpetraVector(solver->getSolutionGroup().getX()));
  return report;
}

bool NonlinearSolver::reusedFactorSolve(Vector& x, const FlowPhysics& physics, const NewtonOptions& options,
                                        StageReport& stage, int& attempted) {
  m_model.setPhysics(physics);
  // A solve of its own takes the penalty scales from its start, as Newton would.
  if (!options.continuing && m_beforeNewton) m_beforeNewton(x);
  const double atol = m_params.get<double>("Absolute Residual Tolerance");
  const double rtol = m_params.get<double>("Relative Residual Tolerance");
  const double utol = m_params.get<double>("Update Tolerance");
  Vector f(x.getMap()), dx(x.getMap());
  m_model.residual(x, f);
  double normF = f.norm2();
  attempted = 0;
  stage = StageReport{rateExponent(physics.material), physics.material.cutoff, 0, false, normF};
  stage.startResidualNorm = normF;
  stage.initialResidualNorm = options.referenceResidual > 0.0 ? options.referenceResidual : normF;
  if (normF <= atol) {  // Newton's test at its start
    stage.converged = true;
    return true;
  }
  int steps = 0;
  Vector last(x, Teuchos::Copy);  // the last contracting iterate (the start at first)
  while (steps < kMaxReusedSteps && !budgetSpent()) {
    m_model.solve(f, dx);
    x.update(-1.0, dx, 1.0);
    ++steps;
    const double previous = normF;
    m_model.residual(x, f);
    normF = f.norm2();
    const double normDx = dx.norm2(), normX = x.norm2();
    log() << "    reused factors " << std::setw(2) << steps << "  |F| = " << std::scientific << std::setprecision(3)
          << normF << "  |dx| = " << normDx << std::defaultfloat << "\n";
    const bool contracted = std::isfinite(normF) && normF <= kReuseContraction * previous;
    if (!contracted && !(normF <= atol)) {
      Tpetra::deep_copy(x, last);
      break;
    }
    Tpetra::deep_copy(last, x);
    stage.newtonIterations = steps;
    stage.residualNorm = normF;
    // Newton's tests (ResidualAndStepTest), the step bounding the remaining error as the
    // iteration contracts (or ||F|| is at its absolute floor).
    if ((normF <= atol || normF <= rtol * stage.initialResidualNorm) && normDx <= utol * (normX + utol)) {
      stage.converged = true;
      attempted = steps;
      return true;
    }
  }
  // Not converged: x is the last contracting iterate (Newton continues from there), or the start.
  attempted = steps;
  return false;
}

void NonlinearSolver::checkPredictorTemperature(Vector& x, const Vector& start, const FlowPhysics& target) const {
  // The predictor predicts the flow with a Newtonian viscosity 1/(3γ) (a hot-working law's γ at
  // its reference temperature), which can be orders above the flow's at its rates, and so can its
  // plastic heating: its temperatures are a good start (the inflow's carried, the tools' pull)
  // unless the heating threw them out of range. For a law that reads T (exp(Q/RT)), T outside
  // (start_min / 2, 2 start_max) or not finite is put back to the start (docs/theory.md §10).
  const DofMap& dofMap = m_model.assembler().dofMap();
  const int t = dofMap.fields().componentOf(kTemperatureField);
  if (t < 0 || temperatureParameter(target.material.law) < 0) return;
  auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  auto sv = start.getLocalViewHost(Tpetra::Access::ReadOnly);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, startLo = lo, startHi = -lo;
  for (LO n = 0; n < dofMap.numOwnedNodes(); ++n) {
    const double v = xv(dofMap.dof(n, t), 0), s = sv(dofMap.dof(n, t), 0);
    lo = std::isfinite(v) ? std::min(lo, v) : -std::numeric_limits<double>::infinity();
    hi = std::max(hi, v);
    startLo = std::min(startLo, s);
    startHi = std::max(startHi, s);
  }
  const auto& comm = *dofMap.comm();
  double local[2] = {-lo, hi}, global[2];
  double startLocal[2] = {-startLo, startHi}, startGlobal[2];
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, local, global);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, startLocal, startGlobal);
  lo = -global[0];
  hi = global[1];
  if (lo > 0.5 * -startGlobal[0] && hi < 2.0 * startGlobal[1]) return;
  log() << "  Newtonian predictor: T in [" << lo << ", " << hi << "], out of (" << 0.5 * -startGlobal[0] << ", "
        << 2.0 * startGlobal[1] << "): the temperature starts from its start values\n";
  for (LO n = 0; n < dofMap.numOwnedNodes(); ++n) xv(dofMap.dof(n, t), 0) = sv(dofMap.dof(n, t), 0);
}

bool NonlinearSolver::isLinear(const FlowPhysics& physics) const {
  // A Newtonian material makes the bulk linear; the contact walls may not be (Coulomb's p⁺ and
  // sticking bound, complementarity's max): then Newton, even at n = 1.
  // A field besides the flow's (the temperature: its convection u·∇T and heating s:D are not
  // linear in u) makes it nonlinear too.
  return isNewtonian(physics.material) && m_model.assembler().contactIsLinear() &&
         m_model.assembler().dofMap().fields().numComponents() == kNumFlowComponents;
}

SolveReport NonlinearSolver::resolve(Vector& x, const FlowPhysics& target, const NewtonOptions& options) {
  if (isLinear(target)) return solve(x, target);
  Vector start(x, Teuchos::Copy);
  int reused = 0;
  NewtonOptions newtonOptions = options;
  if (options.reuseFactors && options.looseTolerance <= 0.0 && options.maxIterations <= 0 && m_model.hasFactors()) {
    StageReport chord;
    if (reusedFactorSolve(x, target, options, chord, reused)) {
      SolveReport report;
      report.converged = true;
      report.stages.push_back(chord);
      report.newtonIterations = report.reusedFactorSteps = reused;
      report.residualNorm = chord.residualNorm;
      return report;
    }
    log() << "    reused factors: not converged; Newton from "
          << (chord.newtonIterations > 0 ? "the last contracting iterate" : "the start") << "\n";
    // Newton continues at the penalty scales of the start, its relative tolerance on the
    // start's ||F||, with a new linearization.
    m_model.restartLinearization();
    newtonOptions.continuing = true;
    newtonOptions.referenceResidual = chord.initialResidualNorm;
  }
  // Only where the residual homotopy follows a failure (restart): a caller with its own fallback
  // (the complementarity walls' entry, whose Newton climbs past 10x and comes back) keeps Newton's.
  if (newtonOptions.divergenceGrowth <= 0.0 && options.restart) newtonOptions.divergenceGrowth = kResolveDivergence;
  StageReport sr = newton(x, target, newtonOptions);
  SolveReport report;
  report.reusedFactorSteps = reused;
  report.stages.push_back(sr);
  report.newtonIterations = reused + sr.newtonIterations;
  report.residualNorm = sr.residualNorm;
  report.converged = sr.converged;
  report.stoppedAtCap = sr.stoppedAtCap;
  if (sr.converged || sr.stoppedAtCap) return report;
  if (budgetWasSpent()) {  // no second try: the run ends (core/Budget.hpp)
    report.message = budgetMessage();
    return report;
  }
  if (options.maxIterations > 0) {
    // A capped step that did not reduce ||F|| (the line search failed): Newton without the
    // cap from the same start, before the costly restart from the predictor.
    Tpetra::deep_copy(x, start);
    NewtonOptions uncapped = options;
    uncapped.maxIterations = 0;
    uncapped.continuing = true;
    if (uncapped.referenceResidual <= 0.0) uncapped.referenceResidual = sr.initialResidualNorm;
    const StageReport again = newton(x, target, uncapped);
    report.stages.push_back(again);
    report.newtonIterations += again.newtonIterations;
    report.residualNorm = again.residualNorm;
    report.converged = again.converged;
    report.stoppedAtCap = false;
    if (again.converged) return report;
    if (budgetWasSpent()) {
      report.message = budgetMessage();
      return report;
    }
  }
  if (!options.restart) {
    Tpetra::deep_copy(x, start);
    report.message = "Newton did not converge from the start it was given";
    return report;
  }
  if (residualHomotopy(x, start, target, report)) return report;
  if (budgetWasSpent()) {
    report.message = budgetMessage();
    return report;
  }
  if (!options.predictorRestart) {
    Tpetra::deep_copy(x, start);
    report.message = "Newton and the residual homotopy did not converge from the start they were given";
    return report;
  }
  log() << "  re-solve failed; starting again from the Newtonian predictor\n";
  Tpetra::deep_copy(x, start);
  SolveReport full = solve(x, target);
  full.newtonIterations += report.newtonIterations;
  full.restarts = 1;
  return full;
}

bool NonlinearSolver::residualHomotopy(Vector& x, const Vector& start, const FlowPhysics& physics,
                                       SolveReport& report) {
  Tpetra::deep_copy(x, start);
  m_model.setPhysics(physics);
  m_model.restartLinearization();
  if (m_beforeNewton) m_beforeNewton(x);
  Vector r0(x.getMap());
  m_model.residual(x, r0);
  const double norm0 = r0.norm2();
  if (!std::isfinite(norm0)) return false;
  log() << "  re-solve failed; following F(x) = (1 - t) F(x0) from t = 0 at the start\n";
  ParameterRamp ramp{0.0, kFirstHomotopyStep};
  while (!ramp.reachedEnd() && ramp.failures <= kMaxHomotopyFailures && !budgetWasSpent()) {
    const Vector last(x, Teuchos::Copy);
    const double next = ramp.next();
    m_model.setResidualShift(&r0, 1.0 - next);
    NewtonOptions stage;
    stage.continuing = true;  // the scales of x0; the duals go on from the last stage
    stage.referenceResidual = norm0;
    const StageReport sr = newton(x, physics, stage);
    m_model.setResidualShift(nullptr, 0.0);
    report.newtonIterations += sr.newtonIterations;
    report.stages.push_back(sr);
    log() << "  homotopy t = " << next << ": " << (sr.converged ? "converged" : "failed") << " in "
          << sr.newtonIterations << " Newton iteration(s)\n";
    if (sr.converged) {
      ramp.accept(next);
      report.residualNorm = sr.residualNorm;
    } else {
      Tpetra::deep_copy(x, last);
      m_model.restartLinearization();
      ramp.reject(next);
    }
  }
  if (!ramp.reachedEnd()) {
    Tpetra::deep_copy(x, start);
    return false;
  }
  report.converged = true;
  report.message.clear();
  return true;
}

SolveReport NonlinearSolver::solve(Vector& x, const FlowPhysics& target, double minimumStep, double finalLooseTolerance) {
  SolveReport report;
  const double atol = m_params.get<double>("Absolute Residual Tolerance");
  const double rtol = m_params.get<double>("Relative Residual Tolerance");

  if (isLinear(target)) {
    // Linear: one factorization and one solve; the second residual only verifies it.
    report.linear = true;
    Vector f(x.getMap());
    m_model.residual(x, f);
    const double normF0 = f.norm2();
    report.residualNorm = linearSolve(x, target);
    report.converged = std::isfinite(report.residualNorm) && report.residualNorm <= std::max(atol, 10 * rtol * normF0);
    log() << "  linear solve: |F| = " << std::scientific << std::setprecision(3) << normF0 << " -> "
          << report.residualNorm << std::defaultfloat << "\n";
    if (!report.converged) report.message = "the linear solve left a residual |F| = " + formatNumber(report.residualNorm);
    return report;
  }

  // Newtonian predictor: μ = 1/(3γ) everywhere (γ the law's, materials/MaterialLaws.hpp).
  FlowPhysics stokes = target;
  stokes.material = newtonianPredictor(target.material);
  const Vector xStart(x, Teuchos::Copy);
  const double predictorResidual = linearSolve(x, stokes);
  checkPredictorTemperature(x, xStart, target);
  log() << "  Newtonian predictor: |F| = " << std::scientific << std::setprecision(3) << predictorResidual
        << std::defaultfloat << "\n";
  if (!std::isfinite(predictorResidual) || !isFinite(x)) {
    Tpetra::deep_copy(x, xStart);
    m_model.setPhysics(target);
    report.message = "the Newtonian predictor produced a non-finite solution (singular Jacobian?)";
    return report;
  }

  const Teuchos::ParameterList& cont = m_params.sublist("Continuation");
  const double nStart = std::min(cont.get<double>("Start Exponent"), rateExponent(target.material));
  const double e0Start = std::max(cont.get<double>("Start Cutoff"), target.material.cutoff);
  // A law that reads a Strain field feels it gradually: the coupling λ (physics/StrainField.hpp).
  const bool strainCoupling = strainParameter(target.material.law) >= 0 &&
                              m_model.assembler().dofMap().fields().contains(kStrainField);
  const bool needsContinuation =
      nStart < rateExponent(target.material) || e0Start > target.material.cutoff || strainCoupling;
  double step = needsContinuation ? cont.get<double>("Initial Step") : 1.0;
  const double minStep = minimumStep > 0.0 ? minimumStep : cont.get<double>("Minimum Step");
  const double growth = cont.get<double>("Growth Factor");

  // The physics at λ: n and e0 interpolated geometrically, the strain field's coupling λ, exactly the
  // target at λ = 1.
  auto stageAt = [&](double l) {
    FlowPhysics stage = target;
    rateExponent(stage.material) = std::pow(nStart, 1.0 - l) * std::pow(rateExponent(target.material), l);
    stage.material.cutoff = std::pow(e0Start, 1.0 - l) * std::pow(target.material.cutoff, l);
    if (strainCoupling) stage.strainField.coupling = l;
    if (l == 1.0) stage = target;  // no rounding
    return stage;
  };

  double lambda = 0.0;
  Vector xConverged(x, Teuchos::Copy);
  const BudgetScope scope("the continuation in n and e0", [&] {
    return std::to_string(report.continuationStages) + " converged stage(s) (lambda = " + formatNumber(lambda) + ")";
  });
  int attempts = 0;
  while (lambda < 1.0) {
    // Caps: the wall-clock budget, and kMaxStageAttempts stages (a Growth Factor of 1 with a tiny
    // Minimum Step could otherwise take 10^12 stages).
    const bool spent = budgetSpent();
    if (spent || ++attempts > kMaxStageAttempts) {
      report.message = spent ? budgetMessage()
                             : "the continuation did not reach the target in " + std::to_string(kMaxStageAttempts) +
                                   " stages (lambda = " + formatNumber(lambda) +
                                   "; Solver/Continuation/Initial Step, Minimum Step, Growth Factor)";
      Tpetra::deep_copy(x, xConverged);
      m_model.setPhysics(target);
      return report;
    }
    const double next = std::min(1.0, lambda + step);
    const FlowPhysics stage = stageAt(next);
    log() << "  stage lambda = " << next << ": n = " << rateExponent(stage.material)
          << ", e0 = " << stage.material.cutoff << "\n";
    Tpetra::deep_copy(x, xConverged);
    NewtonOptions stageOptions;
    if (next == 1.0) stageOptions.looseTolerance = finalLooseTolerance;
    StageReport sr = newton(x, stage, stageOptions);
    report.stages.push_back(sr);
    report.newtonIterations += sr.newtonIterations;
    report.residualNorm = sr.residualNorm;
    if (sr.converged) {
      lambda = next;
      Tpetra::deep_copy(xConverged, x);
      ++report.continuationStages;
      if (sr.newtonIterations <= 5) step *= growth;
    } else if (budgetWasSpent()) {  // stopped by the budget, not a failed stage: no halving
      report.message = budgetMessage();
      Tpetra::deep_copy(x, xConverged);
      m_model.setPhysics(target);
      return report;
    } else {
      step *= 0.5;
      log() << "  stage failed after " << sr.newtonIterations << " iterations (|F| = " << sr.residualNorm
            << "); step -> " << step << "\n";
      if (step < minStep || !needsContinuation) {
        report.message = "Newton did not converge at n = " + formatNumber(rateExponent(stage.material)) +
                         ", e0 = " + formatNumber(stage.material.cutoff) + ": |F| = " + formatNumber(sr.residualNorm) +
                         " after " + std::to_string(sr.newtonIterations) + " iterations, against the tolerance " +
                         formatNumber(std::max(m_params.get<double>("Absolute Residual Tolerance"),
                                               m_params.get<double>("Relative Residual Tolerance") * sr.initialResidualNorm)) +
                         " (continuation step " + formatNumber(step) + " below the minimum " + formatNumber(minStep) + ")";
        Tpetra::deep_copy(x, xConverged);
        m_model.setPhysics(target);
        return report;
      }
    }
  }
  report.converged = true;
  return report;
}

}  // namespace flowform
