// Look-up of named boundary groups. Group names come from the case XML, so a miss is an
// input error, and its message lists what the mesh does have: the usual cause is a typo or
// a physical group that was never defined in the .geo.
#include "flowform/mesh/Mesh.hpp"

#include <algorithm>

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

void Mesh::setCoordinates(const std::vector<std::array<double, 2>>& newCoords) {
  if (newCoords.size() != coords.size())
    throw InputError("mesh '" + source + "': " + std::to_string(newCoords.size()) + " new node positions for " +
                     std::to_string(coords.size()) + " nodes");
  const int npc = nodesPerCell(cellType);
  for (GO c = 0; c < numCells(); ++c)
    for (int a = 0; a < npc; ++a) {
      // The corner at node a turns left (counter-clockwise): det J > 0 at that corner, which
      // for a triangle is its area and for a bilinear quadrilateral holds inside when it
      // holds at all four corners.
      const auto& o = newCoords[cell(c)[a]];
      const auto& n = newCoords[cell(c)[(a + 1) % npc]];
      const auto& p = newCoords[cell(c)[(a + npc - 1) % npc]];
      const double cross = (n[0] - o[0]) * (p[1] - o[1]) - (n[1] - o[1]) * (p[0] - o[0]);
      if (!(cross > 0.0))
        throw InputError("mesh '" + source + "': moving the nodes inverts or degenerates cell " + std::to_string(c) +
                         " (at its node " + std::to_string(cell(c)[a]) + ")");
    }
  coords = newCoords;
}

}  // namespace flowform
