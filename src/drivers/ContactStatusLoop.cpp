#include "flowform/drivers/ContactStatusLoop.hpp"

#include "flowform/core/Log.hpp"

namespace flowform {

ContactStatusLoop::ContactStatusLoop(const Teuchos::ParameterList& contact, const Mesh& mesh, const DofMap& dofMap)
    : m_maxChanges(contact.get<int>("Max Status Changes")),
      m_maxPerNode(contact.get<int>("Max Changes Per Node")),
      m_pressureTolerance(contact.get<double>("Pressure Tolerance")),
      m_penetrationTolerance(contact.get<double>("Penetration Tolerance")),
      m_resolveTolerance(contact.get<double>("Re-solve Tolerance")),
      m_mesh(mesh),
      m_dofMap(dofMap) {}

int ContactStatusLoop::run(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics,
                           std::vector<ContactWall>& walls, SolveReport& report) const {
  int changes = 0;
  bool tight = true;  // whether x is a tightly converged solution (the first solve's is)
  // One re-solve from x, recorded in the report (`loose`: the relative tolerance, 0 tight).
  auto resolve = [&](double loose) {
    const SolveReport again = solver.resolve(x, physics, loose);
    tight = loose <= 0.0;
    report.newtonIterations += again.newtonIterations;
    report.newtonPerSolve.push_back(again.newtonIterations);
    report.restarts += again.restarts;
    report.converged = again.converged;
    report.residualNorm = again.residualNorm;
    if (!again.converged) report.message = "after contact change " + std::to_string(changes) + ": " + again.message;
  };
  while (report.converged) {
    // The largest violation over all walls, at a limit of a contact zone (docs/theory.md §2).
    int wallIndex = -1, unsettled = 0;
    StatusChange best;
    std::vector<double> p;
    std::vector<std::array<double, 2>> u;
    for (size_t w = 0; w < walls.size(); ++w) {
      wallValues(walls[w], m_dofMap, x, p, u);
      int stuck = 0;
      const StatusChange c =
          walls[w].nextChange(p, u, m_pressureTolerance, m_penetrationTolerance, m_maxPerNode, &stuck);
      unsettled += stuck;
      if (c.node >= 0 && c.violation > best.violation) {
        best = c;
        wallIndex = static_cast<int>(w);
      }
    }
    if (wallIndex < 0 && !tight) {
      // No change read from a loosely solved state: converge it tightly and look again.
      resolve(0.0);
      continue;
    }
    if (wallIndex < 0) {
      if (unsettled > 0) {
        report.converged = false;
        report.message = std::to_string(unsettled) + " contact node(s) cycle between active and free (each changed " +
                         std::to_string(m_maxPerNode) + " times) and still violate their criterion";
      }
      break;
    }
    if (changes >= m_maxChanges) {
      report.converged = false;
      report.message = "the contact status did not settle after " + std::to_string(m_maxChanges) + " changes";
      break;
    }
    ContactWall& wall = walls[wallIndex];
    const auto& xy = m_mesh.coords[wall.curve().nodes[best.node]];
    log() << "contact: wall '" << wall.name() << "' node " << wall.curve().nodes[best.node] << " at (" << xy[0] << ", "
          << xy[1] << "): " << (best.activate ? "free -> active (penetration " : "active -> free (tension ")
          << best.violation << ")\n";
    wall.setActive(best.node, best.activate);
    ++changes;
    // The next change is read from this state: a loose solve suffices while changes follow;
    // the last state is converged tightly above.
    resolve(m_resolveTolerance);
  }
  log() << "contact: " << changes << " status change(s)\n";
  return changes;
}

}  // namespace flowform
