// Forward Slip: how much faster the product leaves than the rotating tool's surface moves,
//   S_f = v_exit / v_roll − 1,
// v_exit = ū·ê the mean velocity over the Exit Boundary (ū = Σ_k u_k ∫N_k ds / ∫ds) along
// ê = v_w/|v_w| at the wall's downstream end (the exit plane of a roll's arc, meshes/rolling.geo),
// v_roll = |v_w| there = |ω| R. A rolled strip leaves rigid, so ū is its speed; S_f > 0 when the
// neutral point lies inside the arc.
#pragma once

#include <cmath>
#include <vector>

#include "flowform/core/InputError.hpp"
#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

struct ForwardSlip {
  static constexpr const char* kName = "Forward Slip";
  static constexpr const char* kDescription =
      "v_exit / v_roll - 1: the mean velocity over the Exit Boundary along a rotating wall's surface velocity at its "
      "downstream end, over that surface speed (a roll's forward slip)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the rotating contact wall (the roll)");
    list.set("Exit Boundary", "", "Forward Slip: the group the product leaves through (its mean velocity is v_exit)");
  }
  explicit ForwardSlip(const Teuchos::ParameterList& p)
      : m_wall(p.get<std::string>("Boundary")), m_exit(p.get<std::string>("Exit Boundary")) {}

  void checkMesh(const Mesh& mesh) const {
    if (!mesh.hasBoundary(m_exit))
      throw InputError("Exit Boundary: mesh '" + mesh.source + "' has no boundary group '" + m_exit +
                       "'; it has: " + mesh.boundaryNames());
  }

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const ContactWall& wall = wallNamed(c.walls, m_wall);
    if (wall.motion().kind != ToolMotion::Kind::Rotation)
      throw InputError("Responses: a Forward Slip measures a rotating wall, and wall '" + m_wall +
                       "' has no Tool Motion = Rotation");
    const auto& vw = wall.wallVelocity(wall.downstreamEnd());
    const double speed = std::hypot(vw[0], vw[1]);
    const BoundaryCurve curve = buildBoundaryCurve(c.mesh, c.mesh.boundary(m_exit));
    const size_t numNodes = curve.nodes.size();
    std::vector<double> w(numNodes, 0.0);
    double length = 0.0;
    for (size_t sgm = 0; sgm < curve.segmentLength.size(); ++sgm) {
      w[sgm] += 0.5 * curve.segmentLength[sgm];
      w[(sgm + 1) % numNodes] += 0.5 * curve.segmentLength[sgm];
      length += curve.segmentLength[sgm];
    }
    Scalar local = 0.0;
    for (size_t k = 0; k < numNodes; ++k) {
      const LO n = c.dofMap.overlapIndex(curve.nodes[k]);
      if (n < 0 || !c.dofMap.ownsNode(n)) continue;
      local += w[k] * (c.u(c.x, n, kUx) * vw[0] + c.u(c.x, n, kUy) * vw[1]) / speed;
    }
    const Scalar exitSpeed = sumOverRanks(*c.dofMap.comm(), local) / length;
    return exitSpeed / speed - 1.0;
  }

 private:
  std::string m_wall, m_exit;
};

}  // namespace flowform
