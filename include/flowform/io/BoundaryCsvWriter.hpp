// One CSV per named boundary curve: arc length, position, tangential and normal velocity,
// pressure, and any further nodal scalars (contact status, sensitivities) by name.
#pragma once

#include <string>

#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/io/FieldSet.hpp"

namespace flowform {

/// Writes `outDir`/boundary_<curve.name>.csv with columns
/// s,x,y,u_t,u_n,p[,<scalar nodal fields other than velocity and pressure>...].
/// The curve runs with the material on its left: the tangent is t = (-n_y, n_x) for the
/// outward normal n, and s grows along t. u_t = u·t; u_n = u·n is positive when the flow
/// leaves the material.
/// `fields` must hold a nodal "velocity" (2 components) and "pressure" (1 component).
/// Further nodal fields follow in their FieldSet order, a 2-component one as
/// <name>_x,<name>_y (or, when the field names them, as its tangential and normal
/// components under those names, e.g. du_t_dnu, du_n_dnu); cell fields are not written. One row per curve node in curve order
/// (a closed curve does not repeat its first node). Numbers are in the shortest form that
/// reads back to the same double; NaN/Inf as nan/inf. The file is written under a .tmp
/// name and renamed into place, replacing an existing one.
/// Throws std::invalid_argument (before writing) when velocity or pressure is missing, a
/// nodal field has the wrong size or component count, or the curve's arrays disagree or
/// hold a node id outside the mesh; std::runtime_error naming the file on I/O failure.
void writeBoundaryCsv(const std::string& outDir, const Mesh& mesh, const BoundaryCurve& curve,
                      const FieldSet& fields);

}  // namespace flowform
