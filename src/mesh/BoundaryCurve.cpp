// Ordering a boundary group into a curve.
//
// The direction comes from the cells rather than from the file: mesh cells are
// counter-clockwise, so an edge a-b that a cell lists as a -> b has that cell on its left.
// Giving every edge the direction of its one adjacent cell therefore makes the whole group
// run with the material on its left, and the outward normal of a segment a -> b of unit
// tangent t is n = (t_y, -t_x). This is exact for any cell shape, where a test against the
// cell centroid can fail for very flat cells; and it makes the ordering a walk along
// directed edges, in which a node with two outgoing (or two incoming) edges is a branch.
#include "flowform/mesh/BoundaryCurve.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

std::string where(const Mesh& mesh, const BoundaryGroup& group) {
  return "boundary group '" + group.name + "' of mesh '" + mesh.source + "'";
}

std::string nodeLabel(const Mesh& mesh, GO node) {
  std::ostringstream os;
  os << "node " << node << " (" << mesh.coords[node][0] << ", " << mesh.coords[node][1] << ")";
  return os.str();
}

/// The group's edges, each directed as its single adjacent cell lists it (counter-clockwise).
std::vector<std::array<GO, 2>> directedEdges(const Mesh& mesh, const BoundaryGroup& group) {
  const int npc = nodesPerCell(mesh.cellType);
  for (const auto& e : group.edges) {
    // A segment of zero length has no normal and no lumping weight: reject it by name.
    const auto& a = mesh.coords[e[0]];
    const auto& b = mesh.coords[e[1]];
    if (e[0] == e[1] || (a[0] == b[0] && a[1] == b[1]))
      throw InputError(where(mesh, group) + ": zero-length segment from " + nodeLabel(mesh, e[0]) + " to " +
                       nodeLabel(mesh, e[1]) + "; every boundary segment must join two distinct points");
  }
  // Found before on this topology (the mesh moved since): the same orientation.
  const auto& known = group.orientation;
  if (known && known->edges == group.edges && known->cellNodes == mesh.cellNodes) return known->directed;
  // Every cell edge keyed by its sorted node pair -> the cell's own direction, and a count.
  std::map<std::array<GO, 2>, std::pair<std::array<GO, 2>, int>> cellEdges;
  for (const auto& e : group.edges) cellEdges[{std::min(e[0], e[1]), std::max(e[0], e[1])}];
  for (GO c = 0; c < mesh.numCells(); ++c) {
    const GO* nodes = mesh.cell(c);
    for (int i = 0; i < npc; ++i) {
      const GO a = nodes[i], b = nodes[(i + 1) % npc];
      auto it = cellEdges.find({std::min(a, b), std::max(a, b)});
      if (it == cellEdges.end()) continue;
      it->second.first = {a, b};
      ++it->second.second;
    }
  }
  std::vector<std::array<GO, 2>> directed;
  directed.reserve(cellEdges.size());  // duplicates in the group collapse here
  for (const auto& [key, value] : cellEdges) {
    if (value.second != 1)
      throw InputError(where(mesh, group) + ": the edge from " + nodeLabel(mesh, key[0]) + " to " +
                       nodeLabel(mesh, key[1]) + " is not on the mesh boundary (it belongs to " +
                       std::to_string(value.second) + " cells)");
    directed.push_back(value.first);
  }
  group.orientation = std::make_shared<const BoundaryGroup::Orientation>(
      BoundaryGroup::Orientation{group.edges, mesh.cellNodes, directed});
  return directed;
}

}  // namespace

bool BoundaryCurve::isStraight(double tolerance) const {
  if (segmentNormals.empty()) return true;
  const auto& n0 = segmentNormals.front();
  for (const auto& n : segmentNormals) {
    const double angle = std::atan2(n0[0] * n[1] - n0[1] * n[0], n0[0] * n[0] + n0[1] * n[1]);
    if (std::abs(angle) > tolerance) return false;
  }
  return true;
}

BoundaryCurve buildBoundaryCurve(const Mesh& mesh, const BoundaryGroup& group) {
  if (group.edges.empty()) throw InputError(where(mesh, group) + " has no edges");
  const std::vector<std::array<GO, 2>> edges = directedEdges(mesh, group);

  std::map<GO, GO> next;  // node -> the node its outgoing edge leads to
  std::map<GO, int> inDegree;
  auto branchesAt = [&](GO node) {
    return InputError(where(mesh, group) + " branches at " + nodeLabel(mesh, node) +
                      "; a boundary group must be one chain of edges");
  };
  for (const auto& e : edges) {
    if (!next.emplace(e[0], e[1]).second) throw branchesAt(e[0]);  // two edges leave e[0]
    if (++inDegree[e[1]] > 1) throw branchesAt(e[1]);              // two edges reach e[1]
  }
  // An open chain starts at the one node without an incoming edge; a closed one at its
  // lowest node id (std::map order), so the start is reproducible.
  std::vector<GO> starts;
  for (const auto& [node, to] : next)
    if (!inDegree.count(node)) starts.push_back(node);
  if (starts.size() > 1)
    throw InputError(where(mesh, group) + " is made of " + std::to_string(starts.size()) +
                     " separate pieces (they start at " + nodeLabel(mesh, starts[0]) + " and " +
                     nodeLabel(mesh, starts[1]) + "); a boundary group must be one chain of edges");

  BoundaryCurve curve;
  curve.name = group.name;
  curve.closed = starts.empty();
  const GO first = curve.closed ? next.begin()->first : starts.front();
  curve.nodes.push_back(first);
  for (auto it = next.find(first); it != next.end() && it->second != first;
       it = next.find(it->second))
    curve.nodes.push_back(it->second);
  const std::size_t numSegments = curve.closed ? curve.nodes.size() : curve.nodes.size() - 1;
  if (numSegments != edges.size())
    throw InputError(where(mesh, group) + " is made of several separate pieces (the chain from " +
                     nodeLabel(mesh, first) + " holds " + std::to_string(numSegments) + " of its " +
                     std::to_string(edges.size()) +
                     " edges); a boundary group must be one chain of edges");

  curve.arcLength.push_back(0.0);
  for (std::size_t k = 0; k < numSegments; ++k) {
    const auto& a = mesh.coords[curve.nodes[k]];
    const auto& b = mesh.coords[curve.nodes[(k + 1) % curve.nodes.size()]];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length = std::hypot(dx, dy);
    if (!(length > 0.0))
      throw InputError(where(mesh, group) + " has a zero-length segment from " +
                       nodeLabel(mesh, curve.nodes[k]) + " to " +
                       nodeLabel(mesh, curve.nodes[(k + 1) % curve.nodes.size()]));
    curve.segmentLength.push_back(length);
    curve.segmentNormals.push_back({dy / length, -dx / length});  // material on the left
    if (k + 1 < curve.nodes.size()) curve.arcLength.push_back(curve.arcLength.back() + length);
  }

  // Nodal normal: the bisector of the adjacent segment normals; at the ends of an open
  // curve, the one segment's normal.
  const std::size_t n = curve.nodes.size();
  curve.normals.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool hasBefore = curve.closed || i > 0;
    const bool hasAfter = curve.closed || i + 1 < n;
    std::array<double, 2> sum{0.0, 0.0};
    if (hasBefore) {
      const auto& m = curve.segmentNormals[(i + numSegments - 1) % numSegments];
      sum = {sum[0] + m[0], sum[1] + m[1]};
    }
    if (hasAfter) {
      const auto& m = curve.segmentNormals[i % numSegments];
      sum = {sum[0] + m[0], sum[1] + m[1]};
    }
    const double norm = std::hypot(sum[0], sum[1]);
    // Opposite normals on both sides: the boundary turns back on itself (a zero-angle spike).
    if (norm < 1e-12)
      throw InputError(where(mesh, group) + " folds back on itself at " +
                       nodeLabel(mesh, curve.nodes[i]) + "; no normal is defined there");
    curve.normals[i] = {sum[0] / norm, sum[1] / norm};
  }
  return curve;
}

CurveEnds endsOn(const BoundaryCurve& curve, const BoundaryGroup& group) {
  CurveEnds ends;
  for (const auto& e : group.edges)
    for (GO node : e) {
      ends.first = ends.first || node == curve.nodes.front();
      ends.last = ends.last || node == curve.nodes.back();
    }
  return ends;
}

}  // namespace flowform
