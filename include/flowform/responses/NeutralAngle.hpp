// Neutral Angle: where the relative slip s = (u − v_w)·t between the material and a rotating tool
// changes sign along the contact — a roll's neutral point — as the angle about the Rotation Centre
// c from the wall's downstream end (its end away from the Start Group; meshes/rolling.geo ends the
// roll's arc at the exit plane), in degrees:
//   θ_k = ∠(x_k − c, x_exit − c) at wall node k,
//   scanning the nodes in contact from the downstream end, the first pair j, j+1 with
//   s_j s_{j+1} ≤ 0 (s_j ≠ s_{j+1}) gives θ_n = θ_j + (θ_{j+1} − θ_j) s_j / (s_j − s_{j+1}),
// the zero of the slip interpolated linearly between the two nodes (the slip is linear along a
// segment). Differentiable through s (the solution); the node positions are fixed. With no sign
// change in the contact: θ of the upstream-most node in contact if the material outruns the tool
// everywhere (slip along the tool's motion), of the downstream-most one if the tool outruns the
// material everywhere (a roll that skids over the whole arc).
#pragma once

#include <cmath>
#include <vector>

#include "flowform/core/InputError.hpp"
#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

struct NeutralAngle {
  static constexpr const char* kName = "Neutral Angle";
  static constexpr const char* kDescription =
      "the angle [degrees] about a rotating wall's Rotation Centre, from its downstream end (the exit plane), to the "
      "point of the contact where the slip relative to the tool changes sign (a roll's neutral point)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the contact wall"); }
  explicit NeutralAngle(const Teuchos::ParameterList& p) : m_wall(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const ContactWall& wall = wallNamed(c.walls, m_wall);
    if (wall.motion().kind != ToolMotion::Kind::Rotation)
      throw InputError("Responses: a Neutral Angle measures a rotating wall, and wall '" + m_wall +
                       "' has no Tool Motion = Rotation");
    const int N = wall.numNodes();
    const auto& centre = wall.motion().centre;
    // The slip of every wall node, summed over the ranks (each node by its owner).
    std::vector<Scalar> slip(N, Scalar(0.0));
    for (int k = 0; k < N; ++k) {
      const LO n = c.dofMap.overlapIndex(wall.curve().nodes[k]);
      Scalar local = 0.0;
      if (n >= 0 && c.dofMap.ownsNode(n)) {
        const Scalar u[2] = {c.u(c.x, n, kUx), c.u(c.x, n, kUy)};
        local = wall.relativeSlip(k, u);
      }
      slip[k] = sumOverRanks(*c.dofMap.comm(), local);
    }
    const int exitNode = wall.downstreamEnd();
    const auto& xe = wall.nodeCoordinates(exitNode);
    const double ex = xe[0] - centre[0], ey = xe[1] - centre[1];
    auto theta = [&](int k) {
      const auto& x = wall.nodeCoordinates(k);
      const double rx = x[0] - centre[0], ry = x[1] - centre[1];
      return std::atan2(std::abs(ex * ry - ey * rx), ex * rx + ey * ry) * 180.0 / M_PI;
    };
    // From the downstream end towards the upstream one, over the nodes in contact.
    std::vector<int> order;
    for (int j = 0; j < N; ++j) {
      const int k = wall.firstNodeIsUpstream() ? N - 1 - j : j;
      if (wall.isActive(k)) order.push_back(k);
    }
    if (order.empty()) return Scalar(0.0);
    for (size_t j = 0; j + 1 < order.size(); ++j) {
      const Scalar& a = slip[order[j]];
      const Scalar& b = slip[order[j + 1]];
      if (a * b <= 0.0 && a != b) {
        const double ta = theta(order[j]), tb = theta(order[j + 1]);
        return ta + (tb - ta) * a / (a - b);
      }
    }
    // No sign change: the slip's sign at the downstream end says which way the contact slips, the
    // tool's motion giving the positive sense of t there.
    const double along = wall.wallTangentialSpeed(order.front());  // v_w·t: the tool's motion along t
    const bool outruns = (slip[order.front()] > 0.0) == (along > 0.0);
    return Scalar(outruns ? theta(order.back()) : theta(order.front()));
  }

 private:
  std::string m_wall;
};

}  // namespace flowform
