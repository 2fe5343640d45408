// Scalar and index types shared by every part of flowform. Light on purpose: no Tpetra
// headers here (TpetraTypes.hpp has those), so the element kernels compile fast.
#pragma once

namespace flowform {

using LO = int;        ///< local (per-rank) index, Tpetra's LocalOrdinal
using GO = long long;  ///< global index, Tpetra's GlobalOrdinal (Debian instantiates <int,long long>)

/// The unknown fields of the flow problem: velocity (u_x, u_y) and pressure p. Which nodes
/// carry which field, and where a field's dof sits, is the element layout's business
/// (discretization/ElementLayout.hpp) and the DofMap's, never a hard-wired stride.
enum DofComponent : int { kUx = 0, kUy = 1, kP = 2 };
constexpr int kNumFields = 3;

/// Two-dimensional models (docs/theory.md §1).
enum class Geometry { PlaneStrain, Axisymmetric };

}  // namespace flowform
