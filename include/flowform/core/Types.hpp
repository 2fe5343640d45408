// Scalar and index types shared by every part of flowform. Light on purpose: no Tpetra
// headers here (TpetraTypes.hpp has those), so the element kernels compile fast.
#pragma once

namespace flowform {

using LO = int;        ///< local (per-rank) index, Tpetra's LocalOrdinal
using GO = long long;  ///< global index, Tpetra's GlobalOrdinal (Debian instantiates <int,long long>)

/// Unknowns per mesh node: velocity (u_x, u_y) and pressure p, equal order.
constexpr int kDofsPerNode = 3;
enum DofComponent : int { kUx = 0, kUy = 1, kP = 2 };

/// Two-dimensional models (SPEC §1).
enum class Geometry { PlaneStrain, Axisymmetric };

}  // namespace flowform
