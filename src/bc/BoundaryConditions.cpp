#include "flowform/bc/BoundaryConditions.hpp"

#include <cmath>
#include <sstream>
#include <unordered_set>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/bc/FieldBoundaryValues.hpp"

#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

namespace {

/// One linear condition a·u = b from a named group, before the per-node reduction.
struct LinearCondition {
  double a[2];
  double b;
  std::string group;
};

std::string describeNode(const Mesh& mesh, GO node) {
  std::ostringstream os;
  os << "node " << node << " at (" << mesh.coords[node][0] << ", " << mesh.coords[node][1] << ")";
  return os.str();
}

/// Reduces the conditions at one node to a NodeConstraint; InputError when they conflict.
NodeConstraint reduceConditions(const std::vector<LinearCondition>& conds, const Mesh& mesh, GO node) {
  NodeConstraint nc;
  const LinearCondition* first = nullptr;
  const LinearCondition* second = nullptr;
  for (const auto& c : conds) {
    if (!first) { first = &c; continue; }
    const double cross = first->a[0] * c.a[1] - first->a[1] * c.a[0];
    if (!second && std::abs(cross) > 1e-8) { second = &c; continue; }
    // Dependent on what we have: it must agree with it.
    double predicted;
    if (second) {
      // both components already fixed below; check a·v = b after solving
      continue;
    }
    const double dot = first->a[0] * c.a[0] + first->a[1] * c.a[1];  // ±1 for unit vectors
    predicted = dot * first->b;
    if (std::abs(predicted - c.b) > 1e-12 * (1.0 + std::abs(c.b)))
      throw InputError("boundary conditions of groups '" + first->group + "' and '" + c.group +
                       "' conflict at " + describeNode(mesh, node) + ": they prescribe different values "
                       "for the same velocity component");
  }
  if (!first) return nc;
  if (!second) {
    nc.kind = NodeConstraint::Kind::Single;
    nc.a[0] = first->a[0]; nc.a[1] = first->a[1]; nc.b = first->b;
    nc.constrainedRow = std::abs(nc.a[0]) >= std::abs(nc.a[1]) ? kUx : kUy;
    // t ⊥ a, signed so that the kept row keeps its own sign (t_o > 0).
    nc.t[0] = -nc.a[1]; nc.t[1] = nc.a[0];
    if (nc.t[1 - nc.constrainedRow] < 0) { nc.t[0] = -nc.t[0]; nc.t[1] = -nc.t[1]; }
    return nc;
  }
  // Two independent conditions: solve [a1; a2] v = [b1; b2].
  const double det = first->a[0] * second->a[1] - first->a[1] * second->a[0];
  nc.kind = NodeConstraint::Kind::Full;
  nc.value[0] = (first->b * second->a[1] - first->a[1] * second->b) / det;
  nc.value[1] = (first->a[0] * second->b - first->b * second->a[0]) / det;
  for (const auto& c : conds) {
    const double residual = c.a[0] * nc.value[0] + c.a[1] * nc.value[1] - c.b;
    if (std::abs(residual) > 1e-10 * (1.0 + std::abs(c.b)))
      throw InputError("boundary conditions of groups '" + first->group + "', '" + second->group +
                       "' and '" + c.group + "' conflict at " + describeNode(mesh, node));
  }
  return nc;
}

}  // namespace

static void buildValidGroupParameters(const ValidList& valid) {
  Teuchos::setStringToIntegralParameter<int>(
      "Type", "Traction", "Velocity: prescribed velocity components, or the velocity parallel to a straight "
      "group (Parallel To); Symmetry: zero normal "
      "velocity on a straight boundary; Traction: prescribed traction (default zero: free). "
      "Traction X/Y act on any type, on the components it leaves free. Contact Wall: a frictional "
      "tool wall (its parameters: contact/ContactWall.hpp). Free Surface: traction-free, moved until it is a "
      "streamline (freesurface/FreeSurface.hpp, docs/theory.md §3)",
      Teuchos::tuple<std::string>("Velocity", "Symmetry", "Traction", "Contact Wall", "Free Surface"), valid.get());
  valid->set("Velocity X", 0.0, "prescribed u_x (Velocity type; omit to leave u_x free)", finiteNumber());
  valid->set("Velocity Y", 0.0, "prescribed u_y (Velocity type; omit to leave u_y free)", finiteNumber());
  valid->set("Parallel To", "",
             "Velocity type: the name of a straight boundary group (a tool face); u·n = 0 with n that group's "
             "normal, the tangential component left free (a chip leaving along an inclined rake face)");
  valid->set("Release After Free Surfaces", false,
             "Velocity type: the condition holds while the free surfaces first converge; then the group is "
             "released (traction-free) and the free-surface loop goes on from that shape: a continuation for a "
             "boundary the loop cannot converge free from the start (a curling chip's outlet)");
  valid->set("Rigid Inflow", false,
             "Velocity type: the group moves as one rigid body along (Velocity X, Velocity Y) at a speed that is an "
             "unknown: Velocity X/Y give the direction and the starting speed, and the solve scales them until the "
             "group's reaction balances its Traction X/Y (the force balance of the rigid body upstream: a rolled "
             "strip nobody pushes, docs/rolling.md). At most one group");
  valid->set("Traction X", 0.0, "traction t_x, force per unit area, on free components", finiteNumber());
  valid->set("Traction Y", 0.0, "traction t_y, force per unit area, on free components", finiteNumber());
  declareFieldBoundaryEntries(*valid);
}

Teuchos::RCP<const Teuchos::ParameterList> BoundaryConditions::validGroupParameters() {
  return validListOnce<buildValidGroupParameters>("Boundary Condition");
}

BoundaryConditions::BoundaryConditions(const Teuchos::ParameterList& bcList, const Mesh& mesh,
                                       const DofMap& dofMap)
    : m_bcList(bcList), m_dofMap(dofMap) {
  build(mesh);
}

RankEdges::RankEdges(const Mesh& mesh, const DofMap& dofMap) : m_numNodes(mesh.numNodes()) {
  const int npc = nodesPerCell(mesh.cellType);
  for (GO c : dofMap.cells())
    for (int a = 0; a < npc; ++a) {
      const GO i = mesh.cell(c)[a], j = mesh.cell(c)[(a + 1) % npc];
      m_keys.insert(std::min(i, j) * m_numNodes + std::max(i, j));
    }
}

bool RankEdges::contains(const std::array<GO, 2>& e) const {
  return m_keys.count(std::min(e[0], e[1]) * m_numNodes + std::max(e[0], e[1])) > 0;
}

void BoundaryConditions::refreshGeometry(const Mesh& mesh) { build(mesh); }

void BoundaryConditions::setToolShape(const Mesh& made) {
  for (auto& [group, normal] : m_faceNormals) normal = buildBoundaryCurve(made, made.boundary(group)).segmentNormals.front();
}

void BoundaryConditions::setGroupValue(const Mesh& mesh, const std::string& group, const std::string& entry,
                                       double value) {
  m_bcList.sublist(group).set(entry, value);
  build(mesh);
}

bool BoundaryConditions::releaseHeld(const Mesh& mesh) {
  if (m_held.empty()) return false;
  for (const std::string& name : m_held) {
    Teuchos::ParameterList& group = m_bcList.sublist(name);
    Teuchos::ParameterList free(name);
    free.set("Type", "Traction");
    for (const char* key : {"Traction X", "Traction Y"})
      if (group.isParameter(key)) free.set(key, group.get<double>(key));
    group = free;
    m_released.push_back(name);
  }
  build(mesh);  // the released groups no longer hold: m_held empties
  return true;
}

void BoundaryConditions::build(const Mesh& mesh) {
  const Teuchos::ParameterList& bcList = m_bcList;
  const DofMap& dofMap = m_dofMap;
  m_constraints.clear();
  m_tractionEdges.clear();
  m_held.clear();
  std::vector<std::vector<LinearCondition>> conditions(mesh.numNodes());
  std::vector<std::pair<const BoundaryGroup*, std::array<double, 2>>> tractionGroups;

  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name))
      throw InputError("Boundary Conditions/" + name + " must be a sublist named after a mesh group");
    if (!mesh.hasBoundary(name))
      throw InputError("Boundary Conditions/" + name + ": mesh '" + mesh.source +
                       "' has no boundary group of that name; it has: " + mesh.boundaryNames());
    Teuchos::ParameterList group = bcList.sublist(name);  // copy: validation sets defaults
    if (group.isType<std::string>("Type") &&
        (group.get<std::string>("Type") == "Contact Wall" || group.get<std::string>("Type") == "Free Surface"))
      continue;  // a ContactWall (contact/ContactWall.hpp) or FreeSurfaces (freesurface/) validates it
    try {
      group.validateParameters(*validGroupParameters());
    } catch (const std::exception& e) {
      throw InputError("Boundary Conditions/" + name + ": " + e.what());
    }
    const std::string type = group.get<std::string>("Type", "Traction");
    const BoundaryGroup& bg = mesh.boundary(name);
    if (group.get<bool>("Release After Free Surfaces", false)) {
      if (type != "Velocity")
        throw InputError("Boundary Conditions/" + name + ": 'Release After Free Surfaces' releases a Velocity "
                         "condition, and the group's Type is " + type);
      m_held.push_back(name);
    }

    if (type == "Velocity") {
      const bool hasX = group.isParameter("Velocity X"), hasY = group.isParameter("Velocity Y");
      const std::string parallelTo = group.get<std::string>("Parallel To", "");
      if (!hasX && !hasY && parallelTo.empty())
        throw InputError("Boundary Conditions/" + name +
                         ": type Velocity needs 'Velocity X' and/or 'Velocity Y', or 'Parallel To'");
      std::array<double, 2> normal{0.0, 0.0};
      if (!parallelTo.empty()) {
        if (hasX || hasY)
          throw InputError("Boundary Conditions/" + name + ": 'Parallel To' constrains one component itself; "
                           "give it without 'Velocity X' and 'Velocity Y'");
        if (!m_faceNormals.count(parallelTo)) {  // the first build: the mesh as made
          if (!mesh.hasBoundary(parallelTo))
            throw InputError("Boundary Conditions/" + name + "/Parallel To: mesh '" + mesh.source +
                             "' has no boundary group '" + parallelTo + "'; it has: " + mesh.boundaryNames());
          const BoundaryCurve face = buildBoundaryCurve(mesh, mesh.boundary(parallelTo));
          if (!face.isStraight(1e-8))
            throw InputError("Boundary Conditions/" + name + "/Parallel To: group '" + parallelTo +
                             "' must be straight (its normal is the constrained direction)");
          m_faceNormals[parallelTo] = face.segmentNormals.front();
        }
        normal = m_faceNormals.at(parallelTo);
      }
      // A rigid inflow's velocity is its direction times the current speed (RigidInflow).
      double scale = 1.0;
      if (group.get<bool>("Rigid Inflow", false)) {
        if (!parallelTo.empty() || !hasX || !hasY)
          throw InputError("Boundary Conditions/" + name + ": a 'Rigid Inflow' needs both 'Velocity X' and "
                           "'Velocity Y' (its direction and starting speed), without 'Parallel To'");
        const double vx = group.get<double>("Velocity X"), vy = group.get<double>("Velocity Y");
        const double speed = std::hypot(vx, vy);
        if (!(speed > 0.0))
          throw InputError("Boundary Conditions/" + name + ": a 'Rigid Inflow' needs a nonzero starting velocity "
                           "(Velocity X, Velocity Y): it gives the direction the group moves along");
        if (!m_rigidInflow.group.empty() && m_rigidInflow.group != name)
          throw InputError("Boundary Conditions/" + name + ": 'Rigid Inflow' is set on groups '" +
                           m_rigidInflow.group + "' and '" + name + "'; at most one group may have it");
        if (m_rigidInflow.group.empty()) {  // the first build: the starting speed
          m_rigidInflow.group = name;
          m_rigidInflow.direction = {vx / speed, vy / speed};
          m_rigidInflow.speed = speed;
        }
        scale = m_rigidInflow.speed / speed;
      }
      for (const auto& e : bg.edges)
        for (GO n : e) {
          if (hasX) conditions[n].push_back({{1.0, 0.0}, scale * group.get<double>("Velocity X"), name});
          if (hasY) conditions[n].push_back({{0.0, 1.0}, scale * group.get<double>("Velocity Y"), name});
          if (!parallelTo.empty()) conditions[n].push_back({{normal[0], normal[1]}, 0.0, name});  // u·n = 0
        }
    } else if (type == "Symmetry") {
      const BoundaryCurve curve = buildBoundaryCurve(mesh, bg);
      if (!curve.isStraight(1e-8))
        throw InputError("Boundary Conditions/" + name + ": a Symmetry group must be straight, and '" +
                         name + "' is curved or has a corner");
      const auto& n = curve.segmentNormals.front();
      for (GO node : curve.nodes) conditions[node].push_back({{n[0], n[1]}, 0.0, name});
    }
    // A traction acts on every group that gives one: on a Velocity or Symmetry group it
    // loads the free component(s) only, since the constrained rows are replaced.
    tractionGroups.push_back({&bg, {group.get<double>("Traction X", 0.0), group.get<double>("Traction Y", 0.0)}});
  }

  const auto& overlapNodes = dofMap.overlapNodes();
  m_constraints.resize(overlapNodes.size());
  for (size_t i = 0; i < overlapNodes.size(); ++i)
    m_constraints[i] = reduceConditions(conditions[overlapNodes[i]], mesh, overlapNodes[i]);

  // Traction edges: those that are an edge of one of this rank's cells.
  if (!tractionGroups.empty()) {
    const RankEdges myEdges(mesh, dofMap);
    for (const auto& [bg, t] : tractionGroups) {
      if (t[0] == 0.0 && t[1] == 0.0) continue;  // free: nothing to assemble
      for (const auto& e : bg->edges)
        if (myEdges.contains(e))
          m_tractionEdges.push_back({{dofMap.overlapIndex(e[0]), dofMap.overlapIndex(e[1])}, {t[0], t[1]}});
    }
  }
}

void BoundaryConditions::setRigidInflowSpeed(const Mesh& mesh, double speed) {
  m_rigidInflow.speed = speed;
  build(mesh);
}

void BoundaryConditions::imposeOnSolution(Vector& xOwned, bool homogeneous) const {
  const double scale = homogeneous ? 0.0 : 1.0;
  auto x = xOwned.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (LO i = 0; i < m_dofMap.numOwnedNodes(); ++i) {
    const NodeConstraint& nc = m_constraints[i];
    double& ux = x(m_dofMap.dof(i, kUx), 0);
    double& uy = x(m_dofMap.dof(i, kUy), 0);
    if (nc.kind == NodeConstraint::Kind::Full) {
      ux = scale * nc.value[0];
      uy = scale * nc.value[1];
    } else if (nc.kind == NodeConstraint::Kind::Single) {
      // Move u along a until a·u = b (a is a unit vector).
      const double gap = scale * nc.b - (nc.a[0] * ux + nc.a[1] * uy);
      ux += gap * nc.a[0];
      uy += gap * nc.a[1];
    }
  }
}

}  // namespace flowform
