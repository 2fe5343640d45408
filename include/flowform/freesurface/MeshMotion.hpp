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

#include <Amesos2.hpp>

#include "flowform/core/TpetraTypes.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// The harmonic extension on one mesh with one set of moved boundary nodes, factored once: any
/// number of boundary displacements on those nodes can then be spread (the shape derivative
/// spreads one per surface node).
class HarmonicExtension {
 public:
  /// `prescribed`: per mesh node, whether its displacement is boundary data (every other
  /// boundary node stays). std::runtime_error when the Laplacian cannot be factored.
  HarmonicExtension(const Mesh& mesh, const std::vector<char>& prescribed);

  /// The node positions after moving the prescribed nodes by `displacement` (per mesh node; only
  /// the prescribed entries are read) and the interior by its extension.
  std::vector<std::array<double, 2>> positions(const std::vector<std::array<double, 2>>& displacement);

 private:
  const Mesh& m_mesh;
  std::vector<char> m_prescribed;
  std::vector<GO> m_unknown;  ///< per mesh node: its interior unknown, or −1
  /// K_IB per interior unknown: (boundary node, entry) pairs.
  std::vector<std::vector<std::pair<GO, double>>> m_coupling;
  Teuchos::RCP<CrsMatrix> m_matrix;
  Teuchos::RCP<MultiVector> m_rhs, m_solution;
  Teuchos::RCP<Amesos2::Solver<CrsMatrix, MultiVector>> m_solver;
};

/// HarmonicExtension(mesh, prescribed).positions(displacement): one move.
std::vector<std::array<double, 2>> extendBoundaryDisplacement(const Mesh& mesh,
                                                              const std::vector<std::array<double, 2>>& displacement,
                                                              const std::vector<char>& prescribed);

}  // namespace flowform
