// Distribution of nodes, cells and dofs over the ranks, as Tpetra maps and the FE graph.
//
// Cells are partitioned (METIS on more than one rank); a node is owned by the lowest rank
// among the cells that touch it. The overlapped ("owned plus shared") node list holds every
// node of this rank's cells, owned nodes first — the layout Tpetra's FECrsGraph expects.
// Dof global id = kDofsPerNode * node + component.
#pragma once

#include <array>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "flowform/Mesh.hpp"
#include "flowform/TpetraTypes.hpp"

namespace flowform {

class DofMap {
 public:
  /// `couplings` are node pairs (i, j) whose dofs a term other than the cells couples: the
  /// owner of i gets j into its overlap and row i gets j's columns (contact walls: the
  /// friction at a wall node depends on the pressure at its neighbours along the wall).
  /// Both nodes of a pair must share a cell, so the global row lengths do not change.
  DofMap(const Mesh& mesh, const Teuchos::RCP<const Comm>& comm,
         const std::vector<std::array<GO, 2>>& couplings = {});

  const Teuchos::RCP<const Comm>& comm() const { return m_comm; }
  const Teuchos::RCP<const Map>& ownedMap() const { return m_ownedMap; }      ///< dofs
  const Teuchos::RCP<const Map>& overlapMap() const { return m_overlapMap; }  ///< dofs
  const Teuchos::RCP<const Import>& importer() const { return m_importer; }   ///< owned -> overlap
  const Teuchos::RCP<const Export>& exporter() const { return m_exporter; }   ///< overlap -> owned (ADD)
  const Teuchos::RCP<FECrsGraph>& graph() const { return m_graph; }

  /// Cells this rank assembles (mesh cell ids).
  const std::vector<GO>& cells() const { return m_cells; }
  /// Overlap-local node index of node a of this rank's cell k: cellNodes()[k * npc + a].
  const std::vector<LO>& cellNodes() const { return m_cellNodes; }
  /// Overlap-local node index -> mesh node id.
  const std::vector<GO>& overlapNodes() const { return m_overlapNodes; }
  /// Nodes owned by this rank are overlap-local indices 0 .. numOwnedNodes()-1.
  LO numOwnedNodes() const { return m_numOwnedNodes; }
  /// Overlap-local index of mesh node `node`, or -1 when it is not on this rank.
  LO overlapIndex(GO node) const { return m_overlapIndexOfNode[node]; }
  /// Column-map local index of dof (overlap node `n`, component `c`), for the matrix in
  /// its "owned plus shared" (assembly) state.
  LO columnIndex(LO n, int c) const { return m_columnOfOverlapDof[kDofsPerNode * n + c]; }
  /// Part of every mesh cell (the partition), replicated.
  const std::vector<int>& cellPart() const { return m_cellPart; }

 private:
  Teuchos::RCP<const Comm> m_comm;
  std::vector<int> m_cellPart;
  std::vector<GO> m_cells;
  std::vector<LO> m_cellNodes;
  std::vector<GO> m_overlapNodes;
  std::vector<LO> m_overlapIndexOfNode;
  std::vector<LO> m_columnOfOverlapDof;
  LO m_numOwnedNodes = 0;
  Teuchos::RCP<const Map> m_ownedMap, m_overlapMap;
  Teuchos::RCP<const Import> m_importer;
  Teuchos::RCP<const Export> m_exporter;
  Teuchos::RCP<FECrsGraph> m_graph;
};

}  // namespace flowform
