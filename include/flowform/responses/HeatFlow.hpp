// Heat Flow: Q = −Σ_i R_T,i over the group's nodes, the heat that leaves the workpiece through a
// group held at a prescribed temperature (a cooled wall, a tool at its temperature), by
// conduction; a case with a Temperature field (Material/Thermal, docs/theory.md §10) only.
//
// R_T is the energy equation's unconstrained residual (physics/kernels/CoupledFlowKernel.hpp). With
// Σ_a N_a = 1 its weak form gives, at a node a held at its temperature,
//   R_T,a = ∫_Γ N_a k ∂T/∂n dΓ   (the heat that enters through Γ near a)
// so the sum over the group is the consistent heat flux into the workpiece and Q its negative
// (per unit depth in plane strain, total in axisymmetric models). On a group without a prescribed
// temperature (insulated) R_T vanishes at convergence and so does Q. The sum of Q over every
// held group closes the discrete energy balance: Σ Q = ∫ q dΩ − ∫ a·∇T dΩ (the plastic heat less
// the enthalpy the flow carries out; docs/theory.md §10).
#pragma once

#include <string>

#include "flowform/responses/TemperatureResponses.hpp"

namespace flowform {

struct HeatFlow {
  static constexpr const char* kName = "Heat Flow";
  static constexpr const char* kDescription =
      "the heat leaving the workpiece by conduction through a group held at a prescribed Temperature (the "
      "temperature rows' reactions, negated); needs Material/Thermal";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = true, kAdaptivityTarget = false,
                        kDifferentiable = true;
  static constexpr const char* kField = kTemperatureField;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the group held at its temperature");
  }
  explicit HeatFlow(const Teuchos::ParameterList& p) : m_boundary(p.get<std::string>("Boundary")) {}

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const int t = temperatureComponent(c.dofMap, "the Heat Flow through '" + m_boundary + "'");
    const BoundaryCurve curve = buildBoundaryCurve(c.mesh, c.mesh.boundary(m_boundary));
    Scalar local = 0.0;
    for (GO node : curve.nodes) {
      const LO n = c.dofMap.overlapIndex(node);
      if (c.dofMap.ownsNode(n)) local -= c.u(c.reactions, n, t);  // each node once, by its owner
    }
    return sumOverRanks(*c.dofMap.comm(), local);
  }

 private:
  std::string m_boundary;
};

}  // namespace flowform
