// What every response of the case gets and the tools they share (the responses themselves are
// one file each beside this one, registered in ResponseRegistry.hpp).
//
// A response φ(q, h) is evaluated on the scalar type of the evaluation: double for its value,
// TangentFad (EvaluationTypes.hpp) for its total derivative along a direction (dq/dh, h),
//   dφ/dh = ∂φ/∂h + ∂φ/∂q dq/dh   (docs/theory.md §4, paper eq. 21),
// with x seeded along dq/dh, the material and friction parameters seeded by h, and the reactions'
// derivative from Assembler::tangent; GradientFad for its gradient by the solution and the
// reactions, ∂φ/∂x and ∂φ/∂R_unc, every dof its own variable (the adjoint's right-hand side,
// Responses::gradients). A response never seeds or reads derivatives itself: the same code
// gives the value, the DDM derivative, a finite difference of two values and the adjoint's seed.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/assembly/EvaluationTypes.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/physics/FlowPhysics.hpp"

namespace flowform {

/// The converged state a response reads, for one evaluation type.
template <typename Scalar>
struct ResponseContext {
  const Workset& x;          ///< the solution (and the direction dq/dh) on the overlap map
  const Workset& reactions;  ///< R_unc(x), the unconstrained residual (and its derivative), on the owned map
  const Mesh& mesh;
  const DofMap& dofMap;
  const FlowPhysics& physics;
  const MaterialParameters<Scalar>& material;  ///< with h seeded (tangent)
  const std::vector<ContactWall>& walls;
  const SensitivityParameter* h;  ///< the parameter of a derivative; null for values

  Geometry geometry() const { return physics.kernel.geometry; }
  /// Value (double) or value and directional derivative (tangent) of dof `d` of a workset.
  Scalar at(const Workset& ws, LO d) const {
    Scalar s;
    gather(ws, &d, 1, &s);
    return s;
  }
  Scalar u(const Workset& ws, LO n, int field) const { return at(ws, dofMap.dof(n, field)); }
};

/// A workset that reads `x` (and the direction `dx`) on their own map.
Workset vectorReader(const Vector& x, const Vector* dx = nullptr);

/// Σ over the ranks (the derivative summed with the value). A gradient keeps this rank's
/// derivatives: they are by this rank's dofs, and the ranks' gradients add up to the global one
/// (every later operation is evaluated at the same global values on every rank).
double sumOverRanks(const Comm& comm, double local);
TangentFad sumOverRanks(const Comm& comm, const TangentFad& local);
GradientFad sumOverRanks(const Comm& comm, const GradientFad& local);

/// The length of the curve, or the area 2π r ds it sweeps when axisymmetric (the same on
/// every rank: the curve is replicated).
double curveArea(const Mesh& mesh, const BoundaryCurve& curve, Geometry geometry);

/// The contact wall called `name` (InputError when there is none: Responses::checkWalls says it first).
const ContactWall& wallNamed(const std::vector<ContactWall>& walls, const std::string& name);

/// ∫ 2μ D:D dΩ (plastic power) and Σ τ_K ∫ ∇p·(∇p − f) (stabilization power) over this
/// rank's cells, and (values only) the area of the cells where |u| < deadSpeed. The kernel's own
/// quadrature, so that the powers match the discrete equations exactly.
template <typename Scalar>
void cellIntegrals(const Workset& x, const Mesh& mesh, const DofMap& dofMap, const FlowPhysics& physics,
                   const MaterialParameters<Scalar>& material, double deadSpeed, Scalar& plasticPower,
                   Scalar& stabilizationPower, double& deadArea);

/// Entries shared by several responses (each response's own doc string, merged by the registry).
void declareBoundary(Teuchos::ParameterList& list, const std::string& doc);
void declareComponent(Teuchos::ParameterList& list, const std::string& doc);
/// 0 for "X", 1 for "Y".
inline int componentIndex(const Teuchos::ParameterList& list) { return list.get<std::string>("Component") == "X" ? 0 : 1; }

}  // namespace flowform
