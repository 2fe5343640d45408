// Free surfaces that become streamlines (docs/theory.md §3, paper §2.1): a boundary part with
// zero traction on which the converged flow must satisfy u·n = 0.
//
// Two kinds, both with a fixed start:
//   - a "Free Surface" group (e.g. the jet after a die exit): its nodes from the end it shares
//     with its Start Group (the die wall), which stays put;
//   - a contact wall whose "Released Nodes" are "Free Surface" (the die land): every run of its
//     free nodes starts at the node before it (the separation point, the last node in contact,
//     or the wall's upstream end, shared with its Start Group) and follows the contact status.
//     The tool stays where it is: a node that would enter it is put back on it (gap 0), where
//     the status loop may activate it; an active node that a separated run passes below is
//     released.
//
// The update (spines): each surface node keeps its coordinate a along the chord direction c of
// the surface as made (start → end), and its coordinate b along the outward normal m ⊥ c is
// integrated from the start so that every segment is parallel to the mean velocity ū of its
// two nodes:  b_{k+1} = b_k + (a_{k+1} − a_k) (ū·m)/(ū·c), a_k where node k is (the update moves
// it along m only; a refined run that starts from a coarse run's surface may have it elsewhere).
// With P1/Q1 velocities linear along a straight segment, the volume flux through segment k is
// L_k ū_k·n_k (ū weighted by r in axisymmetry: ū = (u_a(2r_a + r_b) + u_b(r_a + 2r_b)) /
// (3(r_a + r_b))), so at a fixed point of the update no material crosses the surface: the
// measure of convergence is max_k |ū_k·n_k| / |ū_k| (the sine of the angle between the flow
// and the surface).
// The node at the downstream end drags the straight group that ends there (the outlet): its
// nodes move by the same displacement times their arc-length fraction from their other end.
//
// A surface that lands on a tool (the strip's surface before a roll): where the group at the
// downstream end is a contact wall, the end node is the attachment point. It slides along the
// tool's surface (the roll's circle about its Rotation Centre, or a straight wall's line) to where
// the streamline from the node before it meets the tool, so that the last segment is a streamline
// too; the wall's other nodes slide with it by their arc-length fraction from the wall's far end
// (they stay on the tool; the far end stays put). The contact statuses of the wall's nodes stay
// the contact loop's.
//
// Arc length (a surface that turns: a chip's back): x_{k+1} = x_k + λ L_k ū_k/|ū_k| from the fixed
// start, L_k the segment lengths as made and λ the one factor that puts the last node on the line
// of the straight group at the end (the chip's outlet stays where it was made; without the factor
// the surface's length would be fixed and its end would leave the outlet's line as the chip's
// corner moves).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/contact/ContactWall.hpp"
#include "flowform/core/Types.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// One update of every free surface from the current velocity field.
struct FreeSurfaceStep {
  /// Per mesh node: the displacement the update gives to surface nodes and to the nodes of the
  /// groups they drag (zero elsewhere; the mesh motion spreads it to the interior): ω times the
  /// residual (relax(ω); the step comes with ω = 1).
  std::vector<std::array<double, 2>> displacement;
  std::vector<char> prescribed;     ///< per mesh node: its displacement is boundary data
  /// A surface node's move: where the update puts it minus where it is (a vector: along the
  /// spine normal for spines, any direction for arc length), how far along `normal` it may go
  /// before its tool (spines on a wall; +∞ otherwise), whether the update placed it on a
  /// streamline (not a start, not on the tool: the unknowns of the surface's fixed point), and the
  /// directions it can move in (spines: the normal; arc length: x and y).
  /// A node that slides along a tool's surface (a surface's attachment point and the wall nodes it
  /// drags): rotated about `centre` (a circle; positive moves turn from `at` towards `tangent`) or
  /// moved along `tangent` (a straight tool). `at`: the node's position when the step was made.
  struct Slide {
    bool on = false;
    bool circle = false;
    std::array<double, 2> centre{}, at{}, tangent{};
    /// The displacement that moves the node by `amount` along the tool (an arc length on a circle).
    std::array<double, 2> displacement(double amount) const;
  };
  struct Move {
    GO node;
    std::array<double, 2> normal;  ///< the spine normal; a sliding node: its unit tangent along the tool
    std::array<double, 2> residual;
    double room;
    bool integrated;
    bool arcLength;
    Slide slide{};
    std::vector<std::array<double, 2>> directions() const {
      if (arcLength) return {{1.0, 0.0}, {0.0, 1.0}};
      return {normal};
    }
  };
  /// A node of a group dragged by a surface's end (moves[end]), by its arc-length fraction from the
  /// group's other end; where both ends move, the two drags add up.
  struct Drag {
    GO node;
    double fraction;
    size_t end;
    Slide slide{};  ///< a wall node dragged along its tool by an attachment point (fraction of its slide)
  };
  std::vector<Move> moves;
  std::vector<Drag> drags;
  /// Sets the displacements to ω times the residuals (no node past its tool).
  void relax(double omega);
  /// Sets the displacements to the given move of each entry of `moves` (no node past its tool;
  /// the dragged groups follow their surfaces' ends).
  void setMoves(const std::vector<std::array<double, 2>>& perMove);
  double maxFlowAngle = 0.0;        ///< max over surface segments of |ū·n|/|ū| at the current positions
  std::array<double, 2> worstSegment{};  ///< the midpoint of the segment where it is
  void noteFlowAngle(double angle, const std::array<double, 2>& a, const std::array<double, 2>& b) {
    if (!(angle <= maxFlowAngle)) {
      maxFlowAngle = angle;
      worstSegment = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
    }
  }
  double maxMove = 0.0;             ///< largest |residual|: the move of the plain (unrelaxed) update
  std::array<double, 2> largestMoveAt{};  ///< the node that has it (where it is now)
  void noteMove(double move, const std::array<double, 2>& at) {
    if (!(move <= maxMove)) {
      maxMove = move;
      largestMoveAt = at;
    }
  }
  std::vector<double> residual;     ///< the moves' residuals along their directions, in order (Aitken's vector)
  int clampedToTool = 0;            ///< free wall nodes the update put back on their tool
  /// Active wall nodes that a separated surface does not reach (its streamline passes below the
  /// tool there by more than the gap tolerance): they are released, as {wall, wall node}.
  std::vector<std::array<int, 2>> released;
  std::string failure;              ///< why no update is possible (the flow turns against the surface)
};

class FreeSurfaces {
 public:
  /// The case's free surfaces: every "Free Surface" group of `bcList` and every wall whose
  /// Released Nodes are Free Surface (its released runs). InputError for a start group that does not share an
  /// end with its surface, or a surface not made of one open curve.
  FreeSurfaces(const Teuchos::ParameterList& bcList, const Mesh& mesh, const std::vector<ContactWall>& walls);

  bool empty() const { return m_surfaces.empty(); }
  /// Chord length of the longest surface: the length scale of the node-move tolerance.
  double lengthScale() const { return m_lengthScale; }

  /// The update at the velocities `u` (replicated, global dof ids: SolutionTransfer replicate()).
  /// On a wall, active nodes stay on the tool and each run of free nodes follows the streamline
  /// from the node before it (the separation point); a node whose streamline enters the tool is
  /// put back on it.
  /// `gapTolerance`: how far below the tool a separated streamline may pass an active node
  /// before the node is released (a length).
  FreeSurfaceStep step(const Mesh& mesh, const DofMap& dofMap, const std::vector<double>& u,
                       const std::vector<ContactWall>& walls, Geometry geometry, double gapTolerance) const;

  /// Per surface: its name, nodes from its start (a wall: all its nodes in flow order).
  struct Surface {
    std::string name;
    std::vector<GO> nodes;       ///< from the fixed start to the downstream end
    int wall = -1;               ///< index of the contact wall whose released runs these are, or −1
    std::vector<int> wallIndex;  ///< a wall: the wall node of nodes[k]
    std::array<double, 2> origin{}, chord{}, normal{};  ///< x_0, c, m (outward)
    std::vector<double> along;   ///< a_k, fixed
    std::vector<double> tool;    ///< a wall: b_k of the tool (as made); its nodes stay at b ≤ tool
    bool arcLength = false;      ///< Update = Arc Length (else spines)
    std::vector<double> segmentLength;  ///< as made: kept (up to one common factor) by the arc-length update
    /// Arc length with a straight group at the end: the line through it (as made), on which the
    /// surface's last node stays (a point of it and its unit normal).
    bool endOnLine = false;
    std::array<double, 2> endLinePoint{}, endLineNormal{};
    std::vector<GO> dragged;     ///< the nodes of the straight group at the downstream end
    std::vector<double> dragFraction;  ///< their arc-length fraction from the group's other end
    /// A contact wall at the downstream end (the attachment point slides along its tool), or −1;
    /// then `dragged` are its other nodes from the end node on (without the far end).
    int endWall = -1;
  };
  const std::vector<Surface>& surfaces() const { return m_surfaces; }

 private:
  /// The arc-length update of one surface into `out`; false (out.failure set) where the flow stands.
  bool arcLengthStep(const Surface& s, const Mesh& mesh, const std::function<std::array<double, 2>(GO)>& velocity,
                     Geometry geometry, FreeSurfaceStep& out) const;
  /// The attachment point of a spine surface with an end wall into out.moves (its slide along the
  /// tool to where the streamline from `before`, the node before it as updated, meets the tool) and
  /// the wall's dragged nodes into out.drags; false (out.failure set) where it does not meet it.
  bool attachmentStep(const Surface& s, const Mesh& mesh, const std::vector<ContactWall>& walls,
                      const std::array<double, 2>& before, const std::array<double, 2>& flow, FreeSurfaceStep& out) const;
  std::vector<Surface> m_surfaces;
  double m_lengthScale = 1.0;
};

/// Valid entries of a "Free Surface" group sublist.
Teuchos::RCP<const Teuchos::ParameterList> validFreeSurfaceParameters();

}  // namespace flowform
