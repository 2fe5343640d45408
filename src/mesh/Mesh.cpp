// Look-up of named boundary groups. Group names come from the case XML, so a miss is an
// input error, and its message lists what the mesh does have: the usual cause is a typo or
// a physical group that was never defined in the .geo.
#include "flowform/Mesh.hpp"

#include <algorithm>

#include "flowform/InputError.hpp"

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

}  // namespace flowform
