#include "flowform/discretization/DofMap.hpp"

#include <algorithm>

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Assembly_Helpers.hpp>

#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/mesh/Partition.hpp"

namespace flowform {

namespace {

/// Components at every mesh node: the most any cell's layout puts there.
std::vector<int> nodeFields(const Mesh& mesh, const FieldRegistry& registry) {
  const int npc = nodesPerCell(mesh.cellType);
  std::vector<int> fields(mesh.numNodes(), 0);
  for (GO c = 0; c < mesh.numCells(); ++c)
    for (int a = 0; a < npc; ++a) fields[mesh.cell(c)[a]] = std::max(fields[mesh.cell(c)[a]], componentsAtCellNode(mesh.cellType, a, registry));
  return fields;
}

/// Dofs of the distinct nodes that share a cell with each node (itself included), over the
/// whole mesh: the exact length of each of the node's rows in the assembled matrix, also for
/// rows that receive contributions from other ranks' cells.
std::vector<size_t> rowLengths(const Mesh& mesh, const std::vector<int>& fields) {
  const int npc = nodesPerCell(mesh.cellType);
  std::vector<std::vector<GO>> neighbours(mesh.numNodes());
  for (GO c = 0; c < mesh.numCells(); ++c) {
    const GO* nodes = mesh.cell(c);
    for (int a = 0; a < npc; ++a)
      for (int b = 0; b < npc; ++b) neighbours[nodes[a]].push_back(nodes[b]);
  }
  std::vector<size_t> length(mesh.numNodes(), 0);
  for (GO n = 0; n < mesh.numNodes(); ++n) {
    auto& list = neighbours[n];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    for (GO m : list) length[n] += fields[m];
    std::vector<GO>().swap(list);
  }
  return length;
}

}  // namespace

DofMap::DofMap(const Mesh& mesh, const Teuchos::RCP<const Comm>& comm,
               const std::vector<std::array<GO, 2>>& couplings, const FieldRegistry& registry)
    : m_comm(comm), m_fields(registry) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: dof map and graph"));
  const int rank = comm->getRank();
  const int npc = flowform::nodesPerCell(mesh.cellType);
  m_nodesPerCell = npc;

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

  // Dof numbering: each node's fields contiguous, nodes in id order.
  const std::vector<int> fields = nodeFields(mesh, registry);
  m_globalOffset.assign(mesh.numNodes() + 1, 0);
  for (GO n = 0; n < mesh.numNodes(); ++n) m_globalOffset[n + 1] = m_globalOffset[n] + fields[n];
  m_localOffset.assign(m_overlapNodes.size() + 1, 0);
  std::vector<GO> dofs;
  for (size_t i = 0; i < m_overlapNodes.size(); ++i) {
    const GO node = m_overlapNodes[i];
    m_localOffset[i + 1] = m_localOffset[i] + fields[node];
    for (int f = 0; f < fields[node]; ++f) dofs.push_back(globalDof(node, f));
  }
  const LO numOwnedDofs = m_localOffset[m_numOwnedNodes];
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  m_ownedMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(dofs.data(), numOwnedDofs), 0, comm));
  m_overlapMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(dofs.data(), dofs.size()), 0, comm));
  m_importer = Teuchos::rcp(new Import(m_ownedMap, m_overlapMap));
  m_exporter = Teuchos::rcp(new Export(m_overlapMap, m_ownedMap));

  // Graph: every dof of a node couples to every dof of every node sharing a cell with it.
  const std::vector<size_t> length = rowLengths(mesh, fields);
  Kokkos::DualView<size_t*, FECrsGraph::device_type> lengths("flowform row lengths", dofs.size());
  lengths.modify_host();
  for (size_t i = 0; i < m_overlapNodes.size(); ++i)
    for (LO d = m_localOffset[i]; d < m_localOffset[i + 1]; ++d) lengths.h_view(d) = length[m_overlapNodes[i]];
  lengths.sync_device();
  Kokkos::DualView<const size_t*, FECrsGraph::device_type> constLengths = lengths;
  m_graph = Teuchos::rcp(new FECrsGraph(m_ownedMap, m_overlapMap, constLengths));

  Tpetra::beginAssembly(*m_graph);
  std::vector<GO> cellDofs;
  for (size_t k = 0; k < m_cells.size(); ++k) {
    cellDofs.clear();
    for (int a = 0; a < npc; ++a) {
      const GO node = m_overlapNodes[cellNodes(k)[a]];
      for (int f = 0; f < fields[node]; ++f) cellDofs.push_back(globalDof(node, f));
    }
    for (GO row : cellDofs) m_graph->insertGlobalIndices(row, Teuchos::ArrayView<const GO>(cellDofs));
  }
  for (const auto& pair : couplings)
    for (int k = 0; k < 2; ++k) {
      const GO i = pair[k], j = pair[1 - k];
      if (owner[i] != rank) continue;
      std::vector<GO> cols;
      for (int f = 0; f < fields[j]; ++f) cols.push_back(globalDof(j, f));
      for (int f = 0; f < fields[i]; ++f)
        m_graph->insertGlobalIndices(globalDof(i, f), Teuchos::ArrayView<const GO>(cols));
    }
  Tpetra::endAssembly(*m_graph);

  // Column indices of the assembly ("owned plus shared") state, for sumIntoLocalValues.
  m_graph->switchActiveCrsGraph();  // to owned plus shared
  const auto colMap = m_graph->getColMap();
  m_columnOfOverlapDof.resize(dofs.size());
  for (size_t i = 0; i < dofs.size(); ++i) m_columnOfOverlapDof[i] = colMap->getLocalElement(dofs[i]);
  m_graph->switchActiveCrsGraph();  // back to owned
}

void DofMap::cellDofs(size_t k, LO* dofs) const {
  const LO* nodes = cellNodes(k);
  for (int a = 0; a < m_nodesPerCell; ++a)
    for (int c = 0; c < EqualOrderLayout::kFieldsPerNode; ++c) dofs[EqualOrderLayout::index(a, c)] = dof(nodes[a], c);
}

void DofMap::cellDofs(size_t k, const int* components, int n, LO* dofs) const {
  const LO* nodes = cellNodes(k);
  for (int a = 0; a < m_nodesPerCell; ++a)
    for (int i = 0; i < n; ++i) dofs[n * a + i] = dof(nodes[a], components[i]);
}

GO DofMap::nodeOfGlobalDof(GO dof) const {
  // The last node whose first dof is <= dof.
  return static_cast<GO>(std::upper_bound(m_globalOffset.begin(), m_globalOffset.end(), dof) - m_globalOffset.begin()) - 1;
}

}  // namespace flowform
