// The sum over a boundary group's owned nodes of the reactions R_i (the unconstrained momentum
// residual: the force the tool applies to the material), weighted per node: what Boundary Force,
// Mean Pressure and Boundary Power share (each node once, by its owner).
#pragma once

#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

/// Σ_k over the owned nodes of `curve` of add(local, k, n, R_x, R_y) (n the overlap index).
template <typename Scalar, typename Add>
Scalar sumOfReactions(const ResponseContext<Scalar>& c, const BoundaryCurve& curve, Add&& add) {
  Scalar local = 0.0;
  for (size_t k = 0; k < curve.nodes.size(); ++k) {
    const LO n = c.dofMap.overlapIndex(curve.nodes[k]);
    if (!c.dofMap.ownsNode(n)) continue;  // each node once, by its owner
    const Scalar Rx = c.u(c.reactions, n, kUx), Ry = c.u(c.reactions, n, kUy);
    add(local, k, n, Rx, Ry);
  }
  return sumOverRanks(*c.dofMap.comm(), local);
}

}  // namespace flowform
