// Global residual, Jacobian and tangents from the physics kernels and the contact walls, by
// one templated loop over the evaluation types (assembly/EvaluationTypes.hpp):
//   cells   — for each of the case's kernels in order (assembly/CellKernel.hpp): gather the
//             components it reads, its element residual, constraint rows, scatter its rows;
//             a flow-only case has one kernel, the flow (physics/kernels/FlowKernel.hpp);
//   walls   — gather a wall node's stencil (ContactWall::nodeStencil: u_k, p of k and its
//             wall neighbours), the wall's node residual (penalty and friction law),
//             constraint rows, scatter;
// plus the prescribed tractions (constant) and the constraint rows (linear): the velocity
// constraints and the prescribed values of other fields (setPrescribedValues). Cells are this
// rank's partition; contributions to shared rows are summed by the FECrsMatrix / an overlap
// vector exported with ADD.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "flowform/assembly/CellKernel.hpp"
#include "flowform/assembly/EvaluationTypes.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/bc/ThermalBoundaryConditions.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/physics/FlowPhysics.hpp"

namespace flowform {

struct SensitivityParameter;

/// Values at the centroid of one cell: e = sqrt(2/3 D:D), e_r, μ(e_r), σ̄(e_r).
struct CellState {
  double strainRate, regularizedStrainRate, viscosity, flowStress;
};

class Assembler {
 public:
  Assembler(const Mesh& mesh, const DofMap& dofMap, const BoundaryConditions& bcs);

  /// The physics may change between solves (continuation in n and e0).
  void setPhysics(const FlowPhysics& physics) { m_physics = physics; }
  const FlowPhysics& physics() const { return m_physics; }
  const Mesh& mesh() const { return m_mesh; }
  const DofMap& dofMap() const { return m_dofMap; }

  /// Contact walls to assemble with the cells (owned by the caller; may be empty).
  void setContactWalls(const std::vector<ContactWall>* walls);
  /// Whether the contact walls' part of F is affine in x (no walls, or each ContactWall::isLinear):
  /// with a Newtonian material F is then linear and one solve is exact.
  bool contactIsLinear() const {
    if (m_walls)
      for (const ContactWall& wall : *m_walls)
        if (!wall.isLinear()) return false;
    return true;
  }

  /// The case's physics kernels, assembled in this order (default: the flow kernel alone).
  /// Every component of the DofMap's fields must be owned by exactly one kernel.
  void setKernels(std::vector<std::shared_ptr<const CellKernel>> kernels);
  const std::vector<std::shared_ptr<const CellKernel>>& kernels() const { return m_kernels; }

  /// A Dirichlet value of a component other than the velocity's (those are boundary
  /// conditions): at mesh node `node`, row (node, component) becomes x − value.
  struct PrescribedValue {
    GO node;
    int component;
    double value;
  };
  /// Replaces the prescribed values (nodes not on this rank are skipped).
  void setPrescribedValues(const std::vector<PrescribedValue>& values);
  /// Boundary edges that transfer heat (bc/ThermalBoundaryConditions): the rows of `component`
  /// (the temperature) of the constrained residual gain ∫_edge N_a h (T − T_a) dΓ; the
  /// unconstrained residual (the reactions) does not.
  void setHeatTransfer(std::vector<ThermalBoundaryConditions::TransferEdge> edges, int component);
  /// Friction heat (bc/ThermalBoundaryConditions): β per contact wall (the walls' order; empty:
  /// none); the row of `component` (the temperature) of each wall node gains −β g_k (u_k − v_w)·t_k,
  /// the share of the node's friction power that heats the workpiece, in both residuals.
  void setFrictionHeat(std::vector<double> fractions, int component);
  bool hasFrictionHeat() const { return !m_frictionHeat.empty(); }

  /// F(x) on the owned map. With `applyConstraints` false, the rows of constrained nodes
  /// keep their momentum equations: at a prescribed-velocity node the entry is then the
  /// force the tool applies (the reaction), which the Boundary Force response sums.
  void residual(const Vector& xOwned, Vector& fOwned, bool applyConstraints = true) const;
  /// The unconstrained residual at x (residual(x, f, false)) made the constrained one in place:
  /// every row operation the assembly applies per element (constraint rows zeroed or turned,
  /// prescribed fields' rows zeroed) is linear, so it applies to the sum as well; then the
  /// constraint rows. One assembly serves the reactions and R (the linearized surface update).
  void constrainResidual(const Vector& xOwned, Vector& fOwned) const;

  /// J = dF/dx at x into `jacobian` (built on dofMap.graph()); F(x) too when `fOwned` is given.
  /// With `dual`, the cells' stress and the walls' slip are linearized by the dual methods
  /// and the duals are moved to x first (assembly/NewtonDual.hpp); without, J is exact.
  void jacobian(const Vector& xOwned, FECrsMatrix& jacobian, Vector* fOwned = nullptr,
                NewtonDual* dual = nullptr) const;
  /// The exact Jacobian of the unconstrained residual (the reactions' derivative).
  void unconstrainedJacobian(const Vector& xOwned, FECrsMatrix& jacobian) const;
  const BoundaryConditions& boundaryConditions() const { return m_bcs; }

  /// The directional derivative d/dε F(x + ε dx; h + ε) at ε = 0, into `dfOwned`: J dx +
  /// ∂F/∂h. `dxOwned` null: no motion of x; `h` null: no parameter. With `applyConstraints`
  /// false, of the unconstrained residual (the reactions' derivative, for the responses).
  void tangent(const Vector& xOwned, const Vector* dxOwned, const SensitivityParameter* h, Vector& dfOwned,
               bool applyConstraints = true) const;

  /// ∂R/∂h at x (owned map, docs/theory.md §4): the tangent with the dofs held. Constraint
  /// rows (prescribed velocity, symmetry) give 0: they do not depend on h. The contact
  /// penalty scales μ_k and the Tresca σ̄_k are held (ContactWall::setScales).
  void parameterDerivative(const Vector& xOwned, const SensitivityParameter& h, Vector& dRdh) const;

  /// The centroid values of each of this rank's cells (dofMap().cells() order) at x.
  std::vector<CellState> cellStates(const Vector& xOwned) const;
  /// Per overlap node: the largest cell viscosity μ and flow stress σ̄ (at the centroid) over
  /// all cells that touch it, on every rank alike (the contact penalty scales).
  void nodalCellMaxima(const Vector& xOwned, std::vector<double>& viscosity, std::vector<double>& flowStress) const;

  /// A Jacobian matrix on this problem's graph, values unset.
  Teuchos::RCP<FECrsMatrix> createJacobian() const;
  /// x imported to the overlap map (scratch, valid until the next call).
  const Vector& importSolution(const Vector& xOwned) const;

 private:
  /// The one loop over this rank's cells, for every evaluation type.
  template <typename EvalT>
  void assembleCells(Workset& ws, const SensitivityParameter* h, bool applyConstraints) const;
  /// The one loop over this rank's heat-transferring boundary edges, for every evaluation type
  /// (constrained residual only: prescribed rows get nothing).
  template <typename EvalT>
  void assembleHeatTransfer(Workset& ws) const;
  /// The one loop over this rank's contact wall nodes, for every evaluation type.
  template <typename EvalT>
  void assembleContact(Workset& ws, const SensitivityParameter* h, bool applyConstraints) const;
  /// The constraint rows (a·u − b, or u − v) at the values `x`; `withOffsets` false drops b
  /// and v, which gives the rows' derivative a·du when `x` is a direction du.
  void addConstraintRows(const HostView& x, Workset& ws, bool withOffsets = true) const;
  void addTractions(Workset& ws, bool applyConstraints = true) const;
  /// Empty when `kernels` own every component of the fields exactly once, else why not.
  std::string checkKernels(const std::vector<std::shared_ptr<const CellKernel>>& kernels) const;
  Workset workset(const Vector& xOverlap, const Vector* dxOverlap, Vector* fOverlap, FECrsMatrix* jacobian) const;

  /// An owned wall node, its overlap index and the overlap dofs of its stencil (−1: none).
  struct WallNodeRef {
    int wall, k;
    LO node;
    LO dofs[ContactWall::kNodeStencilSize];
  };

  const Mesh& m_mesh;
  const DofMap& m_dofMap;
  const BoundaryConditions& m_bcs;
  FlowPhysics m_physics;
  std::vector<std::shared_ptr<const CellKernel>> m_kernels;
  std::string m_kernelError;  ///< why m_kernels do not own every component once (empty: they do)
  std::vector<char> m_prescribedDof;                  ///< per overlap dof (empty: none prescribed)
  std::vector<std::pair<LO, double>> m_prescribedRows;  ///< owned (dof, value): rows x − value
  std::vector<ThermalBoundaryConditions::TransferEdge> m_transferEdges;
  std::vector<double> m_frictionHeat;  ///< β per wall (empty: no friction heat)
  int m_frictionHeatComponent = -1;
  int m_transferComponent = -1;
  const std::vector<ContactWall>* m_walls = nullptr;
  std::vector<WallNodeRef> m_wallNodes;
  Teuchos::RCP<Vector> m_xOverlap;   ///< scratch: x imported to the overlap map
  Teuchos::RCP<Vector> m_fOverlap;   ///< scratch: residual before the export to owned rows
  Teuchos::RCP<Vector> m_dxOverlap;  ///< scratch: a direction imported to the overlap map
};

}  // namespace flowform
