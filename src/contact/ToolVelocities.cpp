#include "flowform/contact/ToolVelocities.hpp"

namespace flowform {

Teuchos::RCP<Vector> toolVelocities(const std::vector<ContactWall>& walls, const DofMap& dofMap,
                                    const Teuchos::RCP<const Map>& map) {
  Teuchos::RCP<Vector> v;
  for (const ContactWall& wall : walls) {
    if (!wall.motion().moving()) continue;
    if (v.is_null()) v = Teuchos::rcp(new Vector(map));
    auto values = v->getDataNonConst();
    const auto& nodes = wall.curve().nodes;
    for (size_t k = 0; k < nodes.size(); ++k)
      for (int c = 0; c < 2; ++c) {
        const LO row = map->getLocalElement(dofMap.globalDof(nodes[k], c));
        if (row != Teuchos::OrdinalTraits<LO>::invalid()) values[row] = wall.wallVelocity(static_cast<int>(k))[c];
      }
  }
  return v;
}

Teuchos::RCP<Vector> followTools(const std::vector<ContactWall>& walls, const DofMap& dofMap, const Vector& x,
                                 const Teuchos::RCP<const Vector>& before, Vector& moved) {
  moved.assign(x);
  if (before.is_null()) return Teuchos::null;
  Teuchos::RCP<Vector> now = toolVelocities(walls, dofMap, x.getMap());
  moved.update(1.0, *now, -1.0, *before, 1.0);
  return now;
}

}  // namespace flowform
