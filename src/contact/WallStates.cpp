#include "flowform/contact/WallStates.hpp"

namespace flowform {

std::string WallNodeState::name() const {
  return std::string(frictionBranchName(branch)) + (branch != FrictionBranch::Free && !compressed ? " (p <= 0)" : "") +
         (slipSign > 0 ? " (u_t > 0)" : slipSign < 0 ? " (u_t < 0)" : "");
}

void wallValues(const ContactWall& wall, const DofMap& dofMap, const Vector& x, std::vector<double>& p,
                std::vector<std::array<double, 2>>& u) {
  std::vector<GO> gids;
  for (GO node : wall.curve().nodes)
    for (int c : {kUx, kUy, kP}) gids.push_back(dofMap.globalDof(node, c));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto replicated = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(gids), 0, dofMap.comm()));
  Vector values(replicated);
  values.doImport(x, Import(dofMap.ownedMap(), replicated), Tpetra::INSERT);
  auto v = values.getLocalViewHost(Tpetra::Access::ReadOnly);
  p.resize(wall.numNodes());
  u.resize(wall.numNodes());
  for (int k = 0; k < wall.numNodes(); ++k) {
    u[k] = {v(3 * k + 0, 0), v(3 * k + 1, 0)};  // the replicated vector holds u_x, u_y, p per wall node
    p[k] = v(3 * k + 2, 0);
  }
}

namespace {

/// The friction law's branch at every node of `wall`, from its replicated p and u.
std::vector<FrictionBranch> branchesOf(const ContactWall& wall, const std::vector<double>& p,
                                         const std::vector<std::array<double, 2>>& u) {
  std::vector<FrictionBranch> b(wall.numNodes());
  for (int k = 0; k < wall.numNodes(); ++k) {
    const auto v = wall.stencilValues(k, p, u);
    wall.tangentialForce(k, wall.frictionParameters(), v.data(), &b[k]);
  }
  return b;
}

}  // namespace

std::vector<std::vector<FrictionBranch>> wallBranches(const std::vector<ContactWall>& walls, const DofMap& dofMap,
                                                      const Vector& x) {
  std::vector<std::vector<FrictionBranch>> all;
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (const ContactWall& wall : walls) {
    wallValues(wall, dofMap, x, p, u);
    all.push_back(branchesOf(wall, p, u));
  }
  return all;
}

std::vector<std::vector<WallNodeState>> wallStates(const std::vector<ContactWall>& walls, const DofMap& dofMap,
                                                   const Vector& x) {
  std::vector<std::vector<WallNodeState>> all(walls.size());
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (size_t w = 0; w < walls.size(); ++w) {
    wallValues(walls[w], dofMap, x, p, u);  // one collective Import per wall, for branches and states alike
    const std::vector<FrictionBranch> b = branchesOf(walls[w], p, u);
    const bool usesPressure = walls[w].usesFrictionCoefficient();
    // The pressure sign matters only where friction acts (P_k > 0 decides "no friction");
    // at a free node p ≈ 0 and its sign is noise, not a state.
    const bool coulombLike = usesPressure || walls[w].usesShearFactor();  // not Norton (smooth) or None
    for (int k = 0; k < walls[w].numNodes(); ++k) {
      const bool free = b[k] == FrictionBranch::Free;
      const bool slips = b[k] == FrictionBranch::Slip || b[k] == FrictionBranch::SlipTresca;
      const double ut = walls[w].relativeSlip(k, u[k].data());  // (u − v_w)·t, t = (−n_y, n_x), as the law takes it
      const int sign = coulombLike && slips ? (ut >= 0.0 ? 1 : -1) : 0;
      all[w].push_back({b[k], free || !usesPressure ? true : p[k] > 0.0, sign});
    }
  }
  return all;
}

}  // namespace flowform
