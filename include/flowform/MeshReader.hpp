// Reading a mesh through gmsh's API: .msh (v4) files, or .geo files meshed on the fly.
// Rank 0 reads; the mesh (or the input error) is broadcast, so every rank fails alike.
#pragma once

#include <string>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include "flowform/Mesh.hpp"

namespace flowform {

/// The "Mesh" sublist: File, Element Type, Size Factor, Uniform Refinements, and the
/// "Geo Parameters" sublist (numbers passed to a .geo's DefineConstant through onelab).
Teuchos::RCP<const Teuchos::ParameterList> validMeshParameters();

/// Reads the mesh the validated "Mesh" sublist names. A relative File is taken relative to
/// `baseDir` (the directory of the case XML). Throws InputError for a missing or unreadable
/// file, an element type other than the one asked, no 2-D cells, an inverted or degenerate
/// cell (its index and gmsh tag named), or a mesh that mixes triangles and quadrilaterals.
/// Cells are returned counter-clockwise.
Mesh readMesh(const Teuchos::ParameterList& meshParams, const std::string& baseDir,
              const Teuchos::Comm<int>& comm);

}  // namespace flowform
