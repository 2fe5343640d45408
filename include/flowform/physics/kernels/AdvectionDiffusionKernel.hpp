// A passive scalar c, advected by a prescribed velocity w and diffused (the seed of the
// temperature field). Owns and reads one scalar field (default name "Concentration"); it
// neither reads nor is read by the flow, so the flow's rows are those of a flow-only case.
//
// For a cell K with shape functions N_a, constant w, diffusivity κ and source s:
//
//   R_c[a] = ∫_K ( N_a w·∇c + κ ∇N_a·∇c − N_a s ) dΩ
//
// (the Galerkin form of w·∇c − κ Δc = s; no SUPG: meant for moderate cell Péclet numbers
// |w| h / 2κ). Plane strain: dΩ = dx dy; axisymmetric: dΩ = 2π r dr dz, ∇ = (∂_r, ∂_z), w the
// (r, z) velocity. With the flow kernel's rule (integrationOrder) the integrals are exact for
// linear c on P1 and Q1 cells in plane strain (the Q1 integrands are of degree ≤ 2 in each
// reference direction, 2×2 Gauss), so a linear c with s = w·∇c and its Dirichlet data is
// reproduced to round-off (tests/unit/FieldKernelTest.cpp). Axisymmetric, Δc of a linear c
// has the term (1/r) ∂c/∂r: a linear c is not a solution there.
#pragma once

#include <string>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/physics/PhysicsKernel.hpp"

namespace flowform {

struct AdvectionDiffusionSettings {
  std::string field = "Concentration";  ///< the scalar's FieldRegistry name
  double velocity[2] = {0.0, 0.0};      ///< w
  double diffusivity = 1.0;             ///< κ > 0
  double source = 0.0;                  ///< s, per unit volume
};

class AdvectionDiffusionKernel {
 public:
  static constexpr int kNumComponents = 1;  // c
  static constexpr bool kUsesStressDual = false;

  explicit AdvectionDiffusionKernel(const AdvectionDiffusionSettings& settings) : m_settings(settings) {}

  const char* name() const { return "Advection Diffusion"; }
  KernelFields fields() const { return {{m_settings.field}, {m_settings.field}}; }

  template <typename Scalar, typename PScalar>
  void evaluate(const CellContext<PScalar>& c, const Scalar* values, Scalar* residual) const {
    const CellQuadrature& cq = c.cell.rule;
    const double wx = m_settings.velocity[0], wy = m_settings.velocity[1];
    const double kappa = m_settings.diffusivity, s = m_settings.source;
    for (int q = 0; q < cq.numPoints; ++q) {
      const double w = measureWeight(cq, q, c.settings.geometry);
      Scalar cx = 0.0, cy = 0.0;  // ∇c
      for (int a = 0; a < cq.numNodes; ++a) {
        cx += cq.dNdx[q][a] * values[a];
        cy += cq.dNdy[q][a] * values[a];
      }
      const Scalar advection = wx * cx + wy * cy;
      for (int a = 0; a < cq.numNodes; ++a) {
        const double N = cq.N[q][a], Nx = cq.dNdx[q][a], Ny = cq.dNdy[q][a];
        residual[a] += w * (N * advection + kappa * (Nx * cx + Ny * cy) - N * s);
      }
    }
  }

 private:
  AdvectionDiffusionSettings m_settings;
};

}  // namespace flowform
