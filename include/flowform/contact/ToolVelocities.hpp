// The moving tools' surface velocities at their wall nodes, as a dof vector. Differences in the
// node positions (a free surface's linearization, a shape parameter's mesh partials) hold the flow
// while nodes move; a node of a moving tool that moves with its tool should keep its velocity
// relative to the tool instead, or the wall's penalty answers to a relative velocity the move
// itself made: the differences are then taken at x + v_w(X') − v_w(X), the tool velocities after
// the move less those before (docs/theory.md §3.5).
#pragma once

#include <vector>

#include "flowform/contact/ContactWall.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/discretization/DofMap.hpp"

namespace flowform {

/// On `map` (owned dofs): at every node of a moving wall its tool's velocity there, at the walls'
/// current positions; 0 elsewhere. Null when no wall moves.
Teuchos::RCP<Vector> toolVelocities(const std::vector<ContactWall>& walls, const DofMap& dofMap,
                                    const Teuchos::RCP<const Map>& map);

/// `moved` = x + v_w(now) − `before` (before = toolVelocities at x's positions; null: `moved` = x),
/// the flow that follows the tools to where the walls are now. Returns v_w(now) (null with `before`).
Teuchos::RCP<Vector> followTools(const std::vector<ContactWall>& walls, const DofMap& dofMap, const Vector& x,
                                 const Teuchos::RCP<const Vector>& before, Vector& moved);

}  // namespace flowform
