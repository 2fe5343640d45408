// Wall Gap: the distance from its tool of a contact wall's downstream end (away from its Start
// Group) when its released runs are free surfaces: the gap of the separated product; 0 for other
// walls (their nodes never leave the tool). Not the largest gap: the separated surface is flat
// there, and a maximum over tied nodes has no derivative. A position: zero derivative on a frozen
// shape (as Boundary Extent).
#pragma once

#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

struct WallGap {
  static constexpr const char* kName = "Wall Gap";
  static constexpr const char* kDescription =
      "the distance from its tool of a contact wall's downstream end when its released runs are free surfaces (the "
      "gap of the separated product); 0 for other walls";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the contact wall"); }
  explicit WallGap(const Teuchos::ParameterList& p) : m_wall(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const ContactWall& wall = wallNamed(c.walls, m_wall);
    if (!wall.releasedFreeSurface()) return 0.0;  // its nodes never leave the tool
    return wall.gap(wall.downstreamEnd());
  }

 private:
  std::string m_wall;
};

}  // namespace flowform
