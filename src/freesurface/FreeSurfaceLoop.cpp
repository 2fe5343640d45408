#include "flowform/freesurface/FreeSurfaceLoop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/core/ValidList.hpp"
#include "flowform/freesurface/MeshMotion.hpp"
#include "flowform/solvers/AndersonAcceleration.hpp"

namespace flowform {

static void buildValidParameters(const ValidList& valid) {
  valid->set("Maximum Iterations", 30, "surface updates at most; then the run is not converged (exit 3)",
             intInRange(0, 10000));
  valid->set("Flow Angle Tolerance", 1e-4,
             "converged when max |u·n|/|u| over the surface segments (u the segment's mean velocity) is below this",
             inRange(1e-14, 1.0));
  Teuchos::setStringToIntegralParameter<int>(
      "Relaxation", "Anderson",
      "None: every update moves the surface nodes onto the streamline of the current flow (the paper's); Aitken: "
      "they move by ω times that, ω from Aitken's Δ² rule on successive updates; Anderson: the multisecant step "
      "from the last Anderson Depth updates (the plain one after a contact status change); Newton: a Newton step "
      "on the positions with the linearized update (two residual assemblies per surface node per update; "
      "docs/theory.md §3)",
      Teuchos::tuple<std::string>("None", "Aitken", "Anderson", "Newton"), valid.get());
  valid->set("Anderson Depth", 5, "Relaxation = Anderson: how many previous updates its step uses",
             intInRange(1, 50));
  valid->set("Move Tolerance", 1e-4,
             "and when the largest node move of the next update is below this fraction of the surface's length",
             inRange(1e-14, 1.0));
}

Teuchos::RCP<const Teuchos::ParameterList> FreeSurfaceLoop::validParameters() {
  return validListOnce<buildValidParameters>("Free Surface");
}

void FreeSurfaceReport::report(nlohmann::json& summary) const {
  summary["free_surface_iterations"] = iterations;
  summary["free_surface"] = {{"converged", converged},      {"iterations", iterations},
                             {"newton_iterations", newtonIterations}, {"contact_changes", contactChanges},
                             {"flow_angle", flowAngle},     {"move", move},
                             {"seconds", seconds},          {"motion_seconds", motionSeconds},
                             {"resolve_seconds", resolveSeconds}, {"grazing_contacts", grazingContacts},
                             {"plain_fallbacks", plainFallbacks}, {"history", history}};
  if (!message.empty()) summary["free_surface"]["message"] = message;
}

void FreeSurfaceReport::continueFrom(const FreeSurfaceReport& earlier) {
  iterations += earlier.iterations;
  newtonIterations += earlier.newtonIterations;
  contactChanges += earlier.contactChanges;
  seconds += earlier.seconds;
  motionSeconds += earlier.motionSeconds;
  resolveSeconds += earlier.resolveSeconds;
  plainFallbacks += earlier.plainFallbacks;
  // The earlier entries keep their loop number; this loop's is one past the earlier's last.
  int loop = 0;
  nlohmann::json merged = nlohmann::json::array();
  for (const auto& entry : earlier.history) {
    merged.push_back(entry);
    if (!merged.back().contains("loop")) merged.back()["loop"] = 0;
    loop = std::max(loop, merged.back()["loop"].get<int>() + 1);
  }
  for (const auto& entry : history) {
    merged.push_back(entry);
    merged.back()["loop"] = loop;
  }
  history = std::move(merged);
}

FreeSurfaceLoop::FreeSurfaceLoop(const FreeSurfaces& surfaces, const Teuchos::ParameterList& settings)
    : m_surfaces(surfaces),
      m_maxIterations(settings.get<int>("Maximum Iterations")),
      m_angleTolerance(settings.get<double>("Flow Angle Tolerance")),
      m_moveTolerance(settings.get<double>("Move Tolerance")),
      m_andersonDepth(settings.get<int>("Anderson Depth")),
      m_relaxation(settings.get<std::string>("Relaxation") == "Aitken"     ? Relaxation::Aitken
                   : settings.get<std::string>("Relaxation") == "Anderson" ? Relaxation::Anderson
                   : settings.get<std::string>("Relaxation") == "Newton"   ? Relaxation::Newton
                                                                           : Relaxation::None) {}

FreeSurfaceReport FreeSurfaceLoop::run(const Mesh& mesh, const DofMap& dofMap, const std::vector<ContactWall>& walls,
                                       Geometry geometry, const Hooks& hooks, double toleranceScale) const {
  const auto start = std::chrono::steady_clock::now();
  FreeSurfaceReport report;
  const double moveLimit = toleranceScale * m_moveTolerance * m_surfaces.lengthScale();
  const double angleLimit = toleranceScale * m_angleTolerance;
  const int maxIterations = toleranceScale < 1.0 ? 3 * m_maxIterations : m_maxIterations;
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  // Aitken's Δ² relaxation (Irons–Tuck form): with r_k the plain update's residual,
  //   ω_k = −ω_{k−1} r_{k−1}·(r_k − r_{k−1}) / |r_k − r_{k−1}|²,
  // clamped to [kMinRelaxation, kMaxRelaxation]; reset to 1 when the surfaces' node sets change
  // (a contact status changed the runs). Relaxation = Anderson uses ω as its mixing.
  double relaxation = 1.0;
  std::vector<double> previousResidual;
  AndersonAcceleration anderson(m_andersonDepth);
  bool restartAnderson = false;  // the last re-solve changed a contact status, or its move was halved
  // An accelerated loop that makes no progress — its best max flow angle not bettered for
  // kStallUpdates updates (an exact 2-cycle, or a wander where halved moves keep resetting
  // Anderson's history) — goes on with the plain update, which does not cycle on the cutting
  // scene's chip corner (docs/verification.md §9).
  Relaxation mode = m_relaxation;
  double bestAngle = std::numeric_limits<double>::infinity();
  int sinceBest = 0;
  const BudgetScope scope("the free-surface loop", [&] { return std::to_string(report.iterations) + " update(s)"; });
  for (;;) {
    if (budgetSpent()) {  // the run's wall-clock budget (core/Budget.hpp)
      report.message = budgetMessage();
      break;
    }
    auto t = Clock::now();
    FreeSurfaceStep step = m_surfaces.step(mesh, dofMap, hooks.velocities(), walls, geometry, moveLimit);
    if (!step.failure.empty()) {
      report.message = "free-surface update impossible: " + step.failure;
      break;
    }
    report.motionSeconds += since(t);
    if (mode == Relaxation::Aitken || mode == Relaxation::Anderson) {
      if (previousResidual.size() == step.residual.size() && step.released.empty()) {
        double num = 0.0, den = 0.0;
        for (size_t i = 0; i < step.residual.size(); ++i) {
          const double dr = step.residual[i] - previousResidual[i];
          num += previousResidual[i] * dr;
          den += dr * dr;
        }
        relaxation = den > 0.0 ? std::clamp(-relaxation * num / den, kMinRelaxation, kMaxRelaxation) : 1.0;
      } else {
        relaxation = 1.0;
      }
      previousResidual = step.residual;
    }
    double stepGain = relaxation;  // the step over the plain update: ω, or Anderson's
    if (mode == Relaxation::Anderson)
      stepGain = andersonStep(mesh, step, anderson, restartAnderson, relaxation);
    else
      step.relax(relaxation);
    std::string newtonFailure;
    if (mode == Relaxation::Newton && !(step.maxFlowAngle <= angleLimit && step.maxMove <= moveLimit)) {
      // With a status change pending (released nodes) the linearization's unknowns differ: plain.
      std::vector<std::array<double, 2>> moves;
      if (!step.released.empty()) newtonFailure = "a contact status changes";
      else if (hooks.newtonMoves && hooks.newtonMoves(step, moves, newtonFailure) && moves.size() == step.moves.size())
        step.setMoves(moves);
      else log() << "flowform: free surface " << report.iterations << ": no Newton step (" << newtonFailure
                 << "); the plain update instead\n";
    }
    if (step.maxFlowAngle < bestAngle) {
      bestAngle = step.maxFlowAngle;
      sinceBest = 0;
    } else if (++sinceBest >= kStallUpdates && (mode == Relaxation::Aitken || mode == Relaxation::Anderson)) {
      log() << "flowform: free surface " << report.iterations << ": no progress in " << kStallUpdates
            << " updates (best max |u.n|/|u| " << bestAngle << "); the plain update from here\n";
      mode = Relaxation::None;
      relaxation = 1.0;
      ++report.plainFallbacks;
    }
    report.flowAngle = step.maxFlowAngle;
    report.move = step.maxMove;
    const std::pair<int, double> cycling = hooks.unsettledContacts ? hooks.unsettledContacts()
                                                                     : std::pair<int, double>{0, 0.0};
    const auto [unsettled, unsettledRatio] = cycling;
    const bool settled = FreeSurfaceLoop::settled(cycling);
    log() << "flowform: free surface " << report.iterations << ": max |u.n|/|u| = " << step.maxFlowAngle << " at ("
          << step.worstSegment[0] << ", " << step.worstSegment[1] << ")"
          << ", next move " << step.maxMove << " at (" << step.largestMoveAt[0] << ", " << step.largestMoveAt[1] << ")" << (step.clampedToTool ? ", " + std::to_string(step.clampedToTool) +
                                                                         " node(s) back on the tool"
                                                                   : std::string())
          << (step.released.empty() ? std::string()
                                    : ", " + std::to_string(step.released.size()) + " contact node(s) not reached")
          << (unsettled ? ", " + std::to_string(unsettled) + " contact node(s) cycling (" +
                              std::to_string(unsettledRatio) + " x tolerance)" : std::string())
          << "\n";
    if (step.maxFlowAngle <= angleLimit && step.maxMove <= moveLimit && step.released.empty() && settled) {
      report.converged = true;
      report.grazingContacts = unsettled;
      break;
    }
    if (report.iterations >= maxIterations) {
      report.message = "the free surfaces did not converge in " + std::to_string(maxIterations) +
                       " updates (Free Surface/Maximum Iterations) (max |u.n|/|u| = " +
                       std::to_string(step.maxFlowAngle) + ", node move " + std::to_string(step.maxMove) +
                       (unsettled ? ", " + std::to_string(unsettled) + " contact node(s) cycling" : std::string()) + ")";
      break;
    }
    for (const auto& [w, k] : step.released) hooks.release(w, k);
    t = Clock::now();
    // The move; where it would invert a cell (a start far from the streamline), half of it, up to
    // kMaxHalvings times (logged), then the loop gives up.
    int halvings = 0;
    try {
      HarmonicExtension extension(mesh, step.prescribed);
      for (;; ++halvings) {
        try {
          hooks.moveNodes(extension.positions(step.displacement));
          break;
        } catch (const InputError& e) {
          if (halvings == kMaxHalvings) throw;
          log() << "flowform: free surface " << report.iterations << ": the move inverts a cell; halved (" << e.what()
                << ")\n";
          for (auto& d : step.displacement) d = {0.5 * d[0], 0.5 * d[1]};
        }
      }
    } catch (const InputError& e) {
      report.message = std::string("the free-surface update would invert the mesh: ") + e.what();
      break;
    } catch (const std::exception& e) {
      report.message = std::string("the free-surface mesh motion failed: ") + e.what();
      break;
    }
    report.motionSeconds += since(t);
    ++report.iterations;
    int newton = 0, changes = 0;
    std::string why;
    t = Clock::now();
    const bool ok = hooks.resolve(newton, changes, why);
    report.resolveSeconds += since(t);
    report.newtonIterations += newton;
    report.contactChanges += changes;
    // The map changed (a status changed in the re-solve, or a node the update released) or the
    // move was not the step's (halved): Anderson's history starts again at the next update.
    restartAnderson = changes > 0 || halvings > 0 || !step.released.empty();
    report.history.push_back({{"flow_angle", step.maxFlowAngle}, {"move", step.maxMove}, {"relaxation", stepGain},
                              {"clamped_to_tool", step.clampedToTool}, {"released", step.released.size()},
                              {"halvings", halvings}, {"newton_iterations", newton},
                              {"contact_changes", changes}});
    if (!ok) {
      report.message = "the flow re-solve after free-surface update " + std::to_string(report.iterations) +
                       " did not converge: " + why;
      break;
    }
  }
  report.seconds = secondsSince(start);
  if (report.converged)
    log() << "flowform: free surfaces converged in " << report.iterations << " update(s), "
          << report.newtonIterations << " Newton iterations\n";
  else
    log() << "flowform: FREE SURFACES NOT CONVERGED: " << report.message << "\n";
  return report;
}

double FreeSurfaceLoop::andersonStep(const Mesh& mesh, FreeSurfaceStep& step, AndersonAcceleration& anderson,
                                     bool restart, double omega) const {
  // The unknowns: every move's node position along its directions (the residual's layout), each
  // entry's direction and move.
  std::vector<double> x;
  const std::vector<double>& f = step.residual;
  std::vector<std::array<double, 2>> directions;
  std::vector<size_t> ofMove;
  for (size_t k = 0; k < step.moves.size(); ++k)
    for (const auto& d : step.moves[k].directions()) {
      const auto& p = mesh.coords[step.moves[k].node];
      x.push_back(p[0] * d[0] + p[1] * d[1]);
      directions.push_back(d);
      ofMove.push_back(k);
    }
  // A status change alters the map (released nodes, a re-solve that changed statuses) and a halved
  // move did not go where the step said: the history no longer describes it.
  if (restart || !step.released.empty()) anderson.reset();
  // The mixing β is Aitken's ω of this update: the plain step relaxed as Aitken would (an overshooting
  // mode, as at a refined chip's corner, damped), the history removing the slow modes.
  std::vector<double> dx = anderson.step(x, f, omega);
  // Safeguard: a step more than kMaxAndersonGain times the plain one is not trusted (a history
  // from a different regime): the plain update, and the history starts again.
  // A non-finite entry (an overflowing γ) is refused the same way.
  double fMax = 0.0, dxMax = 0.0;
  bool finite = true;
  for (size_t i = 0; i < f.size(); ++i) {
    fMax = std::max(fMax, std::abs(f[i]));
    dxMax = std::max(dxMax, std::abs(dx[i]));
    finite = finite && std::isfinite(dx[i]);
  }
  if (!finite || !(dxMax <= kMaxAndersonGain * fMax)) {
    anderson.reset();
    dx = anderson.step(x, f, omega);
    dxMax = omega * fMax;
  }
  const double gain = fMax > 0.0 ? dxMax / fMax : 1.0;
  std::vector<std::array<double, 2>> perMove(step.moves.size(), {0.0, 0.0});
  for (size_t i = 0; i < dx.size(); ++i) {
    perMove[ofMove[i]][0] += dx[i] * directions[i][0];
    perMove[ofMove[i]][1] += dx[i] * directions[i][1];
  }
  step.setMoves(perMove);
  return gain;
}

}  // namespace flowform
