// A named boundary group ordered into a curve: the nodes in sequence, their arc length,
// and outward unit normals (pointing out of the material). Used by symmetry conditions
// (the normal), contact walls (nodal normals, segment lengths) and the boundary CSV output.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "flowform/mesh/Mesh.hpp"

namespace flowform {

struct BoundaryCurve {
  std::string name;
  /// Node ids in order along the curve, which runs with the material on its left
  /// (counter-clockwise): the tangent at a node is t = (-n_y, n_x).
  std::vector<GO> nodes;
  std::vector<double> arcLength;                ///< s at each node, s(nodes[0]) = 0
  std::vector<std::array<double, 2>> normals;   ///< outward unit normal at each node
  /// Segments between consecutive nodes: segment k joins nodes[k] and nodes[k+1]
  /// (for a closed curve the last segment joins the last node and nodes[0]).
  std::vector<double> segmentLength;
  std::vector<std::array<double, 2>> segmentNormals;  ///< outward unit normal per segment
  bool closed = false;

  /// True when every segment normal equals the first within `tolerance` (radians).
  bool isStraight(double tolerance = 1e-8) const;
};

/// Orders the edges of `group` into one curve. The nodal normal at a node where two segments
/// meet is the normalized sum of the two segment normals (the bisector; at a corner of a
/// straight-sided domain it points diagonally out). InputError when the group is empty,
/// branched, made of several pieces, has a zero-length segment, or has an edge that is not
/// on the mesh boundary.
BoundaryCurve buildBoundaryCurve(const Mesh& mesh, const BoundaryGroup& group);

/// Which ends of `curve` are nodes of `group`'s edges. A contact wall's or a free surface's
/// upstream end is the one it shares with its Start Group.
struct CurveEnds {
  bool first = false, last = false;
};
CurveEnds endsOn(const BoundaryCurve& curve, const BoundaryGroup& group);

}  // namespace flowform
