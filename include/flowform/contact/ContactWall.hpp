// A frictional contact wall on a named boundary group (docs/theory.md §2, paper §2.1): a tool
// whose surface stays in place (fixed, or moving tangentially to itself: Tool Motion,
// ToolMotion.hpp), acting on the wall's nodes with no extra unknowns.
//
// On an ACTIVE node k with outward normal n_k (material → tool), tangent t_k = (−n_y, n_x) and
// the tool's surface velocity v_k = v_w(x_k) (0 for a fixed tool):
//   normal penalty (paper eq. 16):  R_k += α_n ((u_k − v_k)·n_k) n_k
//   friction (eq. 17–19):           R_k += g_k t_k,  g_k the tangential force opposing the
//                                   relative slip u_t = (u_k − v_k)·t_k
// Below, u·n and u_t always mean the velocities relative to the tool, (u − v_w)·n and
// (u − v_w)·t: the status criteria, the complementarity and the laws all read them.
// with α_n = κ_n μ_k W_k, α_t = κ_t μ_k W_k (κ dimensionless input factors, μ_k the largest
// cell viscosity at the node, W_k = 2π r_k axisymmetric, 1 in plane strain): the penalties
// scale with the bulk stiffness, so one default works across scenes.
//
// g_k comes from the wall's friction law (contact/friction/: Coulomb, Tresca, Orowan,
// Norton, None; one file each, registered in FrictionLaws.hpp). This class lumps the segment
// integrals the law needs (P_k, S_k, A_k) over the node's active segments — a segment is
// active when both its nodes are — and keeps the wall's geometry, status and penalty scales.
// μ_k and σ̄ are taken from the solution at the start of each flow solve and held during its
// Newton iterations (setScales).
//
// Templated on the dof scalar (Scalar) and on the friction parameters ν, m (PScalar,
// FrictionParameters): the same code gives values, the AD tangent and ∂/∂ν, ∂/∂m
// (docs/theory.md §4, paper eq. 28).
//
// Nodal normal: the curve's (bisector of the two segment normals inside one wall; the
// segment's own at a wall's end). Where two walls meet at a corner, the node gets each
// wall's penalty along that wall's normal, so both velocity components are held there.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/contact/ContactWallSettings.hpp"
#include "flowform/contact/friction/FrictionLaws.hpp"
#include "flowform/core/Types.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

/// What a status update decided: the wall node to change, or none (index −1).
struct StatusChange {
  int node = -1;
  bool activate = false;
  double violation = 0.0;  ///< tension (−p) or penetration (u·n)
};

class ContactWall {
 public:
  /// Valid entries of a "Contact Wall" group sublist (besides Type).
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// `params` is the group's sublist (validated here; InputError naming the group).
  ContactWall(const std::string& group, const Teuchos::ParameterList& params, const Mesh& mesh, Geometry geometry);

  const std::string& name() const { return m_curve.name; }
  const BoundaryCurve& curve() const { return m_curve; }
  const ContactWallSettings& settings() const { return m_settings; }
  int numNodes() const { return static_cast<int>(m_curve.nodes.size()); }
  /// Re-reads the node coordinates from `mesh` (moved nodes): arc length, normals, segment
  /// lengths. The convex-corner normals are cleared: markConvexToolCorners() sets them again.
  void refreshGeometry(const Mesh& mesh);
  /// Sets the tool itself (the wall as made: what gap() measures from and, for a wall whose
  /// released nodes are free surfaces, the normals) from `made`, the mesh as made moved by a shape
  /// parameter (Problem::moveShape). Free-surface moves leave the tool where it was made.
  void setTool(const Mesh& made);
  /// Whether the released tail of this wall is a free surface (Released Nodes = Free Surface),
  /// and the group at the wall's upstream end (Start Group).
  bool releasedFreeSurface() const { return m_settings.releasedFreeSurface; }
  const std::string& upstreamGroup() const { return m_settings.upstreamGroup; }
  /// Whether the wall's first node is its upstream end: the end it shares with its Start Group;
  /// true without one (the one answer for walls, their responses and their free surfaces).
  bool firstNodeIsUpstream() const { return m_firstIsUpstream; }
  /// The wall node at its downstream end (away from its Start Group).
  int downstreamEnd() const { return m_firstIsUpstream ? numNodes() - 1 : 0; }
  /// Distance of node k from the tool (the wall as made) along the tool's normal: 0 unless a
  /// free-surface update moved the node off it. A node off the tool is never activated.
  double gap(int k) const {
    const auto& n = m_curve.normals[k];
    return (m_toolCoords[k][0] - m_coords[k][0]) * n[0] + (m_toolCoords[k][1] - m_coords[k][1]) * n[1];
  }
  /// The tool's surface velocity v_w at node k (0 for a fixed tool), and its components along
  /// the node's normal and tangent.
  const std::array<double, 2>& wallVelocity(int k) const { return m_wallVelocity[k]; }
  double wallNormalSpeed(int k) const { return m_wallNormalSpeed[k]; }
  double wallTangentialSpeed(int k) const { return m_wallTangentialSpeed[k]; }
  const ToolMotion& motion() const { return m_settings.motion; }
  /// (u − v_w)·n at node k, u the node's velocity: > 0 moves into the tool.
  template <typename Scalar>
  Scalar relativeNormalVelocity(int k, const Scalar* u) const {
    const auto& n = m_curve.normals[k];
    return n[0] * u[0] + n[1] * u[1] - m_wallNormalSpeed[k];
  }
  double relativeNormalVelocity(int k, const std::array<double, 2>& u) const { return relativeNormalVelocity(k, u.data()); }
  /// The relative slip (u − v_w)·t at node k, t = (−n_y, n_x): what the friction laws act on.
  template <typename Scalar>
  Scalar relativeSlip(int k, const Scalar* u) const {
    const auto& n = m_curve.normals[k];
    return -n[1] * u[0] + n[0] * u[1] - m_wallTangentialSpeed[k];
  }
  /// Consecutive wall nodes, which the friction law couples (for the DofMap).
  std::vector<std::array<GO, 2>> couplings() const;

  /// Whether node k is in contact: its status, or for a complementarity node whether it pressed
  /// on the tool (u·n > 0) at the state last read (readContact).
  bool isActive(int k) const { return m_active[k] == kComplementary ? m_inContact[k] != 0 : m_active[k] != kFree; }

  /// Complementarity (Contact/Status Update = Complementarity, docs/contact.md §"Complementarity"):
  /// every node of this wall that can change its status (not held, not at an open convex tool
  /// corner, on a wall whose released nodes are Fixed) stops having one. Its normal force is
  /// α_n max(u·n, 0) — the penalty-regularized complementarity between the normal reaction and
  /// the penetration, decided by Newton itself (semi-smooth: the generalized derivative of max) —
  /// and its friction acts over the part of each adjacent segment that is in contact, which ends
  /// at the interpolated zero of φ = λ/(μW) (in contact) or u·n (separated) inside the segment
  /// that holds the zone limit. The remaining nodes keep their statuses, changed by the
  /// status loop. Returns the number of complementarity nodes.
  int enterComplementarity();
  bool complementarity() const { return m_complementarity; }
  /// Whether the wall's residual is affine in the solution: statuses (no complementarity's max) and
  /// a law without a bound or a kink — None, or Norton with q = 1. Coulomb (ν p⁺, the sticking
  /// bound), Tresca and Orowan are not: a Newtonian case with such a wall needs Newton (NonlinearSolver).
  bool isLinear() const {
    if (m_complementarity) return false;
    const std::string& name = law().name;
    return name == "None" || (name == "Norton" && m_settings.friction.nortonExponent == 1.0);
  }
  /// The nodes at open convex tool corners that keep statuses: those active and in tension
  /// (p < −pressureTolerance) at `p` are released, all at once; returns how many. Called on the
  /// first solve's state before enterComplementarity (the die lip, in tension when every node
  /// is active, is released there as the paper's loop releases it first).
  int releaseCornersInTension(const std::vector<double>& p, double pressureTolerance);
  /// Back to statuses: each complementarity node active if it pressed at the last readContact.
  void leaveComplementarity() {
    for (int k = 0; k < numNodes(); ++k)
      if (m_active[k] == kComplementary) m_active[k] = m_inContact[k] ? kActive : kFree;
    m_complementarity = false;
  }
  bool isComplementary(int k) const { return m_active[k] == kComplementary; }
  /// Records which complementarity nodes press on the tool at `u` (per wall node); returns how
  /// many changed since the last reading.
  int readContact(const std::vector<std::array<double, 2>>& u);
  /// Changes the status of node k and counts the change.
  void setActive(int k, bool active) {
    m_active[k] = active ? kActive : kFree;
    ++m_changes[k];
  }
  /// A node that cycles between active and free at a separation point (the point lies inside a
  /// segment: active it pulls, free it moves into the tool) decides by itself: its normal force
  /// is α_n max(u·n, 0) (no tension, no penetration beyond what the penalty allows), its friction
  /// is bounded by that force (a Tresca or Orowan node slides freely when it separates), and it
  /// counts as active. Only walls whose released nodes are a free surface use it (ContactStatusLoop).
  bool isSelfDeciding(int k) const { return m_active[k] == kSelfDeciding; }
  /// Lets every node that has changed `maxChangesPerNode` times and still violates its
  /// criterion decide by itself; returns how many now do. A self-deciding node that leaves
  /// the tool (u·n < −penetration tolerance) is released as any node is.
  int letCyclingNodesDecide(const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                            double pressureTolerance, double penetrationTolerance, int maxChangesPerNode);
  int selfDecidingNodes() const {
    int count = 0;
    for (char a : m_active) count += a == kSelfDeciding;
    return count;
  }
  int changes(int k) const { return m_changes[k]; }
  /// Forgets the change counts (a new solve from this state, e.g. a finite-difference run,
  /// gets its own Max Changes Per Node).
  void resetChangeCounts() { m_changes.assign(m_changes.size(), 0); }
  const std::array<double, 2>& nodeCoordinates(int k) const { return m_coords[k]; }
  /// Wall neighbours of node k (−1 where the wall ends).
  int previous(int k) const { return k > 0 ? k - 1 : (m_curve.closed ? numNodes() - 1 : -1); }
  int next(int k) const { return k + 1 < numNodes() ? k + 1 : (m_curve.closed ? 0 : -1); }

  /// At a node this wall shares with another wall at a convex tool corner (the material's
  /// angle there is reflex, like the die lip), material moving along the other wall is not
  /// entering the tool: a free node penetrates only if u·n > tolerance for this wall's normal
  /// AND for each normal added here (the tool is the intersection of the half-planes).
  /// With Convex Corners = Closed the node is held instead: active, and never released.
  /// `otherSpeed` is the other tool's v_w·n there (the penetration test is on (u − v_w)·n of
  /// each tool).
  void addCornerNormal(int k, const std::array<double, 2>& otherNormal, double otherSpeed = 0.0) {
    m_cornerNormals[k].push_back(otherNormal);
    m_cornerSpeeds[k].push_back(otherSpeed);
    if (m_settings.closedCorners) m_active[k] = kActive;
  }
  /// Node k's normal velocity is held by a velocity condition of another group (its normal
  /// component prescribed: a `Parallel To` the wall, as the cutting scene's chip outlet at the rake's
  /// top, or both components): the normal force there is that condition's reaction, and the
  /// penalty's normal force, α_n (u − v_w)·n, is exactly 0 (u·n is the condition's value). The
  /// friction laws on the contact force see it as 0 (no friction), not as the round-off sign of a
  /// held product, which flipped the node's branch under any move and made the DDM's mesh
  /// partials straddle the kink of max(·, 0) (docs/sensitivity.md "Shape parameters"). Set by
  /// Problem::markHeldNormals() whenever the conditions or the geometry change.
  void setNormalHeld(int k, bool held) { m_normalHeld[k] = held ? 1 : 0; }
  bool normalHeld(int k) const { return m_normalHeld[k] != 0; }
  /// Whether node k is held active (no status change): at a closed convex corner, or, on a wall
  /// whose released nodes are a free surface, its upstream end when no other wall meets it there
  /// (the fixed start of the surface where the material divides: a cutting tool's tip; at a tool
  /// corner such as a die lip the corner rules decide).
  bool held(int k) const {
    return (m_settings.closedCorners && !m_cornerNormals[k].empty()) || (k == m_upstreamEnd && m_cornerNormals[k].empty());
  }

  /// What solving changes on a wall: the statuses and their change counts, ν and m, and the
  /// penalty scales. A perturbed solve (the finite-difference check) saves it and restores it
  /// afterwards; the geometry is not part of it.
  struct State {
    std::vector<char> active, inContact;
    std::vector<int> changes;
    FrictionParameters<double> friction;
    std::vector<double> frictionField;
    std::vector<double> viscosity, flowStress;
  };
  State state() const {
    return {m_active, m_inContact, m_changes, frictionParameters(), m_settings.frictionField, m_viscosity, m_flowStress};
  }
  void restore(const State& s) {
    m_active = s.active;
    m_inContact = s.inContact;
    m_changes = s.changes;
    setFrictionCoefficient(s.friction.frictionCoefficient);
    setShearFactor(s.friction.shearFactor);
    m_settings.frictionField = s.frictionField;
    m_viscosity = s.viscosity;
    m_flowStress = s.flowStress;
  }

  /// The statuses of `other` (the same wall on another mesh) carried to this wall's nodes:
  /// each node takes the status of the nearest point of `other`'s polyline (the nearer end of
  /// that segment; a node at a segment's midpoint is active only when both ends are). With `u`
  /// (this wall's nodal velocities at the carried-over state), a node inside a segment whose
  /// ends differ — the limit of the contact zone — is decided by the activation criterion
  /// instead: active if it moves into the tool (u·n > penetrationTolerance, for every normal at a
  /// convex tool corner). The change counts start again from zero. For starting a solve on a
  /// new mesh from a converged one. When `other` decides by complementarity and `u` is given (a
  /// solve starts here), so does this wall (each node starting with the contact taken over).
  void takeStatusesFrom(const ContactWall& other, const std::vector<std::array<double, 2>>* u = nullptr,
                        double penetrationTolerance = 0.0);
  /// Per wall node: viscosity μ and flow stress σ̄ (largest over the adjacent cells).
  void setScales(std::vector<double> viscosity, std::vector<double> flowStress);
  void setFrictionCoefficient(double nu) { m_settings.frictionCoefficient = nu; }
  /// Friction Field (docs/contact.md "Friction fields"): ν given at N + 1 stations s_j = j L/N along
  /// the wall (s the arc length from the curve's first node, the curve running with the material
  /// on its left; L the wall's length), linear between them; node k's ν is the field at s_k.
  bool hasFrictionField() const { return !m_settings.frictionField.empty(); }
  int numFieldStations() const { return static_cast<int>(m_settings.frictionField.size()); }
  double fieldValue(int station) const { return m_settings.frictionField[station]; }
  void setFieldValue(int station, double nu) { m_settings.frictionField[station] = nu; }
  /// ν, or the largest value of the Friction Field.
  double largestFrictionCoefficient() const {
    double nu = m_settings.frictionCoefficient;
    for (double v : m_settings.frictionField) nu = std::max(nu, v);
    return nu;
  }
  /// The wall's length (as the curve is now).
  double length() const {
    return m_curve.arcLength.back() + (m_curve.closed ? m_curve.segmentLength.back() : 0.0);
  }
  /// Where station j lies (on the wall as made).
  std::array<double, 2> stationPoint(int station) const;
  /// ν at node k: the field's (with its derivative by the seeded station, fp.seededStation), or fp's ν.
  template <typename PScalar>
  PScalar nodeFrictionCoefficient(int k, const FrictionParameters<PScalar>& fp) const;
  void setShearFactor(double m) { m_settings.shearFactor = m; }
  /// Nodes at rest without compression stick (FrictionSettings::stickAtRest).
  void setStickAtRest(bool on) { m_settings.friction.stickAtRest = on; }
  /// ν and m as the case gives them.
  FrictionParameters<double> frictionParameters() const {
    return {m_settings.frictionCoefficient, m_settings.shearFactor};
  }
  /// Whether ν (Coulomb, Orowan) or m (Tresca, Orowan) enters this wall's law.
  const FrictionLawInfo& law() const { return frictionLaws()[m_settings.law]; }
  bool usesFrictionCoefficient() const { return law().usesFrictionCoefficient; }
  bool usesShearFactor() const { return law().usesShearFactor; }

  /// One entry of a wall node's stencil: a wall node (−1: absent neighbour) and a node component.
  struct StencilEntry {
    int node, component;
  };
  /// Size of a wall node's stencil (the assembler's AD types are sized with it) and of its rows.
  static constexpr int kNodeStencilSize = 9;
  static constexpr int kNodeRows = 2;
  /// The stencil of node k's residual in the order addNodeResidual reads it: u_x, u_y of k
  /// (its kNodeRows rows, in that order), then p of previous(k), k, next(k), then u_x, u_y of
  /// previous(k) and of next(k) (a complementarity node's contact part of each segment).
  std::array<StencilEntry, kNodeStencilSize> nodeStencil(int k) const {
    return {{{k, kUx},
             {k, kUy},
             {previous(k), kP},
             {k, kP},
             {next(k), kP},
             {previous(k), kUx},
             {previous(k), kUy},
             {next(k), kUx},
             {next(k), kUy}}};
  }

  /// The two momentum rows of wall node k from its stencil's values `v` (nodeStencil's order:
  /// u_k = v[0..1], the pressures of previous(k), k, next(k) = v[2..4], the neighbours'
  /// velocities v[5..8]; an absent neighbour's entries are ignored). Adds into R[2]. The
  /// friction parameters are `fp` (PScalar: double, or an AD type when ∂/∂ν, ∂/∂m are
  /// wanted; Scalar must then be an AD type of the same kind).
  /// `dual` (Jacobian evaluations only) selects the dual slip linearization (FrictionDual.hpp).
  template <typename Scalar, typename PScalar>
  void addNodeResidual(int k, const FrictionParameters<PScalar>& fp, const Scalar* v, Scalar* R,
                       FrictionDualPoint* dual = nullptr) const;
  template <typename Scalar>
  void addNodeResidual(int k, const Scalar* v, Scalar* R) const {
    addNodeResidual(k, frictionParameters(), v, R);
  }

  /// Tangential force g_k (positive along t_k) from the stencil's values `v`, and the branch of
  /// the law it is on.
  template <typename Scalar, typename PScalar>
  Scalar tangentialForce(int k, const FrictionParameters<PScalar>& fp, const Scalar* v,
                         FrictionBranch* branch = nullptr, FrictionDualPoint* dual = nullptr) const;
  /// g_k with the case's ν, m, and whether the node sticks, for output.
  template <typename Scalar>
  Scalar tangentialForce(int k, const Scalar* v, bool* sticks = nullptr) const {
    FrictionBranch b;
    const Scalar g = tangentialForce(k, frictionParameters(), v, &b);
    if (sticks) *sticks = b == FrictionBranch::Stick;
    return g;
  }
  /// The stencil's values of node k (nodeStencil's order) from per-wall-node p and u.
  std::array<double, kNodeStencilSize> stencilValues(int k, const std::vector<double>& p,
                                                     const std::vector<std::array<double, 2>>& u) const;

  /// The next status change (docs/theory.md §2): an active node in tension (p < −pressureTolerance)
  /// is released, a free node that penetrates (u·n > penetrationTolerance) is activated;
  /// among the candidates at the limit of the contact zone (a neighbour of the other
  /// status, or a wall end) the one with the largest violation. Candidates not at a limit
  /// are taken only when no limit node is one. `p`, `u` per wall node. A node that has
  /// already changed `maxChangesPerNode` times is not changed again (it would cycle);
  /// `unsettled` returns how many such nodes still violate their criterion.
  /// `runnerUp` (optional) returns the second largest violation of the class the change was
  /// taken from (0 when there is none). `unsettledRatio` (optional) returns the largest tension or
  /// penetration of the unsettled nodes over its tolerance.
  StatusChange nextChange(const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                          double pressureTolerance, double penetrationTolerance, int maxChangesPerNode,
                          int* unsettled = nullptr, double* runnerUp = nullptr,
                          double* unsettledRatio = nullptr) const;

 /// The nodes that changed `maxChangesPerNode` times and still violate their criterion (those
  /// nextChange counts as unsettled).
  std::vector<int> cyclingNodes(const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                                double pressureTolerance, double penetrationTolerance, int maxChangesPerNode) const {
    std::vector<int> nodes;
    for (int k = 0; k < numNodes(); ++k)
      if (m_changes[k] >= maxChangesPerNode && violation(k, p, u, pressureTolerance, penetrationTolerance) > 0.0)
        nodes.push_back(k);
    return nodes;
  }

 private:
  /// How far node k violates the criterion of its status (> 0: it should change; −∞: it
  /// cannot change): tension beyond the pressure tolerance (active), motion into the tool
  /// beyond the penetration tolerance (free), motion away from it (self-deciding).
  double violation(int k, const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                   double pressureTolerance, double penetrationTolerance) const;
  /// P_k, S_k and A_k of node k, each only when the law needs it (FrictionLaw.hpp).
  template <typename Scalar>
  void lumpSegmentIntegrals(int k, const Scalar* v, FrictionNodeData<Scalar>& d) const;
  /// A complementarity wall: the part [s0, s1] of segment k–o (s = 0 at k, 1 at o) that is in
  /// contact, from the nodes' velocities: all of it when both nodes press on the tool, none
  /// when neither does, else up to the zero of φ interpolated along it (enterComplementarity).
  template <typename Scalar>
  bool contactPart(int k, int o, const Scalar* uk, const Scalar* uo, Scalar& s0, Scalar& s1) const;
  /// φ_j of wall node j at velocity uj (enterComplementarity) and whether j is in contact.
  template <typename Scalar>
  Scalar contactMeasure(int j, const Scalar* uj, bool& inContact) const;
  double weight(int k) const;  ///< W_k: 2π r_k or 1
  /// What the status loop compares with the Pressure Tolerance at an active node (compression
  /// positive): the mean pressure p_k (the paper's criterion), or on a wall whose Coulomb law
  /// multiplies the contact force (Coulomb Normal Force = Contact Force) and whose released nodes
  /// stay on the tool's side (not Released Nodes = Free Surface) the normal traction that force
  /// carries — the two differ by s_nn, ≈ −k on a yielding surface, so that p < 0 where the
  /// tool still presses (a roll's arc).
  double compression(int k, const std::vector<double>& p, const std::vector<std::array<double, 2>>& u) const;
  /// Reads Tool Motion and its entries from the validated `list` (`given`: the case's own entries,
  /// for the warnings); InputError naming the group for a rotation in axisymmetry or a radial
  /// axisymmetric translation.
  void readToolMotion(const std::string& group, const Teuchos::ParameterList& given, const Teuchos::ParameterList& list);
  /// InputError naming the group when a moving tool is not tangential to its own segments.
  void checkTangency(const std::string& group) const;
  /// A Rotation whose Rotation Centre X and Y are not given turns about the centre of the circle
  /// fitted to the wall's nodes (the roll's axis follows the mesh's R and gap); InputError naming
  /// the group for fewer than 3 nodes or nodes on a straight line.
  void fitRotationCentre(const std::string& group, const Teuchos::ParameterList& given, const Mesh& mesh);

  BoundaryCurve m_curve;
  ContactWallSettings m_settings;
  bool m_centreFitted = false;  ///< the Rotation Centre is fitted to the nodes (and refitted as they move)
  Geometry m_geometry;
  static constexpr char kFree = 0, kActive = 1, kSelfDeciding = 2, kComplementary = 3;
  std::vector<char> m_active;     ///< kFree, kActive, kSelfDeciding or kComplementary per node
  std::vector<char> m_inContact;  ///< kComplementary nodes: u·n > 0 at the last readContact
  bool m_complementarity = false;
  std::vector<int> m_changes;
  std::vector<std::vector<std::array<double, 2>>> m_cornerNormals;
  std::vector<char> m_normalHeld;  ///< setNormalHeld
  std::vector<std::vector<double>> m_cornerSpeeds;  ///< the other tool's v_w·n, per corner normal
  /// The tool's surface velocity at each node and its normal and tangential components.
  std::vector<std::array<double, 2>> m_wallVelocity;
  std::vector<double> m_wallNormalSpeed, m_wallTangentialSpeed;
  bool m_firstIsUpstream = true;  ///< firstNodeIsUpstream()
  int m_upstreamEnd = -1;  ///< Released Nodes = Free Surface: the wall node shared with the Start Group
  std::vector<double> m_viscosity, m_flowStress;
  /// A Friction Field: node k lies between stations m_fieldStation[k] and the next, at fraction
  /// m_fieldFraction[k] of the way (refreshGeometry).
  std::vector<int> m_fieldStation;
  std::vector<double> m_fieldFraction;
  std::vector<std::array<double, 2>> m_coords;
  /// The tool: the node positions and normals as made. A wall whose released tail is a free
  /// surface keeps these normals when its nodes move (the tool does not turn with the material).
  std::vector<std::array<double, 2>> m_toolCoords, m_toolNormals;
};

/// The case's contact walls: every sublist of `bcList` ("Boundary Conditions") whose Type is
/// Contact Wall, in the list's order, with their convex tool corners marked. InputError for a
/// group the mesh does not have.
std::vector<ContactWall> contactWallsFromCase(const Teuchos::ParameterList& bcList, const Mesh& mesh,
                                              Geometry geometry);

// ---------------------------------------------------------------------------------------

inline double ContactWall::weight(int k) const {
  return m_geometry == Geometry::Axisymmetric ? 2.0 * M_PI * m_coords[k][0] : 1.0;
}

template <typename Scalar>
Scalar ContactWall::contactMeasure(int j, const Scalar* uj, bool& inContact) const {
  const Scalar g = relativeNormalVelocity(j, uj);  // (u − v_w)·n
  const double kappa = m_settings.normalPenalty;
  switch (m_active[j]) {
    case kActive:  // held by its status: in contact, φ = its normal reaction (≥ 0)
      inContact = true;
      return g > 0.0 ? Scalar(kappa * g) : Scalar(0.0);
    case kFree:
      inContact = false;
      return g < 0.0 ? g : Scalar(0.0);
    default:  // complementarity (and self-deciding) nodes: λ/(μW) = κ_n (u − v_w)·n pressing, (u − v_w)·n separating
      inContact = g > 0.0;
      return inContact ? Scalar(kappa * g) : g;
  }
}

template <typename Scalar>
bool ContactWall::contactPart(int k, int o, const Scalar* uk, const Scalar* uo, Scalar& s0, Scalar& s1) const {
  bool ck = false, co = false;
  const Scalar phiK = contactMeasure(k, uk, ck);
  const Scalar phiO = contactMeasure(o, uo, co);
  s0 = 0.0;
  s1 = 1.0;
  if (ck && co) return true;
  if (!ck && !co) return false;
  // One end in contact (φ ≥ 0), the other not (φ ≤ 0): the limit is the zero of the linear φ.
  const Scalar jump = phiK - phiO;
  const Scalar zero = ck ? (jump > 0.0 ? phiK / jump : Scalar(0.5)) : (jump < 0.0 ? phiK / jump : Scalar(0.5));
  if (ck)
    s1 = zero;
  else
    s0 = zero;
  return true;
}

template <typename Scalar>
void ContactWall::lumpSegmentIntegrals(int k, const Scalar* v, FrictionNodeData<Scalar>& d) const {
  // Σ_s ∫_s N_k (·) W ds over the active segments at k (integrateSegment: exact for N, p_h,
  // σ̄_h and W linear along the segment). A complementarity wall integrates each segment over
  // its part in contact (contactPart), with the same 2-point rule on that part.
  const FrictionLawInfo& info = law();
  const int neighbours[2] = {previous(k), next(k)};
  const Scalar* p = v + 2;
  for (int side = 0; side < 2; ++side) {
    const int o = neighbours[side];
    if (o < 0) continue;
    const Scalar pk = p[1] > 0.0 ? p[1] : Scalar(0.0);                                  // p⁺_k
    const Scalar po = p[side == 0 ? 0 : 2] > 0.0 ? p[side == 0 ? 0 : 2] : Scalar(0.0);  // p⁺_o
    const double sk = m_flowStress[k], so = m_flowStress[o];
    if (!m_complementarity) {
      if (!m_active[o]) continue;
      integrateSegment(m_coords[k], m_coords[o], m_geometry, [&](double Nk, double No, double w) {
        if (info.usesFrictionCoefficient) d.pressureIntegral += w * Nk * (Nk * pk + No * po);
        if (info.usesShearFactor) d.stressIntegral += w * Nk * (Nk * sk + No * so);
        if (info.needsTributary) d.tributary += w * Nk;
      });
      continue;
    }
    Scalar s0, s1;
    if (!contactPart(k, o, v, v + (side == 0 ? 5 : 7), s0, s1)) continue;
    integrateSegmentPart(m_coords[k], m_coords[o], s0, s1, m_geometry, [&](const Scalar& Nk, const Scalar& No, const Scalar& w) {
      if (info.usesFrictionCoefficient) d.pressureIntegral += w * Nk * (Nk * pk + No * po);
      if (info.usesShearFactor) d.stressIntegral += w * Nk * (Nk * sk + No * so);
      if (info.needsTributary) d.tributary += w * Nk;
    });
  }
}

template <typename Scalar, typename PScalar>
Scalar ContactWall::tangentialForce(int k, const FrictionParameters<PScalar>& fp, const Scalar* v,
                                    FrictionBranch* branch, FrictionDualPoint* dual) const {
  const Scalar* u = v;
  const Scalar un = relativeNormalVelocity(k, u);  // (u − v_w)·n
  const bool separating = m_active[k] == kSelfDeciding && !(un > 0.0);
  if (m_active[k] == kFree || separating) {
    if (branch) *branch = FrictionBranch::Free;
    return Scalar(0.0);
  }
  FrictionNodeData<Scalar> d{relativeSlip(k, u),  // (u − v_w)·t, t = (−n_y, n_x)
                             Scalar(0.0), Scalar(0.0), Scalar(0.0),
                             m_settings.tangentialPenalty * m_viscosity[k] * weight(k), dual};
  lumpSegmentIntegrals(k, v, d);
  if (m_active[k] == kComplementary && !(d.pressureIntegral > 0.0) && !(d.stressIntegral > 0.0) &&
      !(d.tributary > 0.0)) {
    if (branch) *branch = FrictionBranch::Free;  // no part of its segments in contact
    return Scalar(0.0);
  }
  if (m_settings.coulombOnContactForce || m_active[k] == kSelfDeciding) {
    // N_k = max(α_n (u − v_w)·n, 0): the penalty's normal force on the node (its normal traction, lumped).
    const Scalar normalForce = m_settings.normalPenalty * m_viscosity[k] * weight(k) * un;
    d.pressureIntegral = normalForce > 0.0 && !m_normalHeld[k] ? normalForce : Scalar(0.0);
  }
  FrictionParameters<PScalar> atNode = fp;  // ν of a Friction Field at node k
  atNode.frictionCoefficient = nodeFrictionCoefficient(k, fp);
  const FrictionForce<Scalar> f = frictionForce(m_settings.law, d, atNode, m_settings.friction);
  if (branch) *branch = f.branch;
  return f.g;
}

template <typename PScalar>
PScalar ContactWall::nodeFrictionCoefficient(int k, const FrictionParameters<PScalar>& fp) const {
  if (!hasFrictionField()) return fp.frictionCoefficient;
  const int j = m_fieldStation[k];
  const double w = m_fieldFraction[k];
  const double value = (1.0 - w) * m_settings.frictionField[j] + w * m_settings.frictionField[j + 1];
  if constexpr (std::is_same_v<PScalar, double>) {
    return value;
  } else {
    if (fp.seededStation < 0) return PScalar(value);
    PScalar nu(1, 0, value);  // the derivative by station fp.seededStation: its hat function at s_k
    nu.fastAccessDx(0) = (fp.seededStation == j ? 1.0 - w : 0.0) + (fp.seededStation == j + 1 ? w : 0.0);
    return nu;
  }
}

template <typename Scalar, typename PScalar>
void ContactWall::addNodeResidual(int k, const FrictionParameters<PScalar>& fp, const Scalar* v, Scalar* R,
                                  FrictionDualPoint* dual) const {
  if (m_active[k] == kFree) return;
  const Scalar* u = v;
  const auto& n = m_curve.normals[k];
  const double alphaN = m_settings.normalPenalty * m_viscosity[k] * weight(k);
  Scalar un = relativeNormalVelocity(k, u);  // (u − v_w)·n
  const bool oneSided = m_active[k] == kSelfDeciding || m_active[k] == kComplementary;
  if (oneSided && !(un > 0.0)) un = Scalar(0.0);  // α_n max((u − v_w)·n, 0)
  R[0] += alphaN * un * n[0];
  R[1] += alphaN * un * n[1];
  const Scalar g = tangentialForce(k, fp, v, nullptr, dual);
  R[0] += g * (-n[1]);
  R[1] += g * n[0];
}

}  // namespace flowform
