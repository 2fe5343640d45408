// The state of every contact-wall node at a solution: its values (p, u, replicated on every
// rank), the branch of its friction law, and what makes the law kink there. The status loop
// reads them to decide changes; the finite-difference check compares them between runs.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "flowform/contact/ContactWall.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/discretization/DofMap.hpp"

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

/// Pressure and velocity at every node of `wall`, on every rank (collective).
void wallValues(const ContactWall& wall, const DofMap& dofMap, const Vector& x, std::vector<double>& p,
                std::vector<std::array<double, 2>>& u);

/// The branch of the friction law (free, no friction, stick, slip) at every node of every
/// wall, on every rank: the state whose change makes a derivative one-sided.
std::vector<std::vector<FrictionBranch>> wallBranches(const std::vector<ContactWall>& walls, const DofMap& dofMap,
                                                      const Vector& x);
/// The branch and, at active nodes of walls whose law uses ν, the sign of p: the state
/// whose change between h − δ, h and h + δ makes a finite difference straddle a kink.
std::vector<std::vector<WallNodeState>> wallStates(const std::vector<ContactWall>& walls, const DofMap& dofMap,
                                                   const Vector& x);

}  // namespace flowform
