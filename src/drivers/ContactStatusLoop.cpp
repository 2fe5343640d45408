#include "flowform/contact/StatusLoop.hpp"

#include "flowform/Log.hpp"

namespace flowform {

std::string WallNodeState::name() const {
  return std::string(frictionBranchName(branch)) + (branch != FrictionBranch::Free && !compressed ? " (p <= 0)" : "") +
         (slipSign > 0 ? " (u_t > 0)" : slipSign < 0 ? " (u_t < 0)" : "");
}

ContactStatusLoop::ContactStatusLoop(const Teuchos::ParameterList& contact, const Mesh& mesh, const DofMap& dofMap)
    : m_maxChanges(contact.get<int>("Max Status Changes")),
      m_maxPerNode(contact.get<int>("Max Changes Per Node")),
      m_pressureTolerance(contact.get<double>("Pressure Tolerance")),
      m_penetrationTolerance(contact.get<double>("Penetration Tolerance")),
      m_mesh(mesh),
      m_dofMap(dofMap) {}

void ContactStatusLoop::wallValues(const ContactWall& wall, const Vector& x, std::vector<double>& p,
                                   std::vector<std::array<double, 2>>& u) const {
  std::vector<GO> gids;
  for (GO node : wall.curve().nodes)
    for (int c = 0; c < kDofsPerNode; ++c) gids.push_back(kDofsPerNode * node + c);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto replicated = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(gids), 0, m_dofMap.comm()));
  Vector values(replicated);
  values.doImport(x, Import(m_dofMap.ownedMap(), replicated), Tpetra::INSERT);
  auto v = values.getLocalViewHost(Tpetra::Access::ReadOnly);
  p.resize(wall.numNodes());
  u.resize(wall.numNodes());
  for (int k = 0; k < wall.numNodes(); ++k) {
    u[k] = {v(kDofsPerNode * k + kUx, 0), v(kDofsPerNode * k + kUy, 0)};
    p[k] = v(kDofsPerNode * k + kP, 0);
  }
}

namespace {

/// The friction law's branch at every node of `wall`, from its replicated p and u.
std::vector<FrictionBranch> wallBranches(const ContactWall& wall, const std::vector<double>& p,
                                         const std::vector<std::array<double, 2>>& u) {
  std::vector<FrictionBranch> b(wall.numNodes());
  for (int k = 0; k < wall.numNodes(); ++k) {
    auto pressure = [&](int j) { return j < 0 ? 0.0 : p[j]; };
    const double pk[3] = {pressure(wall.previous(k)), p[k], pressure(wall.next(k))};
    wall.tangentialForce(k, wall.frictionParameters(), u[k].data(), pk, &b[k]);
  }
  return b;
}

}  // namespace

std::vector<std::vector<FrictionBranch>> ContactStatusLoop::branches(const std::vector<ContactWall>& walls,
                                                                     const Vector& x) const {
  std::vector<std::vector<FrictionBranch>> all;
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (const ContactWall& wall : walls) {
    wallValues(wall, x, p, u);
    all.push_back(wallBranches(wall, p, u));
  }
  return all;
}

std::vector<std::vector<WallNodeState>> ContactStatusLoop::states(const std::vector<ContactWall>& walls,
                                                                   const Vector& x) const {
  std::vector<std::vector<WallNodeState>> all(walls.size());
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (size_t w = 0; w < walls.size(); ++w) {
    wallValues(walls[w], x, p, u);  // one collective Import per wall, for branches and states alike
    const std::vector<FrictionBranch> b = wallBranches(walls[w], p, u);
    const bool usesPressure = walls[w].usesFrictionCoefficient();
    // The pressure sign matters only where friction acts (P_k > 0 decides "no friction");
    // at a free node p ≈ 0 and its sign is noise, not a state.
    const bool coulombLike = usesPressure || walls[w].usesShearFactor();  // not Norton (smooth) or None
    for (int k = 0; k < walls[w].numNodes(); ++k) {
      const bool free = b[k] == FrictionBranch::Free;
      const bool slips = b[k] == FrictionBranch::Slip || b[k] == FrictionBranch::SlipTresca;
      const auto& n = walls[w].curve().normals[k];
      const double ut = -n[1] * u[k][0] + n[0] * u[k][1];  // u·t, t = (−n_y, n_x), as the law takes it
      const int sign = coulombLike && slips ? (ut >= 0.0 ? 1 : -1) : 0;
      all[w].push_back({b[k], free || !usesPressure ? true : p[k] > 0.0, sign});
    }
  }
  return all;
}

int ContactStatusLoop::run(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics,
                           std::vector<ContactWall>& walls, SolveReport& report) const {
  int changes = 0;
  while (report.converged) {
    // The largest violation over all walls, at a limit of a contact zone (SPEC §2).
    int wallIndex = -1, unsettled = 0;
    StatusChange best;
    std::vector<double> p;
    std::vector<std::array<double, 2>> u;
    for (size_t w = 0; w < walls.size(); ++w) {
      wallValues(walls[w], x, p, u);
      int stuck = 0;
      const StatusChange c =
          walls[w].nextChange(p, u, m_pressureTolerance, m_penetrationTolerance, m_maxPerNode, &stuck);
      unsettled += stuck;
      if (c.node >= 0 && c.violation > best.violation) {
        best = c;
        wallIndex = static_cast<int>(w);
      }
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
    const SolveReport again = solver.resolve(x, physics);
    report.newtonIterations += again.newtonIterations;
    report.converged = again.converged;
    report.residualNorm = again.residualNorm;
    if (!again.converged) report.message = "after contact change " + std::to_string(changes) + ": " + again.message;
  }
  log() << "contact: " << changes << " status change(s)\n";
  return changes;
}

}  // namespace flowform
