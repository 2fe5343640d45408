#include "flowform/contact/ToolCorners.hpp"

namespace flowform {

void markConvexToolCorners(std::vector<ContactWall>& walls) {
  for (size_t a = 0; a < walls.size(); ++a)
    for (size_t b = 0; b < walls.size(); ++b) {
      if (a == b) continue;
      const BoundaryCurve& ca = walls[a].curve();
      const BoundaryCurve& cb = walls[b].curve();
      for (int ka = 0; ka < walls[a].numNodes(); ++ka)
        for (int kb = 0; kb < walls[b].numNodes(); ++kb) {
          if (ca.nodes[ka] != cb.nodes[kb]) continue;
          const int along = walls[a].next(ka) >= 0 ? walls[a].next(ka) : walls[a].previous(ka);
          if (along < 0) continue;
          const double dx = walls[a].nodeCoordinates(along)[0] - walls[a].nodeCoordinates(ka)[0];
          const double dy = walls[a].nodeCoordinates(along)[1] - walls[a].nodeCoordinates(ka)[1];
          const auto& nb = cb.normals[kb];
          if (dx * nb[0] + dy * nb[1] > 0.0) walls[a].addCornerNormal(ka, nb, walls[b].wallNormalSpeed(kb));
        }
    }
}


}  // namespace flowform
