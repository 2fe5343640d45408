// A mesh of one shape on the topology of another (docs/optimization.md §2): Mesh/Reference Geo
// Parameters names the .geo values whose mesh gives the topology; the nodes are then moved to
// the shape at Mesh/Geo Parameters. Each boundary group's nodes keep their fraction of the arc
// length between the group's corners (nodes where it turns by more than kCornerAngle) along the
// group meshed at the target values; the interior follows by the harmonic extension
// (MeshMotion). The map from the target values to the node positions is then smooth — a shape
// optimizer (optimization/) sees a response that varies smoothly with the design, not gmsh's
// re-triangulation from design to design — and the shape derivative's mesh velocity
// (sensitivity/GeoParameterMotion) is measured on the same map.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include "flowform/mesh/Mesh.hpp"
#include "flowform/mesh/SizeField.hpp"

namespace flowform {

/// A boundary curve turning by more than this at a node has a corner there (degrees).
constexpr double kCornerAngle = 20.0;

/// The Mesh sublist that names the reference's values.
constexpr const char* kReferenceGeoParameters = "Reference Geo Parameters";

/// Whether `meshParams` (a case's Mesh sublist) asks for a reference topology (a non-empty
/// Reference Geo Parameters).
bool hasReferenceTopology(const Teuchos::ParameterList& meshParams);

/// readMesh, or with Mesh/Reference Geo Parameters the reference's mesh moved to the shape at
/// Geo Parameters (InputError naming the group whose corners or ends do not match). Collective.
Mesh readMeshOnReference(const Teuchos::ParameterList& meshParams, const std::string& baseDir,
                         const Teuchos::Comm<int>& comm, const SizeField* sizeField = nullptr);

/// The nodes of `reference` moved onto the boundary groups of `target` (same group names) by arc
/// length between corners, the interior by the harmonic extension.
std::vector<std::array<double, 2>> followShape(const Mesh& reference, const Mesh& target);

}  // namespace flowform
