// The dual variables of Newton's linearization, kept by the model across the iterations of
// one solve and cleared when a solve starts (the first Jacobian of a solve is then exact):
// the normalized stress at the cells' quadrature points (physics/StressDual.hpp) and the
// normalized friction force at this rank's wall nodes (contact/friction/FrictionDual.hpp).
#pragma once

#include <vector>

#include "flowform/contact/friction/FrictionDual.hpp"
#include "flowform/physics/StressDual.hpp"

namespace flowform {

struct NewtonDual {
  StressDual cells;
  std::vector<FrictionDualPoint> wallNodes;  ///< in the assembler's wall-node order

  void clear() {
    cells.clear();
    wallNodes.clear();
  }
  /// The dual of wall node i of `count` (allocated on first use).
  FrictionDualPoint* wallNode(size_t i, size_t count) {
    if (wallNodes.size() != count) wallNodes.assign(count, {});
    return &wallNodes[i];
  }
};

}  // namespace flowform
