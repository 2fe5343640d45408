// Mesh motion for moving boundaries (docs/theory.md §3): the displacement given at some
// boundary nodes (a free-surface update) is spread to the interior as the solution of a
// Laplace problem with stiffening,
//     −div(k ∇d) = 0 in Ω,  d = given on the moved boundary nodes,  d = 0 on every other boundary node,
// one scalar problem per component, P1 on the cells (a quadrilateral is split along both
// diagonals, each half weighted 1/2), with k = 1/|K| on each cell: small cells (the refined die
// corner) are stiff and move almost rigidly, large cells take the distortion (Tezduyar's
// Jacobian-based stiffening). The interior system (both components as two right-hand sides)
// is solved directly, by KLU2 on a serial matrix: the mesh is replicated, so every rank solves
// the same system and gets the same coordinates. (Conjugate gradients took 15 of the 17 s of an
// 84 000-dof die swell, docs/BENCHMARKS.md §12.)
#pragma once

#include <array>
#include <vector>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// The node positions after moving the `prescribed` nodes by `displacement` and the interior
/// nodes by its harmonic extension (other boundary nodes stay). Does not check the cells'
/// orientation (Mesh::setCoordinates does).
std::vector<std::array<double, 2>> extendBoundaryDisplacement(const Mesh& mesh,
                                                              const std::vector<std::array<double, 2>>& displacement,
                                                              const std::vector<char>& prescribed);

}  // namespace flowform
