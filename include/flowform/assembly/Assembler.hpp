// Global residual and Jacobian from the element kernels (Albany's gather/scatter without
// Phalanx). The only place where derivatives are seeded and read:
//   Residual — double
//   Jacobian — Sacado::Fad::SFad<double, N>, N = the cell's dof count (9 for P1, 12 for Q1)
// Cells are this rank's partition; contributions to shared rows are summed by the
// FECrsMatrix / an overlap vector exported with ADD.
#pragma once

#include <Teuchos_RCP.hpp>

#include "flowform/BoundaryConditions.hpp"
#include "flowform/DofMap.hpp"
#include "flowform/Material.hpp"
#include "flowform/Mesh.hpp"
#include "flowform/TpetraTypes.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/kernels/FlowResidual.hpp"

namespace flowform {

struct SensitivityParameter;

/// What the bulk physics is: geometry, stabilization, body force and the material law.
struct FlowPhysics {
  FlowKernelSettings kernel;
  MaterialParameters<double> material{0.0, 1.0, 1.0, 1e-3};
};

class Assembler {
 public:
  Assembler(const Mesh& mesh, const DofMap& dofMap, const BoundaryConditions& bcs);

  /// The physics may change between solves (continuation in n and e0).
  void setPhysics(const FlowPhysics& physics) { m_physics = physics; }
  const FlowPhysics& physics() const { return m_physics; }

  /// Contact walls to assemble with the cells (owned by the caller; may be empty).
  void setContactWalls(const std::vector<ContactWall>* walls);

  /// F(x) on the owned map. With `applyConstraints` false, the rows of constrained nodes
  /// keep their momentum equations: at a prescribed-velocity node the entry is then the
  /// force the tool applies (the reaction), which the Boundary Force response sums.
  void residual(const Vector& xOwned, Vector& fOwned, bool applyConstraints = true) const;

  /// ∂R/∂h at x (owned map, SPEC §4): the same templated residual with the parameter h
  /// seeded and the dofs held, bulk and contact terms alike. Constraint rows (prescribed
  /// velocity, symmetry) give 0: they do not depend on h. The contact penalty scales μ_k and
  /// the Tresca σ̄_k are held (ContactWall::setScales): they do not depend on h here.
  void parameterDerivative(const Vector& xOwned, const SensitivityParameter& h, Vector& dRdh) const;

  /// The directional derivative d/dε F(x + ε dx; h + ε) at ε = 0, into `dfOwned`: J dx +
  /// ∂F/∂h. `dxOwned` null: no motion of x; `h` null: no parameter. With `applyConstraints`
  /// false, of the unconstrained residual (the reactions' derivative, for the responses).
  void tangent(const Vector& xOwned, const Vector* dxOwned, const SensitivityParameter* h, Vector& dfOwned,
               bool applyConstraints = true) const;

  /// Per overlap node: the largest cell viscosity μ and flow stress σ̄ (at the centroid) over
  /// all cells that touch it, on every rank alike (the contact penalty scales).
  void nodalCellMaxima(const Vector& xOwned, std::vector<double>& viscosity, std::vector<double>& flowStress) const;
  /// J = dF/dx at x into `jacobian` (built on dofMap.graph()); F(x) too when `fOwned` is given.
  void jacobian(const Vector& xOwned, FECrsMatrix& jacobian, Vector* fOwned = nullptr) const;

  /// A Jacobian matrix on this problem's graph, values unset.
  Teuchos::RCP<FECrsMatrix> createJacobian() const;

 private:
  template <int NumNodes>
  void assembleJacobianCells(const Vector& xOverlap, FECrsMatrix& jacobian, Vector* fOverlap) const;
  /// The constraint rows (a·u − b, or u − v) at x; `withOffsets` false drops b and v, which
  /// gives the rows' derivative a·du when xOverlap is a direction du.
  void addConstraintRows(const Vector& xOverlap, FECrsMatrix* jacobian, Vector* fOverlap,
                         bool withOffsets = true) const;
  void addTractions(Vector& fOverlap, bool applyConstraints = true) const;
  template <typename Scalar>
  void gatherWallNode(const Vector& xOverlap, int ref, Scalar* u, Scalar* p) const;
  /// Residual (Scalar double) or tangent (an AD type: x seeded along dx, h seeded) of the
  /// cells and of the walls, added into fOverlap.
  template <typename Scalar>
  void addCellResiduals(const Vector& xOverlap, const Vector* dxOverlap, const SensitivityParameter* h,
                        Vector& fOverlap, bool applyConstraints) const;
  template <typename Scalar>
  void addContactResidual(const Vector& xOverlap, const Vector* dxOverlap, const SensitivityParameter* h,
                          Vector& fOverlap, bool applyConstraints) const;
  void addContactJacobian(const Vector& xOverlap, FECrsMatrix& jacobian, Vector* fOverlap) const;

  /// An owned wall node and the overlap indices of it and its wall neighbours (−1: none).
  struct WallNodeRef {
    int wall, k;
    LO node, previous, next;
  };
  const Vector& importSolution(const Vector& xOwned) const;

  const Mesh& m_mesh;
  const DofMap& m_dofMap;
  const BoundaryConditions& m_bcs;
  FlowPhysics m_physics;
  const std::vector<ContactWall>* m_walls = nullptr;
  std::vector<WallNodeRef> m_wallNodes;
  Teuchos::RCP<Vector> m_xOverlap;  ///< scratch: x imported to the overlap map
  Teuchos::RCP<Vector> m_fOverlap;  ///< scratch: residual before the export to owned rows
  Teuchos::RCP<Vector> m_dxOverlap;  ///< scratch: a direction imported to the overlap map
};

}  // namespace flowform
