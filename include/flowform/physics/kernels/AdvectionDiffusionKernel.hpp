// A passive scalar c, advected by a velocity w and diffused (the seed of the temperature
// field). Owns one scalar field (default name "Concentration"); w is either prescribed
// (constant; the kernel reads c only) or the flow's velocity u_h (it reads u_x, u_y and c,
// owns c). Either way the flow does not read c, so the flow's rows are those of a flow-only
// case.
//
// For a cell K with shape functions N_a, diffusivity κ and source s(x) = s0 + ∇s·x:
//
//   R_c[a] = ∫_K ( N_a w·∇c + κ ∇N_a·∇c − N_a s ) dΩ
//
// (the Galerkin form of w·∇c − κ Δc = s; no SUPG: meant for moderate cell Péclet numbers
// |w| h / 2κ). Plane strain: dΩ = dx dy; axisymmetric: dΩ = 2π r dr dz, ∇ = (∂_r, ∂_z), w the
// (r, z) velocity. With the flow kernel's rule (integrationOrder) and a constant w and s the
// integrals are exact for linear c on P1 and Q1 cells in plane strain (the Q1 integrands are
// of degree ≤ 2 in each reference direction, 2×2 Gauss), so a linear c with s = w·∇c and its
// Dirichlet data is reproduced to round-off (tests/unit/FieldKernelTest.cpp). Axisymmetric,
// Δc of a linear c has the term (1/r) ∂c/∂r: a linear c is not a solution there.
#pragma once

#include <string>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/physics/PhysicsKernel.hpp"

namespace flowform {

/// Where the advecting velocity w comes from.
enum class AdvectingVelocity { Prescribed, Flow };

struct AdvectionDiffusionSettings {
  std::string field = "Concentration";  ///< the scalar's FieldRegistry name
  double velocity[2] = {0.0, 0.0};      ///< w when prescribed
  double diffusivity = 1.0;             ///< κ > 0
  double source = 0.0;                  ///< s0, per unit volume
  double sourceGradient[2] = {0.0, 0.0};  ///< ∇s
};

template <AdvectingVelocity Velocity = AdvectingVelocity::Prescribed>
class AdvectionDiffusionKernel {
  static constexpr bool kByFlow = Velocity == AdvectingVelocity::Flow;
  static constexpr int kC = kByFlow ? 2 : 0;  ///< slot of c in a node's element vector

 public:
  static constexpr int kNumComponents = kByFlow ? 3 : 1;  // (u_x, u_y,) c
  static constexpr bool kUsesStressDual = false;

  explicit AdvectionDiffusionKernel(const AdvectionDiffusionSettings& settings) : m_settings(settings) {}

  const char* name() const { return kByFlow ? "Advection Diffusion (flow velocity)" : "Advection Diffusion"; }
  KernelFields fields() const {
    if (kByFlow) return {{m_settings.field}, {"Velocity", m_settings.field}};
    return {{m_settings.field}, {m_settings.field}};
  }

  template <typename Scalar, typename PScalar>
  void evaluate(const CellContext<PScalar>& c, const Scalar* values, Scalar* residual) const {
    constexpr int C = kNumComponents;
    const CellQuadrature& cq = c.cell.rule;
    const double kappa = m_settings.diffusivity;
    for (int q = 0; q < cq.numPoints; ++q) {
      const double w = measureWeight(cq, q, c.settings.geometry);
      Scalar cx = 0.0, cy = 0.0;  // ∇c
      Scalar wx = m_settings.velocity[0], wy = m_settings.velocity[1];
      if constexpr (kByFlow) wx = wy = 0.0;
      for (int a = 0; a < cq.numNodes; ++a) {
        cx += cq.dNdx[q][a] * values[C * a + kC];
        cy += cq.dNdy[q][a] * values[C * a + kC];
        if constexpr (kByFlow) {
          wx += cq.N[q][a] * values[C * a + kUx];
          wy += cq.N[q][a] * values[C * a + kUy];
        }
      }
      const Scalar advection = wx * cx + wy * cy;
      const double s = m_settings.source + m_settings.sourceGradient[0] * cq.x[q] + m_settings.sourceGradient[1] * cq.y[q];
      for (int a = 0; a < cq.numNodes; ++a) {
        const double N = cq.N[q][a], Nx = cq.dNdx[q][a], Ny = cq.dNdy[q][a];
        residual[C * a + kC] += w * (N * advection + kappa * (Nx * cx + Ny * cy) - N * s);
      }
    }
  }

 private:
  AdvectionDiffusionSettings m_settings;
};

}  // namespace flowform
