// Boundary conditions by gmsh physical-group name (docs/theory.md §2, first bullet):
//   Velocity   — one or both components prescribed ("Velocity X", "Velocity Y"), or the velocity
//                parallel to a straight group ("Parallel To": u·n = 0, n its normal as made)
//   Symmetry   — zero normal velocity on a straight boundary of any orientation
//   Traction   — a given traction vector t̄ ("Traction X", "Traction Y"; default 0 = free)
// Contact Wall and Free Surface groups are validated and handled elsewhere (contact/,
// freesurface/); here they are skipped (a free surface is traction-free).
// A traction given on a Velocity or Symmetry group loads its free component (a mixed
// condition, e.g. u_y = 0 with a normal traction at a channel inlet).
// Groups the case does not name are traction-free.
//
// Velocity and symmetry conditions are linear constraints a·u_i = b on the velocity of a
// node i. At a node with one constraint, the momentum row of the component where |a_c| is
// largest is replaced by the constraint, and the other row by the tangential momentum
// equation t·R_i (t ⊥ a): the constraint acts in the node's own frame, so an inclined
// symmetry line needs no change of unknowns. Two independent constraints fix both
// components. The element-level part (zeroing and rotating rows) is applyConstraintRows();
// the owner of the node adds the constraint rows once (Assembler).
#pragma once

#include <array>
#include <map>
#include <string>
#include <unordered_set>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/core/Types.hpp"

namespace flowform {

/// The edges of this rank's cells, for the boundary terms assembled edge by edge (tractions, heat
/// transfer): a boundary edge has one cell, so each is assembled once over the ranks.
class RankEdges {
 public:
  RankEdges(const Mesh& mesh, const DofMap& dofMap);
  bool contains(const std::array<GO, 2>& edge) const;

 private:
  GO m_numNodes;
  std::unordered_set<GO> m_keys;  ///< min(a, b) × numNodes + max(a, b)
};

struct NodeConstraint {
  enum class Kind { None, Single, Full };
  Kind kind = Kind::None;
  double a[2] = {0.0, 0.0};      ///< Single: unit constraint direction
  double b = 0.0;                ///< Single: a·u = b
  int constrainedRow = kUx;      ///< Single: row (component) replaced by the constraint
  double t[2] = {0.0, 0.0};      ///< Single: tangent whose momentum equation stays
  double value[2] = {0.0, 0.0};  ///< Full: the prescribed velocity
};

/// A boundary edge carrying a prescribed traction, assembled by the rank whose cell has it.
struct TractionEdge {
  LO nodes[2];  ///< overlap-local node indices
  double traction[2];
};

/// Element-level part of the constraints: in the node's two momentum rows R = (R_x, R_y),
/// Single → R_c := 0, R_o := t·R; Full → both := 0. Linear, so it commutes with assembly.
template <typename Scalar>
void applyConstraintRows(const NodeConstraint& nc, Scalar* nodeResidual) {
  if (nc.kind == NodeConstraint::Kind::None) return;
  if (nc.kind == NodeConstraint::Kind::Full) {
    nodeResidual[kUx] = 0.0;
    nodeResidual[kUy] = 0.0;
    return;
  }
  const Scalar tangential = nc.t[0] * nodeResidual[kUx] + nc.t[1] * nodeResidual[kUy];
  nodeResidual[nc.constrainedRow] = 0.0;
  nodeResidual[1 - nc.constrainedRow] = tangential;
}

/// A group that moves as one rigid body at an unknown speed (the "Rigid Inflow" entry): u = U d on
/// its nodes, U found by the solve from the force balance d·Σ_i R_i = 0 (R_i the unconstrained
/// residual, which holds the group's traction load; Problem::balanceRigidInflow).
struct RigidInflow {
  std::string group;  ///< empty: the case has none
  std::array<double, 2> direction{1.0, 0.0};
  double speed = 0.0;  ///< U, the current speed
};

class BoundaryConditions {
 public:
  /// The valid entries of one group's sublist (Type, Velocity X/Y, Traction X/Y).
  static Teuchos::RCP<const Teuchos::ParameterList> validGroupParameters();

  /// `bcList` is the "Boundary Conditions" sublist: one sublist per group name. Throws
  /// InputError for an unknown group (naming the groups the mesh has), an unknown type,
  /// a velocity group with no component, a curved symmetry group, or conflicting
  /// constraints at a node (naming both groups).
  BoundaryConditions(const Teuchos::ParameterList& bcList, const Mesh& mesh, const DofMap& dofMap);

  /// Constraint of every overlap node.
  const std::vector<NodeConstraint>& constraints() const { return m_constraints; }
  const std::vector<TractionEdge>& tractionEdges() const { return m_tractionEdges; }

  /// Recomputes what depends on the node positions (the directions of symmetry
  /// constraints) after the mesh's nodes moved; InputError if a Symmetry group is no longer
  /// straight.
  void refreshGeometry(const Mesh& mesh);
  /// The directions that `Parallel To` takes from a tool's face (fixed as made, so that the
  /// free-surface loop's moves of a released wall do not turn them) taken again from `made`, the
  /// mesh as made moved by a shape parameter (Problem::moveShape); refreshGeometry applies them.
  void setToolShape(const Mesh& made);

  /// Sets entry `entry` (a number: Velocity X, Velocity Y, ...) of group `group`'s condition to
  /// `value` and rebuilds the constraints (a boundary value's sensitivity and its check).
  void setGroupValue(const Mesh& mesh, const std::string& group, const std::string& entry, double value);

  /// Releases the groups marked "Release After Free Surfaces" (they become traction-free, their
  /// tractions kept); false when there are none.
  bool releaseHeld(const Mesh& mesh);
  /// The groups marked "Release After Free Surfaces" and not yet released.
  const std::vector<std::string>& heldGroups() const { return m_held; }
  /// The groups releaseHeld released (empty before).
  const std::vector<std::string>& releasedGroups() const { return m_released; }

  /// The case's rigid inflow (group empty when there is none), and its speed changed: the
  /// group's prescribed velocity becomes speed × direction (impose it on the solution next).
  const RigidInflow& rigidInflow() const { return m_rigidInflow; }
  void setRigidInflowSpeed(const Mesh& mesh, double speed);

  /// Sets the constrained components of an owned solution vector so that a·u = b holds
  /// (the initial guess then satisfies every constraint, and Newton keeps it so).
  /// `homogeneous`: the constraints with zero data (a·u = 0, u = 0), for test-space vectors.
  void imposeOnSolution(Vector& xOwned, bool homogeneous = false) const;

 private:
  void build(const Mesh& mesh);

  Teuchos::ParameterList m_bcList;
  const DofMap& m_dofMap;
  std::vector<NodeConstraint> m_constraints;
  std::vector<TractionEdge> m_tractionEdges;
  /// The normals of the groups named by Parallel To, taken from the mesh as first built: a tool
  /// face is rigid, while free-surface updates may move its released nodes off it.
  std::map<std::string, std::array<double, 2>> m_faceNormals;
  std::vector<std::string> m_held, m_released;
  RigidInflow m_rigidInflow;
};

}  // namespace flowform
