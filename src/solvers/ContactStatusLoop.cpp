#include "flowform/solvers/ContactStatusLoop.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Log.hpp"

namespace flowform {

ContactStatusLoop::ContactStatusLoop(const Teuchos::ParameterList& contact, const Mesh& mesh, const DofMap& dofMap)
    : m_maxChanges(contact.get<int>("Max Status Changes")),
      m_maxPerNode(contact.get<int>("Max Changes Per Node")),
      m_pressureTolerance(contact.get<double>("Pressure Tolerance")),
      m_penetrationTolerance(contact.get<double>("Penetration Tolerance")),
      m_resolveTolerance(contact.get<double>("Re-solve Tolerance")),
      m_certainIterate(contact.get<std::string>("Status Update") != "Converged State"),
      m_complementarity(contact.get<std::string>("Status Update") == "Complementarity"),
      m_mesh(mesh),
      m_dofMap(dofMap) {}

std::vector<ContactStatusLoop::WallValues> ContactStatusLoop::gatherWallValues(const std::vector<ContactWall>& walls,
                                                                               const Vector& x) const {
  std::vector<WallValues> values(walls.size());
  for (size_t w = 0; w < walls.size(); ++w) wallValues(walls[w], m_dofMap, x, values[w].p, values[w].u);
  return values;
}

ContactStatusLoop::Decision ContactStatusLoop::decide(const std::vector<ContactWall>& walls,
                                                      const std::vector<WallValues>& values, double pressureShift,
                                                      double penetrationShift) const {
  // The largest violation over all walls, at a limit of a contact zone (docs/theory.md §2).
  Decision d;
  for (size_t w = 0; w < walls.size(); ++w) {
    int stuck = 0;
    double second = 0.0, ratio = 0.0;
    const StatusChange c = walls[w].nextChange(values[w].p, values[w].u, m_pressureTolerance + pressureShift,
                                               m_penetrationTolerance + penetrationShift, m_maxPerNode, &stuck, &second,
                                               &ratio);
    d.unsettled += stuck;
    d.unsettledRatio = std::max(d.unsettledRatio, ratio);
    if (c.node < 0) continue;
    if (c.violation > d.change.violation) {
      d.runnerUp = std::max({d.runnerUp, d.change.violation, second});
      d.change = c;
      d.wall = static_cast<int>(w);
    } else {
      d.runnerUp = std::max(d.runnerUp, c.violation);
    }
  }
  return d;
}

bool ContactStatusLoop::certain(const std::vector<ContactWall>& walls, const std::vector<WallValues>& values,
                                const Decision& d, double pressureError, double penetrationError) const {
  // Every state within the error bounds of x gives the decision d: the same change (or none)
  // with every violation moved by ±error, and a margin to the runner-up that no error can close.
  auto same = [&](const Decision& e) {
    return e.wall == d.wall && e.change.node == d.change.node && e.change.activate == d.change.activate;
  };
  const Decision more = decide(walls, values, -pressureError, -penetrationError);  // every violation larger
  const Decision fewer = decide(walls, values, pressureError, penetrationError);   // every violation smaller
  if (!same(more) || !same(fewer)) return false;
  if (d.wall < 0) return true;
  return more.change.violation - more.runnerUp > 2.0 * std::max(pressureError, penetrationError);
}

std::string ContactStatusLoop::cyclingMessage(const std::vector<ContactWall>& walls,
                                              const std::vector<WallValues>& values, int total) const {
  auto number = [](double v) {
    std::ostringstream os;
    os << std::setprecision(3) << v;
    return os.str();
  };
  std::string where, hints;
  for (size_t w = 0; w < walls.size(); ++w) {
    const ContactWall& wall = walls[w];
    const std::vector<int> nodes = wall.cyclingNodes(values[w].p, values[w].u, m_pressureTolerance,
                                                     m_penetrationTolerance, m_maxPerNode);
    if (nodes.empty()) continue;
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    int active = 0;
    for (int k : nodes) {
      const auto& xy = m_mesh.coords[wall.curve().nodes[k]];
      for (int i = 0; i < 2; ++i) {
        lo[i] = std::min(lo[i], xy[i]);
        hi[i] = std::max(hi[i], xy[i]);
      }
      active += wall.isActive(k);
    }
    auto range = [&](int i) {
      return lo[i] == hi[i] ? std::string(i ? "y = " : "x = ") + number(lo[i])
                            : std::string(i ? "y " : "x ") + number(lo[i]) + ".." + number(hi[i]);
    };
    where += std::string(where.empty() ? "" : "; ") + std::to_string(nodes.size()) + " on wall '" + wall.name() +
             "' at " + range(0) + ", " + range(1) + " (" + std::to_string(active) + " active in tension, " +
             std::to_string(nodes.size() - active) + " free and penetrating)";
    hints += std::string(hints.empty() ? "" : ", ") + "Boundary Conditions/" + wall.name() + "/Released Nodes=Never";
  }
  return "the contact status does not settle: " + std::to_string(total) +
         " node(s) cycle between active and free: " + where + "; each changed " + std::to_string(m_maxPerNode) +
         " times (Contact/Max Changes Per Node) and still violates its criterion (released in tension, the node "
         "then penetrates). To try: " + hints +
         " (a bilateral wall: the nodes stay on the tool, which may then pull; check p in the wall's boundary CSV); "
         "a finer mesh (Mesh/Geo Parameters, Mesh/Uniform Refinements); a larger Contact/Pressure Tolerance. "
         "More Contact/Max Changes Per Node or Contact/Status Update=Converged State did not help in the cases tried";
}

int ContactStatusLoop::run(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics,
                           std::vector<ContactWall>& walls, SolveReport& report) const {
  int changes = 0;
  bool tight = true;  // whether x is a tightly converged solution (the first solve's is)
  double pressureError = 0.0, penetrationError = 0.0;  // bounds of x's error at the wall nodes
  double reference = 0.0;  // ||F_0|| of the current re-solve
  int steps = 0;           // Newton iterations of the current re-solve
  bool readable = false;   // x is an iterate whose last step bounds its error

  // Newton from x, recorded in the report. `options.continuing`: the same re-solve goes on
  // (its iterations add to the last entry of newtonPerSolve).
  auto resolve = [&](NewtonOptions options) {
    // A re-solve converged to the tolerances tries the last factors first (NewtonOptions::
    // reuseFactors; resolve() uses them for uncapped, tight solves only). An iterate is read only
    // after a Newton step: a simplified step that halves ||F|| bounds nothing (the old factors may
    // not see the change, and its step is then small).
    options.reuseFactors = true;
    const Vector before(x, Teuchos::Copy);
    if (options.continuing) options.referenceResidual = reference;
    const SolveReport again = solver.resolve(x, physics, options);
    if (!options.continuing) {
      reference = again.stages.empty() ? 0.0 : again.stages.front().initialResidualNorm;
      steps = 0;
      report.newtonPerSolve.push_back(0);
    }
    steps += again.newtonIterations;
    report.newtonIterations += again.newtonIterations;
    report.newtonPerSolve.back() += again.newtonIterations;
    report.restarts += again.restarts;
    report.residualNorm = again.residualNorm;
    report.converged = again.converged || again.stoppedAtCap;
    tight = again.converged && options.looseTolerance <= 0.0;
    pressureError = penetrationError = 0.0;
    // An iterate is read only after a full Newton step that multiplied ||F|| by at most
    // kContraction = 1/2: Newton contracts, and the remaining error (a geometric series of
    // ratio <= 1/2) is below the step. Otherwise the step bounds nothing; another one follows.
    const StageReport* last = again.stages.empty() ? nullptr : &again.stages.back();
    readable = again.stoppedAtCap && last && last->lastStep == 1.0 &&
               last->newtonIterations == 1 && last->residualNorm <= kContraction * last->startResidualNorm;
    if (readable) {
      // The error of the iterate at the wall nodes, bounded by the last Newton step.
      Vector step(x, Teuchos::Copy);
      step.update(-1.0, before, 1.0);
      std::vector<double> dp;
      std::vector<std::array<double, 2>> du;
      for (const ContactWall& wall : walls) {
        wallValues(wall, m_dofMap, step, dp, du);
        for (size_t k = 0; k < dp.size(); ++k) {
          pressureError = std::max(pressureError, std::abs(dp[k]));
          penetrationError = std::max({penetrationError, std::abs(du[k][0]), std::abs(du[k][1])});
        }
      }
    }
    if (!report.converged) report.message = "after contact change " + std::to_string(changes) + ": " + again.message;
  };
  // Converges the current re-solve to the Solver tolerances (converged means tight then).
  auto converge = [&]() {
    NewtonOptions options;
    options.continuing = true;
    resolve(options);
  };

  const BudgetScope scope("the contact-status loop",
                          [&] { return std::to_string(changes) + " status change(s)"; });
  // Every pass of the loop either changes a status (at most Max Status Changes), or takes one
  // more Newton iteration (at most kMaxStepsPerChange per change), or converges a re-solve;
  // kPassesPerChange passes per change bound them all, a cap that only a bug can reach.
  const long maxPasses = kPassesPerChange * (static_cast<long>(m_maxChanges) + 1);
  long passes = 0;
  while (report.converged) {
    if (budgetSpent()) {
      report.converged = false;
      report.message = budgetMessage();
      break;
    }
    if (++passes > maxPasses) {
      report.converged = false;
      report.message = "the contact-status loop made " + std::to_string(maxPasses) + " passes after " +
                       std::to_string(changes) + " status change(s) without settling";
      break;
    }
    // Not yet sure what the converged state would decide (an iterate whose error nothing
    // bounds, or a decision not certain within the bound): one more Newton iteration.
    auto oneMoreIteration = [&]() {
      if (steps >= kMaxStepsPerChange) {
        converge();
        return;
      }
      NewtonOptions options;
      options.continuing = true;
      options.maxIterations = 1;
      resolve(options);
    };
    if (!tight && m_certainIterate && !readable) {
      oneMoreIteration();
      continue;
    }
    const std::vector<WallValues> values = gatherWallValues(walls, x);
    const Decision d = decide(walls, values);
    if (!tight && m_certainIterate && !certain(walls, values, d, pressureError, penetrationError)) {
      oneMoreIteration();
      continue;
    }
    if (d.wall < 0 && !tight) {
      // No change read from an iterate or a loosely solved state: converge it tightly and look again.
      converge();
      continue;
    }
    report.unsettledContacts = 0;
    report.unsettledContactRatio = 0.0;
    if (d.wall < 0 && d.unsettled > 0 && m_tolerateCycling) {
      // A separation point inside a segment: the nodes that cycle decide by themselves
      // (ContactWall::letCyclingNodesDecide), and the state is solved again with them.
      int deciding = 0;
      for (size_t w = 0; w < walls.size(); ++w)
        deciding += walls[w].letCyclingNodesDecide(values[w].p, values[w].u, m_pressureTolerance,
                                                   m_penetrationTolerance, m_maxPerNode);
      if (deciding > 0) {
        log() << "contact: " << deciding << " node(s) that cycle between active and free now decide by themselves "
              << "(normal force alpha_n max(u.n, 0))\n";
        converge();
        continue;
      }
    }
    if (d.wall < 0) {
      if (d.unsettled > 0 && m_tolerateCycling) {
        report.unsettledContacts = d.unsettled;
        report.unsettledContactRatio = d.unsettledRatio;
        log() << "contact: " << d.unsettled << " node(s) cycle between active and free (violation up to "
              << d.unsettledRatio << " x its tolerance); left as they are while the free surfaces move\n";
      } else if (d.unsettled > 0) {
        report.converged = false;
        report.message = cyclingMessage(walls, values, d.unsettled);
      }
      break;
    }
    if (changes >= m_maxChanges) {
      report.converged = false;
      report.message = "the contact status did not settle after " + std::to_string(m_maxChanges) + " changes";
      break;
    }
    ContactWall& wall = walls[d.wall];
    const StatusChange& best = d.change;
    const auto& xy = m_mesh.coords[wall.curve().nodes[best.node]];
    log() << "contact: wall '" << wall.name() << "' node " << wall.curve().nodes[best.node] << " at (" << xy[0] << ", "
          << xy[1] << "): " << (best.activate ? "free -> active (penetration " : "active -> free (tension ")
          << best.violation << ")" << (tight ? "" : " [read from an iterate]") << "\n";
    wall.setActive(best.node, best.activate);
    ++changes;
    // The next change is read from the first iterate that decides it for certain, or from a
    // state solved to the re-solve tolerance; the last state is converged tightly above.
    NewtonOptions options;
    if (m_certainIterate)
      options.maxIterations = 1;
    else
      options.looseTolerance = m_resolveTolerance;
    resolve(options);
  }
  log() << "contact: " << changes << " status change(s)\n";
  // The complementarity nodes' contact as the converged state has it (responses and outputs read it).
  if (report.converged) {
    const std::vector<WallValues> values = gatherWallValues(walls, x);
    for (size_t w = 0; w < walls.size(); ++w) {
      if (!walls[w].complementarity()) continue;
      const int changed = walls[w].readContact(values[w].u);
      int pressing = 0, nodes = 0;
      for (int k = 0; k < walls[w].numNodes(); ++k)
        if (walls[w].isComplementary(k)) {
          ++nodes;
          pressing += walls[w].isActive(k);
        }
      if (nodes > 0)
        log() << "contact: wall '" << walls[w].name() << "': " << pressing << " of " << nodes
              << " complementarity node(s) press on the tool (" << changed << " changed)\n";
      changes += changed;
    }
  }
  return changes;
}

}  // namespace flowform
