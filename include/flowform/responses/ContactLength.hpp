// Contact Length: the arc length along a contact wall from its upstream end (the end it shares
// with its Start Group, else its first node) to the last node of the contact zone that starts
// there (the separation point): the tool–chip contact length, to within a segment. With
// Direction = X or Y, the same zone's extent projected on that axis, |x_last − x_upstream| (a
// roll's contact length along the rolling direction). Piecewise constant in q: no derivative
// (like Dead Zone).
#pragma once

#include <cmath>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

struct ContactLength {
  static constexpr const char* kName = "Contact Length";
  static constexpr const char* kDescription =
      "the arc length along a contact wall from its upstream end (Start Group) to its farthest active node: the "
      "tool-chip contact length (to within a segment; no derivative)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = false;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the contact wall");
    Teuchos::setStringToIntegralParameter<int>(
        "Direction", "Arc", "Contact Length: Arc (along the wall) or X, Y (the zone's extent projected on that axis)",
        Teuchos::tuple<std::string>("Arc", "X", "Y"), &list);
  }
  explicit ContactLength(const Teuchos::ParameterList& p)
      : m_wall(p.get<std::string>("Boundary")), m_direction(p.get<std::string>("Direction")) {}

  double evaluate(const ResponseContext<double>& c) const {
    const ContactWall& wall = wallNamed(c.walls, m_wall);
    const BoundaryCurve& curve = wall.curve();
    const bool firstIsUpstream = wall.firstNodeIsUpstream();
    const int upstream = firstIsUpstream ? 0 : wall.numNodes() - 1;
    const int axis = m_direction == "X" ? 0 : 1;
    double length = 0.0;
    for (int j = 0; j < wall.numNodes(); ++j) {
      const int k = firstIsUpstream ? j : wall.numNodes() - 1 - j;
      if (!wall.isActive(k)) break;
      if (m_direction == "Arc")
        length = firstIsUpstream ? curve.arcLength[k] : curve.arcLength.back() - curve.arcLength[k];
      else
        length = std::abs(wall.nodeCoordinates(k)[axis] - wall.nodeCoordinates(upstream)[axis]);
    }
    return length;
  }

 private:
  std::string m_wall;
  std::string m_direction;
};

}  // namespace flowform
