// Carrying a dof vector from one mesh to another (a uniformly refined copy for the two-level
// error estimate, a remeshed domain in the adaptive loop): every node of the target mesh is
// located in the source mesh (PointLocator) and each field is interpolated there with the
// source cell's own shape functions, so a P1/Q1 field on a nested refinement carries over
// exactly.
#pragma once

#include <array>
#include <vector>

#include "flowform/core/TpetraTypes.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// Every dof of `x` (owned map) on every rank, indexed by global dof id. Collective.
std::vector<double> replicate(const Vector& x, const DofMap& dofMap);

/// `toOwned` (on `toDofs`' owned map) = the field `fromValues` (replicated, from replicate())
/// of mesh `fromMesh` interpolated at the nodes of `toMesh`. Both dof maps must carry the same
/// fields at every node. Not collective.
void interpolate(const Mesh& fromMesh, const DofMap& fromDofs, const std::vector<double>& fromValues,
                 const Mesh& toMesh, const DofMap& toDofs, Vector& toOwned);

/// The nodes of `toMesh` (a mesh of the same domain as `fromMade`: a refined copy, a remeshed
/// one) moved as `fromMade`'s nodes moved to `fromMoved` (the same mesh after free-surface
/// updates): each node is located in `fromMade` and placed at the same shape-function weights
/// in the moved cell, x' = Σ_a N_a(x) x'_a. On a nested refinement the refined free surfaces
/// then lie on the moved ones exactly, so a field interpolated afterwards carries over exactly
/// too. Not collective (the meshes are replicated).
std::vector<std::array<double, 2>> carryShape(const Mesh& fromMade, const Mesh& fromMoved, const Mesh& toMesh);

}  // namespace flowform
