// The seam of the physics (MOOSE's Kernel, Albany's residual evaluators without Phalanx):
// a physics kernel is one small class in physics/kernels/ that
//   - names the fields it owns (its residual rows) and the fields it reads (its element
//     vector, node-major: NodeMajorLayout<kNumComponents>, the owned ones among them);
//   - gives its element residual templated on the scalar type of the dofs (Scalar) and of the
//     material parameters (PScalar). It never seeds or reads derivatives: the assembler
//     gathers the read components, seeds them (Residual, Jacobian, ParamDeriv), and scatters
//     the owned rows (assembly/CellKernel.hpp).
//
// The compile-time part of a kernel (what CellKernelOf<Kernel> uses):
//   static constexpr int  kNumComponents;   components read per node (sizes SFad<kNumComponents × nodes>)
//   static constexpr bool kUsesStressDual;  Jacobian evaluations pass the cell's stress duals
//   const char* name() const;
//   KernelFields fields() const;            owned ⊆ read, read in element-vector order
//   template <typename Scalar, typename PScalar>
//   void evaluate(const CellContext<PScalar>&, const Scalar* values, Scalar* residual) const;
// `residual` has the element vector's size; the kernel adds into its owned entries only.
#pragma once

#include <string>
#include <vector>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/physics/StrainField.hpp"
#include "flowform/physics/StressDual.hpp"
#include "flowform/physics/ThermalProperties.hpp"

namespace flowform {

/// The fields a kernel owns (rows) and reads (element vector), by FieldRegistry name.
struct KernelFields {
  std::vector<std::string> owned, read;
};

/// What a kernel gets for one cell besides its dofs: the cell's geometry (rule, centroid,
/// h_K), the case's bulk settings (geometry, β, body force), the case's material and thermal
/// properties (PScalar: seeded by the assembler when a parameter derivative is wanted), the strain
/// field's settings and, for a kernel with kUsesStressDual in a Jacobian evaluation with the dual
/// linearization, the cell's points.
template <typename PScalar>
struct CellContext {
  const CellGeometry& cell;
  const FlowKernelSettings& settings;
  const MaterialParameters<PScalar>& material;
  StressDualPoint* dual = nullptr;
  const ThermalParameters<PScalar>* thermal = nullptr;  ///< k, ρc, η (seeded like the material)
  const StrainFieldSettings* strainField = nullptr;     ///< ε_min and the coupling λ (a Strain field's)
};

}  // namespace flowform
