// Convex tool corners: nodes shared by two contact walls where the material's angle is
// reflex, as at a die lip (docs/contact.md).
#pragma once

#include <vector>

#include "flowform/contact/ContactWall.hpp"

namespace flowform {

/// Nodes shared by two walls where the material's angle is reflex (a convex tool corner, as
/// at a die lip): with d the direction along wall a away from the node, the material angle
/// is reflex when d points to the tool side of wall b (d·n_b > 0). There each wall's
/// penetration test also needs the other wall's normal (ContactWall::addCornerNormal).
void markConvexToolCorners(std::vector<ContactWall>& walls);

}  // namespace flowform
