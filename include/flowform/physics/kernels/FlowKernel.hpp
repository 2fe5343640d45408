// The stabilized rigid-viscoplastic flow as a physics kernel: owns and reads Velocity and
// Pressure; its element residual is addFlowResidual (physics/FlowResidual.hpp, the weak form
// there and in docs/theory.md §1). Every case has it, registered first.
#pragma once

#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/PhysicsKernel.hpp"

namespace flowform {

struct FlowKernel {
  static constexpr int kNumComponents = EqualOrderLayout::kFieldsPerNode;  // u_x, u_y, p
  static constexpr bool kUsesStressDual = true;

  const char* name() const { return "Flow"; }
  KernelFields fields() const { return {{"Velocity", "Pressure"}, {"Velocity", "Pressure"}}; }

  template <typename Scalar, typename PScalar>
  void evaluate(const CellContext<PScalar>& c, const Scalar* values, Scalar* residual) const {
    addFlowResidual(c.cell.rule, c.cell.centroid, c.cell.diameter, c.settings, c.material, values, residual, c.dual);
  }
};

}  // namespace flowform
