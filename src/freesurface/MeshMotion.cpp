#include "flowform/freesurface/MeshMotion.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace flowform {

namespace {

/// Symmetric sparse matrix in rows of (column, value), the diagonal included.
using SparseRows = std::vector<std::map<GO, double>>;

/// Adds the P1 Laplacian of triangle (a, b, c), times `weight`/|K| (the stiffening), to `K`.
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
  const double scale = weight;  // ∫_K k ∇N_i·∇N_j dx = |K| (1/|K|) ∇N_i·∇N_j
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) K[v[i]][v[j]] += scale * (g[i][0] * g[j][0] + g[i][1] * g[j][1]);
}

}  // namespace

std::vector<std::array<double, 2>> extendBoundaryDisplacement(const Mesh& mesh,
                                                              const std::vector<std::array<double, 2>>& displacement,
                                                              const std::vector<char>& prescribed) {
  const GO numNodes = mesh.numNodes();
  const int npc = nodesPerCell(mesh.cellType);
  // Boundary nodes: the ends of edges that belong to one cell only.
  std::map<std::pair<GO, GO>, int> edgeCount;
  for (GO c = 0; c < mesh.numCells(); ++c)
    for (int e = 0; e < npc; ++e) {
      const GO a = mesh.cell(c)[e], b = mesh.cell(c)[(e + 1) % npc];
      ++edgeCount[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<char> fixed(numNodes, 0);
  for (const auto& [edge, count] : edgeCount)
    if (count == 1) fixed[edge.first] = fixed[edge.second] = 1;

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

  std::vector<std::array<double, 2>> coords = mesh.coords;
  for (GO i = 0; i < numNodes; ++i)
    if (prescribed[i] || fixed[i]) {
      const double s = prescribed[i] ? 1.0 : 0.0;
      coords[i] = {coords[i][0] + s * displacement[i][0], coords[i][1] + s * displacement[i][1]};
    }
  // Interior unknowns: K_II d_I = −K_IB d_B, one component at a time, by Jacobi-preconditioned CG.
  for (int comp = 0; comp < 2; ++comp) {
    std::vector<double> d(numNodes, 0.0), r(numNodes, 0.0), z(numNodes, 0.0), q(numNodes, 0.0), Aq(numNodes, 0.0);
    for (GO i = 0; i < numNodes; ++i)
      if (prescribed[i]) d[i] = displacement[i][comp];
    double rhsNorm = 0.0;
    for (GO i = 0; i < numNodes; ++i) {
      if (fixed[i] || prescribed[i]) continue;
      double s = 0.0;
      for (const auto& [j, kij] : K[i])
        if (fixed[j] || prescribed[j]) s += kij * d[j];
      r[i] = -s;
      rhsNorm += r[i] * r[i];
    }
    rhsNorm = std::sqrt(rhsNorm);
    if (rhsNorm == 0.0) continue;
    auto apply = [&](const std::vector<double>& x, std::vector<double>& y) {
      for (GO i = 0; i < numNodes; ++i) {
        if (fixed[i] || prescribed[i]) { y[i] = 0.0; continue; }
        double s = 0.0;
        for (const auto& [j, kij] : K[i])
          if (!(fixed[j] || prescribed[j])) s += kij * x[j];
        y[i] = s;
      }
    };
    auto precondition = [&](const std::vector<double>& x, std::vector<double>& y) {
      for (GO i = 0; i < numNodes; ++i) y[i] = (fixed[i] || prescribed[i]) ? 0.0 : x[i] / K[i][i];
    };
    std::vector<double> x(numNodes, 0.0);
    precondition(r, z);
    q = z;
    double rz = 0.0;
    for (GO i = 0; i < numNodes; ++i) rz += r[i] * z[i];
    const int maxIterations = 10 * static_cast<int>(numNodes) + 100;
    bool converged = false;
    for (int it = 0; it < maxIterations; ++it) {
      apply(q, Aq);
      double qAq = 0.0;
      for (GO i = 0; i < numNodes; ++i) qAq += q[i] * Aq[i];
      const double alpha = rz / qAq;
      double rr = 0.0;
      for (GO i = 0; i < numNodes; ++i) {
        x[i] += alpha * q[i];
        r[i] -= alpha * Aq[i];
        rr += r[i] * r[i];
      }
      if (std::sqrt(rr) <= 1e-12 * rhsNorm) { converged = true; break; }
      precondition(r, z);
      double rzNew = 0.0;
      for (GO i = 0; i < numNodes; ++i) rzNew += r[i] * z[i];
      const double beta = rzNew / rz;
      rz = rzNew;
      for (GO i = 0; i < numNodes; ++i) q[i] = z[i] + beta * q[i];
    }
    if (!converged) throw std::runtime_error("mesh motion: conjugate gradients did not converge");
    for (GO i = 0; i < numNodes; ++i)
      if (!(fixed[i] || prescribed[i])) coords[i][comp] += x[i];
  }
  return coords;
}

}  // namespace flowform
