// Boundary Extent: the largest coordinate (X or Y) of the group's nodes: where a free surface ends
// (the extrudate's half-thickness at the outlet: the swell). A position: node positions do not
// depend on q, so on a frozen shape its derivative is zero (docs/theory.md §3); the finite-
// difference check with re-converged free surfaces gives the derivative through the shape.
#pragma once

#include <algorithm>
#include <limits>

#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

struct BoundaryExtent {
  static constexpr const char* kName = "Boundary Extent";
  static constexpr const char* kDescription =
      "the largest coordinate (Component X or Y) of the group's nodes: where a free surface ends (the swell)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the group, e.g. a free surface");
    declareComponent(list, "the coordinate");
  }
  explicit BoundaryExtent(const Teuchos::ParameterList& p)
      : m_boundary(p.get<std::string>("Boundary")), m_component(componentIndex(p)) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    double extent = -std::numeric_limits<double>::max();
    for (const auto& e : c.mesh.boundary(m_boundary).edges)
      for (GO n : e) extent = std::max(extent, c.mesh.coords[n][m_component]);
    return extent;
  }

 private:
  std::string m_boundary;
  int m_component;
};

}  // namespace flowform
