// Newton's method (NOX, line search) on the flow problem, with continuation in the rate
// exponent n and the strain-rate cutoff e0.
//
// Linear problem (n = 1, σ0 = 0): one assembly, one factorization, one solve — no Newton.
//
// Otherwise: a Newtonian predictor (one linear solve with μ = 1/(3γ)), then continuation
// stages along λ ∈ (0, 1] with geometric interpolation of both parameters,
//     n(λ)  = n_s^(1−λ) n^λ,       e0(λ) = e0_s^(1−λ) e0^λ,
// from the start values (n_s, e0_s) ("Start Exponent", "Start Cutoff") to the target.
// The step in λ starts at "Initial Step", is halved when a stage fails (from the last
// converged state) and grows by "Growth Factor" after a stage that took few iterations.
// If the target needs no continuation (n ≤ n_s and e0 ≥ e0_s) there is one stage, λ = 1.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <nlohmann/json_fwd.hpp>

#include "flowform/physics/FlowPhysics.hpp"
#include "flowform/solvers/FlowModel.hpp"

namespace flowform {

struct StageReport {
  double rateExponent;
  double cutoff;
  int newtonIterations;
  bool converged;
  double residualNorm;
  double initialResidualNorm = 0.0;  ///< ||F|| at the stage's start (its relative tolerance's scale)
  bool stoppedAtCap = false;         ///< NewtonOptions::maxIterations reached with a finite F (x is that iterate)
  double lastStep = 1.0;             ///< the line-search step of the last iteration (1: a full Newton step)
  double startResidualNorm = 0.0;    ///< ||F|| where this solve started (initialResidualNorm may be a reference)
};

/// How one Newton solve runs (the defaults: a solve of its own, to the Solver tolerances).
struct NewtonOptions {
  /// > 0: stop once ||F|| ≤ looseTolerance ||F_0|| (an intermediate state the contact
  /// loop only reads its next change from).
  double looseTolerance = 0.0;
  /// > 0: at most this many iterations; reaching it with a finite F is not a failure, the
  /// iterate is returned (StageReport::stoppedAtCap).
  int maxIterations = 0;
  /// true: the iterations continue the previous solve at the same physics and statuses, so
  /// the penalty scales (before-Newton hook) and the Newton duals are kept.
  bool continuing = false;
  /// > 0: the ||F_0|| of the solve this one continues (the relative tolerance's scale).
  double referenceResidual = 0.0;
  /// resolve(): false: a Newton that fails is reported as failed, with no restart from the
  /// predictor (the caller has a better fallback).
  bool restart = true;
  /// resolve() with restart: false: once the residual homotopy fails too, the solve is reported
  /// as failed instead of starting again from the predictor (the caller has its own start).
  bool predictorRestart = true;
  /// resolve() of an uncapped, tight solve: first the simplified Newton iteration with the
  /// factors the model holds (an earlier Jacobian's: the state before a small change such as a
  /// free-surface move), x ← x − J_old⁻¹ F(x), while each step at least halves ||F||, to the same
  /// tolerances; else Newton goes on from its last contracting iterate (the start if none), at
  /// the penalty scales of the start, with a new linearization (the duals restart). No Jacobian
  /// assembly or factorization when it converges (docs/theory.md §8).
  bool reuseFactors = false;
  /// > 0: Newton fails once ||F|| exceeds this many times its start (DivergenceTest; 0: its
  /// default, a blow-up only).
  double divergenceGrowth = 0.0;
};

struct SolveReport {
  bool converged = false;
  bool linear = false;         ///< solved as a linear problem (one solve)
  int newtonIterations = 0;    ///< over all stages, failed ones included
  int continuationStages = 0;  ///< converged stages
  double residualNorm = 0.0;   ///< ||F|| at the returned x
  std::vector<StageReport> stages;
  std::string message;         ///< why it did not converge, when it did not
  /// Newton iterations of each flow solve: the first (all its stages), then one per re-solve
  /// after a contact status change (ContactStatusLoop).
  std::vector<int> newtonPerSolve;
  int restarts = 0;  ///< re-solves that failed and started again from the predictor
  /// Of newtonIterations: simplified Newton steps with earlier factors (NewtonOptions::reuseFactors).
  int reusedFactorSteps = 0;
  bool stoppedAtCap = false;  ///< a resolve() that stopped at NewtonOptions::maxIterations
  /// Contact nodes left cycling between active and free by a status loop that tolerates them
  /// (ContactStatusLoop::tolerateCycling: while free surfaces move); 0 otherwise.
  int unsettledContacts = 0;
  double unsettledContactRatio = 0.0;  ///< their largest tension or penetration over its tolerance
  /// converged, linear_problem, newton_iterations, continuation_stages, residual_norm,
  /// stages, message and "solves" (newton_iterations per solve, restarts) into the summary.
  void report(nlohmann::json& summary) const;
};

class NonlinearSolver {
 public:
  /// The "Solver" sublist: Newton, line search and continuation settings.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// `params` is the validated "Solver" sublist.
  NonlinearSolver(FlowModel& model, const Teuchos::ParameterList& params);

  /// Solves F(x; target material) = 0 starting from x (which must satisfy the velocity
  /// constraints). On return x is the last converged state (the target's if converged).
  /// The model's physics is left at the target.
  /// `minimumStep` > 0 replaces Continuation/Minimum Step for this solve (a first try that
  /// gives up sooner). `finalLooseTolerance` > 0: the last stage stops at ||F|| ≤ that ×
  /// ||F_0|| (NewtonOptions::looseTolerance; for a state that another Newton continues).
  SolveReport solve(Vector& x, const FlowPhysics& target, double minimumStep = 0.0, double finalLooseTolerance = 0.0);

  /// Solves again after a small change (a contact status change): Newton at the target
  /// from x; if that fails, the full solve() (predictor and continuation). `options`: a
  /// loose tolerance, an iteration cap (the iterate is kept), continuing the previous solve.
  SolveReport resolve(Vector& x, const FlowPhysics& target, const NewtonOptions& options = {});

  /// Called with the current x before every Newton solve (each continuation stage, each
  /// re-solve): the contact walls take their penalty scales from it.
  void setBeforeNewton(std::function<void(const Vector&)> hook) { m_beforeNewton = std::move(hook); }

 private:
  /// One Newton solve at the model's current physics; returns iterations, sets converged.
  StageReport newton(Vector& x, const FlowPhysics& physics, const NewtonOptions& options = {});
  /// NewtonOptions::reuseFactors: the simplified Newton iteration from x with the model's
  /// factors, at most kMaxReusedSteps steps, each to halve ||F||. true when it met Newton's tests
  /// (x the solution); false with x its last contracting iterate (the start if none). `stage`:
  /// how far it got; `attempted`: the steps taken, a last one that did not contract included.
  bool reusedFactorSolve(Vector& x, const FlowPhysics& physics, const NewtonOptions& options, StageReport& stage,
                         int& attempted);
  /// A simplified Newton step must multiply ||F|| by at most this: the remaining error is then
  /// below the last step (a geometric series of ratio ≤ 1/2), as for the update test of Newton.
  static constexpr double kReuseContraction = 0.5;
  static constexpr int kMaxReusedSteps = 25;
  /// A re-solve's Newton starts next to its answer (a converged state before a small change, or
  /// another mesh's): once ||F|| exceeds this many times its start it has left that
  /// neighbourhood (a failed line search takes NOX's full recovery step), and the residual
  /// homotopy from the start follows at once instead of after Max Newton Iterations (the cutting
  /// scene's re-solves: 75 at the fourth step from 0.76, then 36 more iterations up to 5·10⁵).
  /// Not with NewtonOptions::restart false (no homotopy follows; the complementarity walls'
  /// entry climbs past 10× and converges: the axisymmetric hot extrusion at k = 10⁹).
  static constexpr double kResolveDivergence = 10.0;
  /// The re-solve's second try from its start x0 (before the predictor): the homotopy
  /// G(x, t) = F(x) − (1 − t) F(x0) = 0 followed from t = 0 (solved by x0) to t = 1 (F = 0),
  /// Newton at each t from the last one's solution, the penalty scales and the physics of x0
  /// held; the increase of t doubles after a converged stage and halves after a failed one
  /// (given up after kMaxHomotopyFailures failed stages: a branch that turns back before t = 1). It stays on the branch of solutions that x0 is near
  /// (another mesh's converged state: the same contact zones), where a Newton that overshoots
  /// in its first steps, or the predictor, may land on another. true when F(x) = 0 was reached;
  /// x is then the solution, else `start`. Iterations add to `report`.
  bool residualHomotopy(Vector& x, const Vector& start, const FlowPhysics& physics, SolveReport& report);
  static constexpr double kFirstHomotopyStep = 0.25;
  static constexpr int kMaxHomotopyFailures = 3;
  /// x += −J⁻¹ F(x): exact for a linear problem.
  double linearSolve(Vector& x, const FlowPhysics& physics);
  /// Whether F is linear at `physics`: a Newtonian material and contact walls that are linear
  /// (Assembler::contactIsLinear). Only then is one solve exact; otherwise Newton.
  bool isLinear(const FlowPhysics& physics) const;
  /// After the Newtonian predictor: a Temperature field the predictor's heating threw out of
  /// range (a law that reads T only) put back to `start`.
  void checkPredictorTemperature(Vector& x, const Vector& start, const FlowPhysics& target) const;

  FlowModel& m_model;
  Teuchos::ParameterList m_params;
  std::function<void(const Vector&)> m_beforeNewton;
};

}  // namespace flowform
