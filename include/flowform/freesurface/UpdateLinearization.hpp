// The free-surface update linearized at a converged state (docs/theory.md §3.5): the surface
// unknowns b (the spine coordinates of the nodes the update places on streamlines: one per node
// for spines, x and y for arc length), the flow's response to them Y = dq/db = −K_t⁻¹ ∂R/∂X E,
// and the Jacobian of the map b ↦ U(q(b), X(b)),
//     G = ∂U/∂b + U_q Y.
// ∂R/∂X E, ∂U/∂b (and ∂φ/∂b for the responses) are central differences in the node positions:
// each unknown moved by ±10⁻⁶ × the surface length (±10⁻⁹ for an attachment point, which slides a
// contact wall's nodes), the interior following by the harmonic extension E (factored once);
// with a Rigid Inflow in the state, its speed follows the unknowns (Y_j += dU_j g). A moving
// tool's nodes slid by an attachment point carry the tool's velocity with them (the differences
// are taken at q + εQ, Q the tool's velocity change at the moved nodes, and Y is dq/db − Q, which
// leaves every total derivative unchanged and avoids the penalty's stiff response). U_q and φ_q
// along a direction are central differences in q. The flow part uses the factors of K_t at the
// state (one back-substitution per unknown); contact statuses and penalty scales are held. Used
// by the total shape derivative (ShapeDerivative) and by the Newton step on the positions of the
// free-surface loop.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <Teuchos_SerialDenseMatrix.hpp>

#include "flowform/responses/Responses.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/freesurface/FreeSurface.hpp"
#include "flowform/solvers/FlowModel.hpp"

namespace flowform {

/// What the linearization reads and moves of a converged state (problem/Problem gives its own:
/// Problem::linearizationState): the current mesh, moved through `moveNodes` (which refreshes
/// what caches geometry and drops the factors) and restored, the model whose factors it leaves
/// at the state, and the solution it linearizes at.
struct SurfaceLinearizationState {
  const Mesh& mesh;
  const DofMap& dofMap;
  Geometry geometry;
  const FreeSurfaces& surfaces;
  const std::vector<ContactWall>& walls;
  FlowModel& model;
  const Responses& responses;
  const Vector& solution;
  std::function<void(const std::vector<std::array<double, 2>>&)> moveNodes;
  /// A Rigid Inflow whose speed U the flow's response carries (the total shape derivative; empty
  /// for the loop's own Newton step, which holds U): its force F from the unconstrained residual
  /// (on the current mesh), −∂f/∂U, and dF along dq at the state. Then Y_j = y_j + dU_j g with
  /// K g = −∂f/∂U and dU_j = −(∂F/∂b_j + dF(y_j)) / dF(g), the bordered system of docs/rolling.md.
  std::function<double(const Vector&)> inflowForce{};
  Teuchos::RCP<const Vector> minusDfDU{};
  std::function<double(const Vector&)> inflowForceTangent{};
};

class UpdateLinearization {
 public:
  /// Linearizes at the state's solution and mesh (the mesh is moved and restored; the
  /// factors of K_t at the state are left in the model). With `responses`, also ∂φ/∂b + φ_q Y
  /// for every response. failure() says why when it cannot be made.
  UpdateLinearization(const SurfaceLinearizationState& state, bool responses);

  const std::string& failure() const { return m_failure; }
  int size() const { return static_cast<int>(m_unknowns.size()); }
  /// The plain update at the state.
  const FreeSurfaceStep& step() const { return m_step; }
  /// The spectral radius of G (power iteration): the plain update's contraction per step.
  double spectralRadius() const { return m_spectralRadius; }
  /// U_q d (per unknown) by central differences along d (a dof vector on the owned map).
  std::vector<double> updateAlong(const Vector& d) const;
  /// The change of the update's residual (where it puts each unknown's node, less where the node
  /// is) when the whole mesh moves along V (a shape parameter's motion, GeoParameterMotion) at the
  /// state's q: central differences at X ± εV; the mesh is put back.
  std::vector<double> residualAlongMotion(const std::vector<std::array<double, 2>>& V) const;
  /// dφ/db_j = ∂φ/∂b_j + φ_q Y_j of response `name` (with `responses` only).
  double responseShape(int j, const std::string& name) const { return m_phiB[j].at(name) + m_phiQ[j].at(name); }
  /// X = (I − G)⁻¹ B (columns); false when I − G is singular.
  bool solve(const Teuchos::SerialDenseMatrix<int, double>& B, Teuchos::SerialDenseMatrix<int, double>& X) const;
  /// One Newton step on the positions: per move of step(), the displacement δ = (I − G)⁻¹ r on the
  /// unknowns (r the plain update's residual), the plain residual on the other moves.
  bool newtonMoves(std::vector<std::array<double, 2>>& moves) const;

 private:
  struct Unknown {
    size_t move;                     ///< index into step().moves
    std::array<double, 2> direction;  ///< unit direction the unknown moves the node in
  };
  /// U along the unknowns at x on the current mesh.
  std::vector<double> updateAt(const Vector& x) const;
  /// `reactions`: the unconstrained residual at x on the current mesh, when already assembled.
  std::map<std::string, double> responsesAt(const Vector& x, const Vector* reactions = nullptr) const;

  SurfaceLinearizationState m_at;  ///< the state linearized at
  std::string m_failure;
  FreeSurfaceStep m_step;
  std::vector<Unknown> m_unknowns;
  Teuchos::RCP<Vector> m_state;
  Teuchos::SerialDenseMatrix<int, double> m_G;
  std::vector<std::map<std::string, double>> m_phiB, m_phiQ;
  double m_spectralRadius = 0.0;
};

}  // namespace flowform
