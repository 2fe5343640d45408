#include "flowform/freesurface/MeshMotion.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <Teuchos_DefaultSerialComm.hpp>

namespace flowform {

namespace {

/// Symmetric sparse matrix in rows of (column, value), the diagonal included.
using SparseRows = std::vector<std::map<GO, double>>;

/// Adds the P1 Laplacian of triangle (a, b, c) with the stiffening k = 1/|K|, times `weight`.
void addTriangle(const Mesh& mesh, GO a, GO b, GO c, double weight, SparseRows& K) {
  const GO v[3] = {a, b, c};
  const auto& p = mesh.coords;
  const double area = 0.5 * std::abs((p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) -
                                     (p[c][0] - p[a][0]) * (p[b][1] - p[a][1]));
  if (!(area > 0.0)) return;
  // ∇N_i = (y_j − y_k, x_k − x_j) / (2|K|) for (i, j, k) cyclic.
  double g[3][2];
  for (int i = 0; i < 3; ++i) {
    const GO j = v[(i + 1) % 3], k = v[(i + 2) % 3];
    g[i][0] = (p[j][1] - p[k][1]) / (2.0 * area);
    g[i][1] = (p[k][0] - p[j][0]) / (2.0 * area);
  }
  // ∫_K k ∇N_i·∇N_j dx = |K| (1/|K|) ∇N_i·∇N_j
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) K[v[i]][v[j]] += weight * (g[i][0] * g[j][0] + g[i][1] * g[j][1]);
}

}  // namespace

HarmonicExtension::HarmonicExtension(const Mesh& mesh, const std::vector<char>& prescribed)
    : m_mesh(mesh), m_prescribed(prescribed) {
  const GO numNodes = mesh.numNodes();
  const int npc = nodesPerCell(mesh.cellType);
  // Boundary nodes: the ends of edges that belong to one cell only.
  std::map<std::pair<GO, GO>, int> edgeCount;
  for (GO c = 0; c < mesh.numCells(); ++c)
    for (int e = 0; e < npc; ++e) {
      const GO a = mesh.cell(c)[e], b = mesh.cell(c)[(e + 1) % npc];
      ++edgeCount[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<char> boundary(numNodes, 0);
  for (const auto& [edge, count] : edgeCount)
    if (count == 1) boundary[edge.first] = boundary[edge.second] = 1;
  m_unknown.assign(numNodes, -1);
  GO m = 0;
  for (GO i = 0; i < numNodes; ++i)
    if (!boundary[i] && !prescribed[i]) m_unknown[i] = m++;
  if (m == 0) return;

  SparseRows K(numNodes);
  for (GO c = 0; c < mesh.numCells(); ++c) {
    const GO* v = mesh.cell(c);
    if (npc == 3) {
      addTriangle(mesh, v[0], v[1], v[2], 1.0, K);
    } else {  // both diagonals, each half weighted 1/2
      addTriangle(mesh, v[0], v[1], v[2], 0.5, K);
      addTriangle(mesh, v[0], v[2], v[3], 0.5, K);
      addTriangle(mesh, v[1], v[2], v[3], 0.5, K);
      addTriangle(mesh, v[1], v[3], v[0], 0.5, K);
    }
  }
  // K_II (factored) and K_IB (kept for the right-hand sides −K_IB d_B).
  auto map = Teuchos::rcp(new Map(m, 0, Teuchos::rcp(new Teuchos::SerialComm<int>())));
  Teuchos::Array<size_t> rowLength(m, 0);
  m_coupling.resize(m);
  for (GO i = 0; i < numNodes; ++i) {
    if (m_unknown[i] < 0) continue;
    for (const auto& [j, kij] : K[i]) {
      if (m_unknown[j] >= 0) ++rowLength[m_unknown[i]];
      else if (prescribed[j]) m_coupling[m_unknown[i]].push_back({j, kij});
    }
  }
  m_matrix = Teuchos::rcp(new CrsMatrix(map, rowLength()));
  std::vector<GO> cols;
  std::vector<double> vals;
  for (GO i = 0; i < numNodes; ++i) {
    if (m_unknown[i] < 0) continue;
    cols.clear();
    vals.clear();
    for (const auto& [j, kij] : K[i])
      if (m_unknown[j] >= 0) {
        cols.push_back(m_unknown[j]);
        vals.push_back(kij);
      }
    m_matrix->insertGlobalValues(m_unknown[i], Teuchos::ArrayView<const GO>(cols), Teuchos::ArrayView<const double>(vals));
  }
  m_matrix->fillComplete();
  m_rhs = Teuchos::rcp(new MultiVector(map, 2));
  m_solution = Teuchos::rcp(new MultiVector(map, 2));
  try {
    m_solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", m_matrix, m_solution, m_rhs);
    m_solver->symbolicFactorization();
    m_solver->numericFactorization();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("mesh motion: the Laplacian could not be factored: ") + e.what());
  }
}

std::vector<std::array<double, 2>> HarmonicExtension::positions(const std::vector<std::array<double, 2>>& displacement) {
  std::vector<std::array<double, 2>> coords = m_mesh.coords;
  for (GO i = 0; i < m_mesh.numNodes(); ++i)
    if (m_prescribed[i]) coords[i] = {coords[i][0] + displacement[i][0], coords[i][1] + displacement[i][1]};
  if (m_solver.is_null()) return coords;
  {
    // K_II d_I = −K_IB d_B (d_B = the prescribed displacement, 0 on the other boundary nodes).
    auto b = m_rhs->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t r = 0; r < m_coupling.size(); ++r) {
      double sum[2] = {0.0, 0.0};
      for (const auto& [j, kij] : m_coupling[r]) {
        sum[0] -= kij * displacement[j][0];
        sum[1] -= kij * displacement[j][1];
      }
      b(r, 0) = sum[0];
      b(r, 1) = sum[1];
    }
  }
  m_solver->solve();
  const auto x = m_solution->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (GO i = 0; i < m_mesh.numNodes(); ++i)
    if (m_unknown[i] >= 0) coords[i] = {coords[i][0] + x(m_unknown[i], 0), coords[i][1] + x(m_unknown[i], 1)};
  return coords;
}

std::vector<std::array<double, 2>> extendBoundaryDisplacement(const Mesh& mesh,
                                                              const std::vector<std::array<double, 2>>& displacement,
                                                              const std::vector<char>& prescribed) {
  return HarmonicExtension(mesh, prescribed).positions(displacement);
}

}  // namespace flowform
