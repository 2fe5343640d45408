// Cell partition by METIS on the dual graph, and node ownership derived from it.
//
// Every rank holds the whole mesh (Mesh.hpp) and runs the same serial METIS call with a
// fixed seed, so all ranks agree on the partition without exchanging it. The dual graph is
// built here (cells are neighbours when they share an edge, i.e. METIS_PartMeshDual's
// ncommon = 2) to keep the edge-sharing rule explicit and to work for triangles and
// quadrilaterals alike.
#include "flowform/mesh/Partition.hpp"

#include <metis.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

/// CSR adjacency of the dual graph: xadj[c]..xadj[c+1] index the neighbours of cell c.
void buildDualGraph(const Mesh& mesh, std::vector<idx_t>& xadj, std::vector<idx_t>& adjncy) {
  const int npc = nodesPerCell(mesh.cellType);
  const GO numCells = mesh.numCells();
  struct EdgeOfCell {
    GO lo, hi, cell;
    bool operator<(const EdgeOfCell& o) const {
      return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : cell < o.cell;
    }
  };
  std::vector<EdgeOfCell> edges;
  edges.reserve(static_cast<std::size_t>(numCells) * npc);
  for (GO c = 0; c < numCells; ++c) {
    const GO* nodes = mesh.cell(c);
    for (int i = 0; i < npc; ++i) {
      const GO a = nodes[i], b = nodes[(i + 1) % npc];
      edges.push_back({std::min(a, b), std::max(a, b), c});
    }
  }
  // Sorting brings the cells of one edge together: every pair in a run is a dual-graph edge.
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<idx_t>> neighbours(numCells);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    for (std::size_t p = i; p < j; ++p)
      for (std::size_t q = i; q < j; ++q)
        if (p != q) neighbours[edges[p].cell].push_back(static_cast<idx_t>(edges[q].cell));
    i = j;
  }
  xadj.assign(1, 0);
  adjncy.clear();
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    adjncy.insert(adjncy.end(), list.begin(), list.end());
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
  }
}

}  // namespace

std::vector<int> partitionCells(const Mesh& mesh, int numParts) {
  if (numParts < 1) throw std::invalid_argument("partitionCells: numParts must be >= 1");
  const GO numCells = mesh.numCells();
  if (numParts == 1) return std::vector<int>(numCells, 0);
  if (numCells < numParts)
    throw InputError("mesh '" + mesh.source + "' has " + std::to_string(numCells) +
                     " cells, fewer than the " + std::to_string(numParts) +
                     " MPI ranks; use fewer ranks or a finer mesh");
  if (static_cast<long long>(numCells) * nodesPerCell(mesh.cellType) >
      std::numeric_limits<idx_t>::max())
    throw std::runtime_error("partitionCells: mesh too large for 32-bit METIS indices");

  std::vector<idx_t> xadj, adjncy;
  buildDualGraph(mesh, xadj, adjncy);
  idx_t nvtxs = static_cast<idx_t>(numCells), ncon = 1, nparts = numParts, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;  // fixed: every rank must compute the same partition
  std::vector<idx_t> part(numCells, 0);
  const int status =
      METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), nullptr, nullptr, nullptr,
                          &nparts, nullptr, nullptr, options, &objval, part.data());
  if (status != METIS_OK)
    throw std::runtime_error("partitionCells: METIS_PartGraphKway failed (status " +
                             std::to_string(status) + ") for mesh '" + mesh.source + "'");
  return std::vector<int>(part.begin(), part.end());
}

std::vector<int> nodeOwners(const Mesh& mesh, const std::vector<int>& cellPart) {
  if (static_cast<GO>(cellPart.size()) != mesh.numCells())
    throw std::invalid_argument("nodeOwners: cellPart has " + std::to_string(cellPart.size()) +
                                " entries for " + std::to_string(mesh.numCells()) + " cells");
  const int npc = nodesPerCell(mesh.cellType);
  // A node no cell touches (the reader drops those) would keep INT_MAX; give it rank 0.
  std::vector<int> owner(mesh.numNodes(), std::numeric_limits<int>::max());
  for (GO c = 0; c < mesh.numCells(); ++c)
    for (int i = 0; i < npc; ++i) {
      int& o = owner[mesh.cell(c)[i]];
      o = std::min(o, cellPart[c]);
    }
  for (int& o : owner)
    if (o == std::numeric_limits<int>::max()) o = 0;
  return owner;
}

}  // namespace flowform
