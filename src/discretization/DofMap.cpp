#include "flowform/DofMap.hpp"

#include <algorithm>

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Assembly_Helpers.hpp>

#include "flowform/Partition.hpp"

namespace flowform {

namespace {

/// Number of distinct nodes that share a cell with each node (itself included), over the
/// whole mesh: the exact row length (in nodes) of the assembled matrix, also for rows that
/// receive contributions from other ranks' cells.
std::vector<size_t> nodeDegrees(const Mesh& mesh) {
  const int npc = nodesPerCell(mesh.cellType);
  std::vector<std::vector<GO>> neighbours(mesh.numNodes());
  for (GO c = 0; c < mesh.numCells(); ++c) {
    const GO* nodes = mesh.cell(c);
    for (int a = 0; a < npc; ++a)
      for (int b = 0; b < npc; ++b) neighbours[nodes[a]].push_back(nodes[b]);
  }
  std::vector<size_t> degree(mesh.numNodes());
  for (GO n = 0; n < mesh.numNodes(); ++n) {
    auto& list = neighbours[n];
    std::sort(list.begin(), list.end());
    degree[n] = std::unique(list.begin(), list.end()) - list.begin();
    std::vector<GO>().swap(list);
  }
  return degree;
}

}  // namespace

DofMap::DofMap(const Mesh& mesh, const Teuchos::RCP<const Comm>& comm,
               const std::vector<std::array<GO, 2>>& couplings)
    : m_comm(comm) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: dof map and graph"));
  const int rank = comm->getRank();
  const int npc = nodesPerCell(mesh.cellType);

  m_cellPart = partitionCells(mesh, comm->getSize());
  const std::vector<int> owner = nodeOwners(mesh, m_cellPart);

  // Owned nodes first (ascending), then the shared ones this rank's cells touch.
  std::vector<char> touched(mesh.numNodes(), 0);
  for (GO c = 0; c < mesh.numCells(); ++c) {
    if (m_cellPart[c] != rank) continue;
    m_cells.push_back(c);
    for (int a = 0; a < npc; ++a) touched[mesh.cell(c)[a]] = 1;
  }
  // Coupled nodes of an owned node become ghosts (they share a cell, maybe on another rank).
  for (const auto& [i, j] : couplings) {
    if (owner[i] == rank) touched[j] = 1;
    if (owner[j] == rank) touched[i] = 1;
  }
  for (GO n = 0; n < mesh.numNodes(); ++n)
    if (touched[n] && owner[n] == rank) m_overlapNodes.push_back(n);
  m_numOwnedNodes = static_cast<LO>(m_overlapNodes.size());
  for (GO n = 0; n < mesh.numNodes(); ++n)
    if (touched[n] && owner[n] != rank) m_overlapNodes.push_back(n);

  m_overlapIndexOfNode.assign(mesh.numNodes(), -1);
  for (size_t i = 0; i < m_overlapNodes.size(); ++i)
    m_overlapIndexOfNode[m_overlapNodes[i]] = static_cast<LO>(i);
  m_cellNodes.reserve(m_cells.size() * npc);
  for (GO c : m_cells)
    for (int a = 0; a < npc; ++a) m_cellNodes.push_back(m_overlapIndexOfNode[mesh.cell(c)[a]]);

  // Dof maps.
  std::vector<GO> dofs(kDofsPerNode * m_overlapNodes.size());
  for (size_t i = 0; i < m_overlapNodes.size(); ++i)
    for (int c = 0; c < kDofsPerNode; ++c) dofs[kDofsPerNode * i + c] = kDofsPerNode * m_overlapNodes[i] + c;
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  m_ownedMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(dofs.data(), kDofsPerNode * m_numOwnedNodes), 0, comm));
  m_overlapMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(dofs.data(), dofs.size()), 0, comm));
  m_importer = Teuchos::rcp(new Import(m_ownedMap, m_overlapMap));
  m_exporter = Teuchos::rcp(new Export(m_overlapMap, m_ownedMap));

  // Graph: every dof of a node couples to every dof of every node sharing a cell with it.
  const std::vector<size_t> degree = nodeDegrees(mesh);
  Kokkos::DualView<size_t*, FECrsGraph::device_type> rowLengths("flowform row lengths", dofs.size());
  rowLengths.modify_host();
  for (size_t i = 0; i < m_overlapNodes.size(); ++i)
    for (int c = 0; c < kDofsPerNode; ++c)
      rowLengths.h_view(kDofsPerNode * i + c) = kDofsPerNode * degree[m_overlapNodes[i]];
  rowLengths.sync_device();
  Kokkos::DualView<const size_t*, FECrsGraph::device_type> constLengths = rowLengths;
  m_graph = Teuchos::rcp(new FECrsGraph(m_ownedMap, m_overlapMap, constLengths));

  Tpetra::beginAssembly(*m_graph);
  std::vector<GO> cellDofs(kDofsPerNode * npc);
  for (size_t k = 0; k < m_cells.size(); ++k) {
    for (int a = 0; a < npc; ++a)
      for (int c = 0; c < kDofsPerNode; ++c)
        cellDofs[kDofsPerNode * a + c] = kDofsPerNode * m_overlapNodes[m_cellNodes[npc * k + a]] + c;
    for (GO row : cellDofs) m_graph->insertGlobalIndices(row, Teuchos::ArrayView<const GO>(cellDofs));
  }
  for (const auto& pair : couplings)
    for (int k = 0; k < 2; ++k) {
      const GO i = pair[k], j = pair[1 - k];
      if (owner[i] != rank) continue;
      GO cols[kDofsPerNode];
      for (int c = 0; c < kDofsPerNode; ++c) cols[c] = kDofsPerNode * j + c;
      for (int c = 0; c < kDofsPerNode; ++c)
        m_graph->insertGlobalIndices(kDofsPerNode * i + c, Teuchos::ArrayView<const GO>(cols, kDofsPerNode));
    }
  Tpetra::endAssembly(*m_graph);

  // Column indices of the assembly ("owned plus shared") state, for sumIntoLocalValues.
  m_graph->switchActiveCrsGraph();  // to owned plus shared
  const auto colMap = m_graph->getColMap();
  m_columnOfOverlapDof.resize(dofs.size());
  for (size_t i = 0; i < dofs.size(); ++i) m_columnOfOverlapDof[i] = colMap->getLocalElement(dofs[i]);
  m_graph->switchActiveCrsGraph();  // back to owned
}

}  // namespace flowform
