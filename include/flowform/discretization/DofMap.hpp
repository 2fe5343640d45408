// Distribution of nodes, cells and dofs over the ranks, as Tpetra maps and the FE graph.
//
// Cells are partitioned (METIS on more than one rank); a node is owned by the lowest rank
// among the cells that touch it. The overlapped ("owned plus shared") node list holds every
// node of this rank's cells, owned nodes first — the layout Tpetra's FECrsGraph expects.
//
// Dofs: node n carries numFields(n) components of the case's fields (FieldRegistry; the
// element layout says which: all of them at every node of the equal-order elements, 3 for
// the flow alone); its dofs are numbered contiguously after those of nodes 0..n-1,
//     global dof (n, component) = offset(n) + component,
// and the overlap dofs of this rank follow the overlap nodes in the same way. Nothing else
// in flowform computes a dof index: it asks this map.
#pragma once

#include <array>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "flowform/core/TpetraTypes.hpp"
#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

class DofMap {
 public:
  /// `couplings` are node pairs (i, j) whose dofs a term other than the cells couples: the
  /// owner of i gets j into its overlap and row i gets j's columns (contact walls: the
  /// friction at a wall node depends on the pressure at its neighbours along the wall).
  /// Both nodes of a pair must share a cell, so the global row lengths do not change.
  /// `fields` are the case's unknowns (default: the flow's).
  DofMap(const Mesh& mesh, const Teuchos::RCP<const Comm>& comm,
         const std::vector<std::array<GO, 2>>& couplings = {}, const FieldRegistry& fields = FieldRegistry::flow());

  const FieldRegistry& fields() const { return m_fields; }

  const Teuchos::RCP<const Comm>& comm() const { return m_comm; }
  const Teuchos::RCP<const Map>& ownedMap() const { return m_ownedMap; }      ///< dofs
  const Teuchos::RCP<const Map>& overlapMap() const { return m_overlapMap; }  ///< dofs
  const Teuchos::RCP<const Import>& importer() const { return m_importer; }   ///< owned -> overlap
  const Teuchos::RCP<const Export>& exporter() const { return m_exporter; }   ///< overlap -> owned (ADD)
  const Teuchos::RCP<FECrsGraph>& graph() const { return m_graph; }

  /// Cells this rank assembles (mesh cell ids).
  const std::vector<GO>& cells() const { return m_cells; }
  /// Nodes per cell of the mesh.
  int nodesPerCell() const { return m_nodesPerCell; }
  /// Overlap-local node indices of this rank's cell k (nodesPerCell() of them).
  const LO* cellNodes(size_t k) const { return m_cellNodes.data() + m_nodesPerCell * k; }
  /// Overlap-local node index -> mesh node id.
  const std::vector<GO>& overlapNodes() const { return m_overlapNodes; }
  /// Nodes owned by this rank are overlap-local indices 0 .. numOwnedNodes()-1.
  LO numOwnedNodes() const { return m_numOwnedNodes; }
  /// Whether overlap node `n` (−1: not on this rank) is owned by this rank: the one test of
  /// "each node once, by its owner".
  bool ownsNode(LO n) const { return n >= 0 && n < m_numOwnedNodes; }
  /// Overlap-local index of mesh node `node`, or -1 when it is not on this rank.
  LO overlapIndex(GO node) const { return m_overlapIndexOfNode[node]; }

  /// Overlap-local dof of (overlap node `n`, field); the owned map's local index too when n
  /// is owned (owned nodes come first in both).
  LO dof(LO n, int field) const { return m_localOffset[n] + field; }
  /// The overlap dofs of the flow's components of this rank's cell k in the flow kernel's
  /// element layout (the cell gather's addresses): dofs[EqualOrderLayout::index(a, c)] =
  /// dof(cellNodes(k)[a], c), c = u_x, u_y, p.
  void cellDofs(size_t k, LO* dofs) const;
  /// The same for the node components `components[0..n)` (a kernel's element vector,
  /// node-major): dofs[n a + i] = dof(cellNodes(k)[a], components[i]).
  void cellDofs(size_t k, const int* components, int n, LO* dofs) const;
  /// Global dof id of (mesh node `node`, field).
  GO globalDof(GO node, int field) const { return m_globalOffset[node] + field; }
  /// Fields carried by mesh node `node`.
  int numFields(GO node) const { return static_cast<int>(m_globalOffset[node + 1] - m_globalOffset[node]); }
  /// Global number of dofs.
  GO numGlobalDofs() const { return m_globalOffset.back(); }
  /// The mesh node and field of a global dof id (inverse of globalDof).
  GO nodeOfGlobalDof(GO dof) const;
  int fieldOfGlobalDof(GO dof) const { return static_cast<int>(dof - m_globalOffset[nodeOfGlobalDof(dof)]); }

  /// Column-map local index of overlap dof `d`, for the matrix in its "owned plus shared"
  /// (assembly) state; −1 for d < 0 (an absent neighbour).
  LO column(LO d) const { return d < 0 ? LO(-1) : m_columnOfOverlapDof[d]; }
  /// Part of every mesh cell (the partition), replicated.
  const std::vector<int>& cellPart() const { return m_cellPart; }

 private:
  Teuchos::RCP<const Comm> m_comm;
  FieldRegistry m_fields;
  int m_nodesPerCell = 0;
  std::vector<int> m_cellPart;
  std::vector<GO> m_cells;
  std::vector<LO> m_cellNodes;
  std::vector<GO> m_overlapNodes;
  std::vector<LO> m_overlapIndexOfNode;
  std::vector<GO> m_globalOffset;  ///< per mesh node, and the total at the end
  std::vector<LO> m_localOffset;   ///< per overlap node, and the total at the end
  std::vector<LO> m_columnOfOverlapDof;
  LO m_numOwnedNodes = 0;
  Teuchos::RCP<const Map> m_ownedMap, m_overlapMap;
  Teuchos::RCP<const Import> m_importer;
  Teuchos::RCP<const Export> m_exporter;
  Teuchos::RCP<FECrsGraph> m_graph;
};

}  // namespace flowform
