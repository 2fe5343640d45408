// Scalar and index types shared by every part of flowform. Light on purpose: no Tpetra
// headers here (TpetraTypes.hpp has those), so the element kernels compile fast.
#pragma once

namespace flowform {

using LO = int;        ///< local (per-rank) index, Tpetra's LocalOrdinal
using GO = long long;  ///< global index, Tpetra's GlobalOrdinal (Debian instantiates <int,long long>)

/// The node components of the flow's fields: velocity (u_x, u_y) and pressure p. The flow's
/// fields are registered first (discretization/FieldRegistry.hpp), so these are their
/// components in every case; a case may add fields after them. Which nodes carry which
/// field, and where a field's dof sits, is the element layout's business
/// (discretization/ElementLayout.hpp) and the DofMap's, never a hard-wired stride.
enum DofComponent : int { kUx = 0, kUy = 1, kP = 2 };
/// Components the flow kernel reads and owns at a node (its element vector's stride).
constexpr int kNumFlowComponents = 3;

/// Two-dimensional models (docs/theory.md §1).
enum class Geometry { PlaneStrain, Axisymmetric };

}  // namespace flowform
