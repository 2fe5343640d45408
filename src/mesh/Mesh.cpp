// Look-up of named boundary groups. Group names come from the case XML, so a miss is an
// input error, and its message lists what the mesh does have: the usual cause is a typo or
// a physical group that was never defined in the .geo.
#include "flowform/mesh/Mesh.hpp"

#include <algorithm>
#include <cmath>

#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

const BoundaryGroup* findBoundary(const Mesh& mesh, const std::string& name) {
  auto it = std::find_if(mesh.boundaries.begin(), mesh.boundaries.end(),
                         [&](const BoundaryGroup& g) { return g.name == name; });
  return it == mesh.boundaries.end() ? nullptr : &*it;
}

}  // namespace

const BoundaryGroup& Mesh::boundary(const std::string& name) const {
  if (const BoundaryGroup* group = findBoundary(*this, name)) return *group;
  const std::string available = boundaries.empty() ? std::string("none") : boundaryNames();
  throw InputError("mesh '" + source + "' has no boundary group (1-D physical group) named '" +
                   name + "'; it has: " + available);
}

bool Mesh::hasBoundary(const std::string& name) const {
  return findBoundary(*this, name) != nullptr;
}

std::string Mesh::boundaryNames() const {
  std::string names;
  for (const BoundaryGroup& group : boundaries) {
    if (!names.empty()) names += ", ";
    names += group.name;
  }
  return names;
}

CellOrientation cellOrientation(CellType type, const std::array<double, 2>* x) {
  const int npc = nodesPerCell(type);
  // Twice the area of the triangle spanned by corner o and its neighbours a, b.
  auto cross = [](const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& o) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  double longest2 = 0;
  for (int i = 0; i < npc; ++i) {
    const double dx = x[(i + 1) % npc][0] - x[i][0], dy = x[(i + 1) % npc][1] - x[i][1];
    longest2 = std::max(longest2, dx * dx + dy * dy);
  }
  const double tiny = 2.0 * 1e-12 * longest2;  // on twice the area
  using Kind = CellOrientation::Kind;
  if (type == CellType::Triangle3) {
    const double twiceArea = cross(x[1], x[2], x[0]);
    if (std::abs(twiceArea) <= tiny) return {Kind::Degenerate, 0};
    return {twiceArea > 0 ? Kind::CounterClockwise : Kind::Clockwise};
  }
  // Quadrilateral: the corners decide. Same-signed nonzero corner Jacobians also bound the
  // area away from zero, while a bow-tie can have zero net area and is reported as mixed.
  int positive = 0, negative = 0;
  for (int i = 0; i < 4; ++i) {
    // Jacobian determinant of the bilinear map at corner i (times 4).
    const double j = cross(x[(i + 1) % 4], x[(i + 3) % 4], x[i]);
    if (std::abs(j) <= tiny) return {Kind::Degenerate, i};
    (j > 0 ? positive : negative)++;
  }
  if (positive == 4) return {Kind::CounterClockwise};
  if (negative == 4) return {Kind::Clockwise};
  return {Kind::Mixed};
}

void Mesh::setCoordinates(const std::vector<std::array<double, 2>>& newCoords) {
  if (newCoords.size() != coords.size())
    throw InputError("mesh '" + source + "': " + std::to_string(newCoords.size()) + " new node positions for " +
                     std::to_string(coords.size()) + " nodes");
  const int npc = nodesPerCell(cellType);
  std::array<double, 2> xy[4];
  for (GO c = 0; c < numCells(); ++c) {
    for (int a = 0; a < npc; ++a) xy[a] = newCoords[cell(c)[a]];
    if (cellOrientation(cellType, xy).kind != CellOrientation::Kind::CounterClockwise) {
      double cx = 0.0, cy = 0.0;  // where it is (as it was), for the message
      for (int a = 0; a < npc; ++a) cx += coords[cell(c)[a]][0] / npc, cy += coords[cell(c)[a]][1] / npc;
      throw InputError("mesh '" + source + "': moving the nodes inverts or degenerates cell " + std::to_string(c) +
                       " at (" + std::to_string(cx) + ", " + std::to_string(cy) + ")");
    }
  }
  coords = newCoords;
}

}  // namespace flowform
