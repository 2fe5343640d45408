// Reading a mesh through gmsh's API: .msh (v4) files, or .geo files meshed on the fly.
// Rank 0 reads; the mesh (or the input error) is broadcast, so every rank fails alike.
#pragma once

#include <string>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include "flowform/mesh/Mesh.hpp"
#include "flowform/mesh/SizeField.hpp"

namespace flowform {

/// The "Mesh" sublist: File, Element Type, Size Factor, Uniform Refinements, Verbose (gmsh's
/// log on rank 0), and the "Geo Parameters" sublist (numbers passed to a .geo's
/// DefineConstant through onelab).
///
/// Geo Parameters: before the .geo is parsed, each entry NAME = v (double, or int) becomes
/// gmsh::onelab::setNumber("Parameters/NAME", {v}); the .geo picks it up with
///     DefineConstant[ NAME = {default, Name "Parameters/NAME"} ];
/// (checked with gmsh 4.8.4; a DefineConstant without that Name does not see it). After
/// parsing, a NAME that no DefineConstant claimed is an InputError listing the names the .geo
/// does define. Geo Parameters and a Size Factor other than 1 are an InputError for a .msh.
///
/// "Geo Parameters" accepts any entry names: the sublist is marked
/// disableRecursiveValidation(). Embed this list with set("Mesh", *validMeshParameters()),
/// which keeps that mark; sublist("Mesh").setParameters(...) drops it.
Teuchos::RCP<const Teuchos::ParameterList> validMeshParameters();

/// Reads the mesh the validated "Mesh" sublist names. A relative File is taken relative to
/// `baseDir` (the directory of the case XML). Throws InputError for a missing or unreadable
/// file, an element type other than the one asked, no 2-D cells, an inverted or degenerate
/// cell (its index and gmsh tag named), or a mesh that mixes triangles and quadrilaterals.
/// Cells are returned counter-clockwise.
///
/// What the Mesh holds: when the file has 2-D physical groups, the cells of those groups
/// (what gmsh itself would save), otherwise every 2-D cell; only the nodes those cells use,
/// numbered 0.. in increasing gmsh node tag; every 1-D physical group as a BoundaryGroup and
/// every 2-D one as a RegionGroup, in gmsh's order, unnamed ones called "group<tag>". A
/// surface whose cells are all clockwise (drawn clockwise) is turned round; a cell whose
/// orientation disagrees with most cells of its gmsh surface is an inverted cell.
/// A .geo asked for quadrilaterals is meshed with Mesh.RecombineAll = 1 (Blossom); if
/// triangles remain, that is an InputError suggesting Mesh.SubdivisionAlgorithm = 1.
/// `sizeField` (a .geo only): mesh with the sizes it gives instead of the .geo's own (SizeField.hpp).
/// Collective: every rank of `comm` must call it.
Mesh readMesh(const Teuchos::ParameterList& meshParams, const std::string& baseDir,
              const Teuchos::Comm<int>& comm, const SizeField* sizeField = nullptr);

}  // namespace flowform
