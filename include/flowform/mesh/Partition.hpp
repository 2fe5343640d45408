// Which rank assembles which cell, and which rank owns which node.
#pragma once

#include <vector>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// Part (0..numParts-1) of every cell: METIS k-way on the dual graph of the mesh (cells that
/// share an edge are neighbours) when numParts > 1, all zeros otherwise. Deterministic, so
/// every rank computes the same answer without communication.
std::vector<int> partitionCells(const Mesh& mesh, int numParts);

/// Owner rank of every node: the lowest part among the cells that touch it.
std::vector<int> nodeOwners(const Mesh& mesh, const std::vector<int>& cellPart);

}  // namespace flowform
