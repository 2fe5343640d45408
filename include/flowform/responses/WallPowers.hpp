// The responses summed node by node over the contact walls (each node by its owner), from the
// wall's part of the momentum residual R_k = α_n ((u − v_w)·n) n + g t (normal penalty and friction;
// v_w the tool's surface velocity, 0 for a fixed tool):
//   Wall Force      Σ R_k on the named wall (component X or Y): the force the material exerts on
//                   it, a tool's cutting (X) and thrust (Y) forces; by the balance of the whole
//                   body, the sum of the Boundary Forces on the velocity-driven groups when the
//                   rest is traction-free
//   Wall Pressure   Σ R_k·n_k / A over the named wall (A its length, or area ∫ 2πr ds when
//                   axisymmetric): the mean normal pressure on the tool, e.g. a drawing die's
//   Friction Power  Σ g_k (u − v_w)·t_k over the active nodes of every wall: the friction
//                   dissipation (g_k times the relative slip)
//   Penalty Power   Σ (normal part of R_k)·(u − v_w) = α_n ((u − v_w)·n)²: the work of the normal penalty
// A moving tool's own power and torque are Tool Power and Tool Torque (their own files).
#pragma once

#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

/// Σ over the owned nodes of the walls (only wall `only` when not empty) of add(local, wall, k, fp,
/// v, R_k): v the node's stencil values (ContactWall::nodeStencil, u_k first).
template <typename Scalar, typename Add>
Scalar sumOverWallNodes(const ResponseContext<Scalar>& c, const std::string& only, Add&& add) {
  const DofMap& dofMap = c.dofMap;
  Scalar local = 0.0;
  for (size_t w = 0; w < c.walls.size(); ++w) {
    const ContactWall& wall = c.walls[w];
    if (!only.empty() && wall.name() != only) continue;
    const FrictionParameters<Scalar> fp = frictionFor<Scalar>(wall, static_cast<int>(w), c.h);
    for (int k = 0; k < wall.numNodes(); ++k) {
      const LO n = dofMap.overlapIndex(wall.curve().nodes[k]);
      if (!dofMap.ownsNode(n)) continue;
      // The node's stencil values (ContactWall::nodeStencil), an absent neighbour's 0.
      Scalar v[ContactWall::kNodeStencilSize];
      const auto stencil = wall.nodeStencil(k);
      for (int i = 0; i < ContactWall::kNodeStencilSize; ++i)
        v[i] = stencil[i].node < 0 ? Scalar(0.0)
                                   : c.at(c.x, dofMap.dof(dofMap.overlapIndex(wall.curve().nodes[stencil[i].node]),
                                                          stencil[i].component));
      Scalar Rk[2] = {0.0, 0.0};
      wall.addNodeResidual(k, fp, v, Rk);
      add(local, wall, k, fp, v, Rk);
    }
  }
  return sumOverRanks(*dofMap.comm(), local);
}

struct WallForce {
  static constexpr const char* kName = "Wall Force";
  static constexpr const char* kDescription =
      "the force the material exerts on a contact wall (Component X or Y): the wall's part of the momentum residual "
      "(a tool's cutting and thrust forces)";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the contact wall");
    declareComponent(list, "the force component");
  }
  explicit WallForce(const Teuchos::ParameterList& p)
      : m_wall(p.get<std::string>("Boundary")), m_component(componentIndex(p)) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return sumOverWallNodes(c, m_wall, [&](Scalar& local, const ContactWall&, int, const FrictionParameters<Scalar>&,
                                           const Scalar*, const Scalar* Rk) {
      local += m_component == 0 ? Rk[0] : Rk[1];
    });
  }

 private:
  std::string m_wall;
  int m_component;
};

struct WallPressure {
  static constexpr const char* kName = "Wall Pressure";
  static constexpr const char* kDescription =
      "sum of R_k.n_k over a contact wall's nodes divided by its length (area 2 pi r ds when axisymmetric): the mean "
      "normal pressure on the tool";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = true, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) { declareBoundary(list, "the contact wall"); }
  explicit WallPressure(const Teuchos::ParameterList& p) : m_wall(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const Scalar force = sumOverWallNodes(c, m_wall, [&](Scalar& local, const ContactWall& wall, int k,
                                                         const FrictionParameters<Scalar>&, const Scalar*,
                                                         const Scalar* Rk) {
      const auto& n = wall.curve().normals[k];
      local += Rk[0] * n[0] + Rk[1] * n[1];
    });
    return force / curveArea(c.mesh, wallNamed(c.walls, m_wall).curve(), c.geometry());
  }

 private:
  std::string m_wall;
};

struct FrictionPower {
  static constexpr const char* kName = "Friction Power";
  static constexpr const char* kDescription =
      "sum over active wall nodes of g_k (u - v_w).t_k (the relative slip): the friction dissipation";
  static constexpr bool kNeedsBoundary = false, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList&) {}
  explicit FrictionPower(const Teuchos::ParameterList&) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return of(c, "");
  }
  /// The friction power of wall `only` (every wall when empty).
  template <typename Scalar>
  static Scalar of(const ResponseContext<Scalar>& c, const std::string& only) {
    return sumOverWallNodes(c, only, [&](Scalar& local, const ContactWall& wall, int k,
                                         const FrictionParameters<Scalar>& fp, const Scalar* u, const Scalar*) {
      const Scalar g = wall.tangentialForce(k, fp, u);
      local += g * wall.relativeSlip(k, u);
    });
  }
};

struct PenaltyPower {
  static constexpr const char* kName = "Penalty Power";
  static constexpr const char* kDescription =
      "sum over active wall nodes of alpha_n ((u - v_w).n)^2: the work of the normal penalty";
  static constexpr bool kNeedsBoundary = false, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList&) {}
  explicit PenaltyPower(const Teuchos::ParameterList&) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    return sumOverWallNodes(c, "", [&](Scalar& local, const ContactWall& wall, int k,
                                       const FrictionParameters<Scalar>& fp, const Scalar* u, const Scalar* Rk) {
      const auto& nk = wall.curve().normals[k];
      const auto& vw = wall.wallVelocity(k);
      const Scalar g = wall.tangentialForce(k, fp, u);
      local += (Rk[0] + g * nk[1]) * (u[0] - vw[0]) + (Rk[1] - g * nk[0]) * (u[1] - vw[1]);
    });
  }
};

}  // namespace flowform
