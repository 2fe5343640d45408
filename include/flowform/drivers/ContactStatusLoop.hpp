// The contact-status loop (SPEC §2, paper §2.1): after a converged flow solve, change one
// wall node's status — an active node in tension is released, a free node that penetrates
// is activated, at the current limit of the contact zone — and solve again, until no
// change is needed. Every change is logged. Used by the primal run and by each
// finite-difference run of the sensitivity check, which starts from the converged state.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/DofMap.hpp"
#include "flowform/Mesh.hpp"
#include "flowform/NonlinearSolver.hpp"
#include "flowform/contact/ContactWall.hpp"

namespace flowform {

/// What makes the law kink at a wall node: its friction branch, and for laws with ν p⁺
/// whether the node's own pressure is positive (p⁺ = max(p, 0) kinks at p = 0).
struct WallNodeState {
  FrictionBranch branch = FrictionBranch::Free;
  bool compressed = false;
  /// sign(u_t) of a node slipping under Coulomb/Tresca/Orowan friction (0 otherwise): the
  /// force f̂ sign(u_t) and ∂g/∂ν = P_k sign(u_t) jump where it flips, also at ν = 0 where the
  /// stick range is empty and no branch changes.
  int slipSign = 0;
  bool operator==(const WallNodeState& o) const {
    return branch == o.branch && compressed == o.compressed && slipSign == o.slipSign;
  }
  bool operator!=(const WallNodeState& o) const { return !(*this == o); }
  /// e.g. "stick", "slip (p <= 0)".
  std::string name() const;
};

class ContactStatusLoop {
 public:
  /// `contact` is the validated "Contact" sublist.
  ContactStatusLoop(const Teuchos::ParameterList& contact, const Mesh& mesh, const DofMap& dofMap);

  /// Runs the loop from the converged x: changes statuses in `walls`, re-solves with
  /// `solver` at `physics`, and adds the Newton iterations, the convergence and the
  /// message to `report`. Returns the number of changes made.
  int run(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics, std::vector<ContactWall>& walls,
          SolveReport& report) const;

  /// Pressure and velocity at every node of `wall`, on every rank.
  void wallValues(const ContactWall& wall, const Vector& x, std::vector<double>& p,
                  std::vector<std::array<double, 2>>& u) const;

  /// The branch of the friction law (free, no friction, stick, slip) at every node of
  /// every wall, on every rank: the state whose change makes a derivative one-sided.
  std::vector<std::vector<FrictionBranch>> branches(const std::vector<ContactWall>& walls, const Vector& x) const;
  /// The branch and, at active nodes of walls whose law uses ν, the sign of p: the state
  /// whose change between h − δ, h and h + δ makes a finite difference straddle a kink.
  std::vector<std::vector<WallNodeState>> states(const std::vector<ContactWall>& walls, const Vector& x) const;

 private:
  int m_maxChanges, m_maxPerNode;
  double m_pressureTolerance, m_penetrationTolerance;
  const Mesh& m_mesh;
  const DofMap& m_dofMap;
};

}  // namespace flowform
