// solution.h5 + solution.xdmf: the mesh and its fields in a form ParaView opens (XDMF 3,
// heavy data in HDF5). Called on one rank with gathered fields.
#pragma once

#include <string>

#include "flowform/mesh/Mesh.hpp"
#include "flowform/io/FieldSet.hpp"

namespace flowform {

/// Writes `outDir`/`baseName`.h5 and `outDir`/`baseName`.xdmf, replacing existing files
/// (each is written under a .tmp name and renamed into place). `outDir` must exist.
///
/// HDF5 layout: /mesh/coordinates float64 [nodes x 3] (x, y, 0); /mesh/topology int64
/// [cells x nodesPerCell] from Mesh::cellNodes; /fields/<name> float64 [n] for
/// 1-component fields, [n x 3] (x, y, 0) for 2-component ones, n = nodes or cells. The
/// XDMF 3 file has one Uniform grid (Triangle or Quadrilateral topology, XYZ geometry)
/// with an Attribute per field (Scalar/Vector, Center Node/Cell) and names the .h5
/// relative to itself.
///
/// Throws std::invalid_argument, before any file is touched, when a field has a size
/// other than count x components, components other than 1 or 2, an empty name or one
/// with '/', or a name used twice (nodal and cell fields share one namespace), and when
/// the mesh has no cells or a cell node id out of range. Throws std::runtime_error naming
/// the file when HDF5 or the file system fails.
void writeXdmf(const std::string& outDir, const std::string& baseName, const Mesh& mesh,
               const FieldSet& fields);

}  // namespace flowform
