#include "flowform/sensitivity/GeoParameterMotion.hpp"

#include <algorithm>
#include <cmath>

#include "flowform/contact/ToolVelocities.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/freesurface/MeshMotion.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/freesurface/ReferenceTopology.hpp"
#include "flowform/mesh/MeshReader.hpp"
#include "flowform/problem/Problem.hpp"
#include "flowform/sensitivity/BoundaryValuePartials.hpp"

namespace flowform {

GeoParameterValues givenGeoParameters(const Teuchos::ParameterList& caseParams) {
  GeoParameterValues values;
  if (!caseParams.isSublist("Mesh") || !caseParams.sublist("Mesh").isSublist("Geo Parameters")) return values;
  const Teuchos::ParameterList& geo = caseParams.sublist("Mesh").sublist("Geo Parameters");
  for (auto it = geo.begin(); it != geo.end(); ++it) {
    const Teuchos::ParameterEntry& entry = geo.entry(it);
    if (entry.isType<double>()) values.emplace_back(geo.name(it), Teuchos::getValue<double>(entry));
    else if (entry.isType<int>()) values.emplace_back(geo.name(it), Teuchos::getValue<int>(entry));
  }
  return values;
}

std::vector<std::array<double, 2>> meshedAt(const Problem& problem, const std::string& name, double value) {
  Teuchos::ParameterList meshList = problem.parameters().sublist("Mesh");
  meshList.sublist("Geo Parameters").set(name, value);
  const SizeField& sizes = problem.sizeField();
  const Mesh other =
      readMeshOnReference(meshList, problem.baseDirectory(), *problem.comm(), sizes.empty() ? nullptr : &sizes);
  const Mesh made = problem.meshAsMade();
  const std::string where = "Sensitivity/Parameters: 'Geo Parameter:" + name + "': meshed at " + name + " = " +
                            std::to_string(value) + ", ";
  // On a reference topology (Mesh/Reference Geo Parameters, freesurface/ReferenceTopology) both
  // meshes are the reference's moved: every node is followed, the interior too, so that V is the
  // derivative of the very map that made this mesh.
  if (hasReferenceTopology(meshList) && other.cellNodes == made.cellNodes) return other.coords;
  // Boundary nodes: the k-th node along each group in the other mesh is the k-th here.
  std::vector<std::array<double, 2>> displacement(made.numNodes(), {0.0, 0.0});
  std::vector<char> prescribed(made.numNodes(), 0);
  for (const BoundaryGroup& group : made.boundaries) {
    if (!other.hasBoundary(group.name))
      throw InputError(where + "the mesh has no group '" + group.name + "'");
    const BoundaryCurve here = buildBoundaryCurve(made, group);
    const BoundaryCurve there = buildBoundaryCurve(other, other.boundary(group.name));
    if (here.closed || there.closed)
      throw InputError(where + "group '" + group.name + "' is a closed curve, whose nodes have no first one to " +
                       "match; a shape parameter needs open boundary groups");
    if (here.nodes.size() != there.nodes.size())
      throw InputError(where + "group '" + group.name + "' has " + std::to_string(there.nodes.size()) +
                       " nodes instead of " + std::to_string(here.nodes.size()) +
                       ": its nodes cannot be followed; a smaller change (or sizes that do not depend on it) would");
    for (size_t k = 0; k < here.nodes.size(); ++k) {
      const GO n = here.nodes[k];
      const auto& to = other.coords[there.nodes[k]];
      displacement[n] = {to[0] - made.coords[n][0], to[1] - made.coords[n][1]};
      prescribed[n] = 1;
    }
  }
  // The interior follows by the harmonic extension (freesurface/MeshMotion).
  return extendBoundaryDisplacement(made, displacement, prescribed);
}

std::vector<std::array<double, 2>> geoParameterMotion(const Problem& problem, const SensitivityParameter& h) {
  // Relative, as the finite-difference check's step; absolute for a parameter at 0 (a rake angle).
  const double delta = h.geoValue != 0.0 ? kGeoMotionStep * std::abs(h.geoValue) : kGeoMotionStep;
  const auto plus = meshedAt(problem, h.geoName, h.geoValue + delta);
  const auto minus = meshedAt(problem, h.geoName, h.geoValue - delta);
  std::vector<std::array<double, 2>> V(plus.size());
  double largest = 0.0;
  for (size_t n = 0; n < V.size(); ++n) {
    V[n] = {(plus[n][0] - minus[n][0]) / (2 * delta), (plus[n][1] - minus[n][1]) / (2 * delta)};
    largest = std::max(largest, std::hypot(V[n][0], V[n][1]));
  }
  log() << "sensitivity: " << h.name << ": the mesh moves by up to " << largest << " per unit of " << h.geoName
        << " (meshed at " << h.geoName << " = " << h.geoValue << " ± " << delta << ")\n";
  return V;
}

std::vector<std::array<double, 2>> movedAlong(const std::vector<std::array<double, 2>>& from,
                                              const std::vector<std::array<double, 2>>& V, double amount) {
  std::vector<std::array<double, 2>> coords = from;
  for (size_t n = 0; n < coords.size(); ++n) {
    coords[n][0] += amount * V[n][0];
    coords[n][1] += amount * V[n][1];
  }
  return coords;
}

MeshPartials meshPartials(Problem& problem, const Vector& state, const std::vector<std::array<double, 2>>& V) {
  // A copy: moving the nodes re-imposes the problem's own solution's prescribed values, which may
  // be `state` itself, and the differences need q held.
  const Vector x(state, Teuchos::Copy);
  const std::vector<std::array<double, 2>> base = problem.mesh().coords;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300}, largest = 0.0;
  for (size_t n = 0; n < base.size(); ++n) {
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], base[n][d]), hi[d] = std::max(hi[d], base[n][d]);
    largest = std::max(largest, std::hypot(V[n][0], V[n][1]));
  }
  MeshPartials out;
  out.dRdh = Teuchos::rcp(new Vector(x.getMap()));
  if (!(largest > 0.0)) return out;  // the parameter moves no node
  // The move (kMeshPartialMove). Central differences in the node positions meet kinks: a wall
  // node near its stick/slip switch (the tangential penalty's stick window |u_t| < f̂/α_t is
  // narrow) changes branch under a move; the Neutral Angle's interpolated zero of the slip jumps a
  // segment where the stick zone's slips are ~0. A smaller move loses digits to round-off where a
  // derivative is small against the residual's terms. Measured with the largest move at 10⁻⁶ …
  // 10⁻¹⁰ of the mesh's size: xml/rolling.xml's dU/dR by the bordered DDM 1.34, 0.514, 0.7853,
  // 0.7853, 0.7853 (re-meshed finite differences 0.785), its dθ_n/dR −9216 at 10⁻⁸ and −0.1369 at
  // 10⁻⁹ (finite differences −0.1370); xml/extrusion.xml's dF/dLe 0.0135044 from 10⁻⁶ to 10⁻⁸
  // (finite differences 0.0135043), 0.0134985 at 10⁻⁹ (4.4e-4 off: 1.6e-6 of F per unit Le).
  // Mixing moves (the residual at 10⁻⁸, the responses at 10⁻⁹, or each at the largest move that
  // agrees with a smaller one) made the rolling forces' derivatives 2–7 % wrong, for a reason not
  // traced (evaluations at several moves in sequence do not reproduce one move's alone).
  //
  // A moving tool's nodes keep their velocity relative to the tool (contact/ToolVelocities.hpp):
  // the differences are taken at x + v_w(X ± εV) − v_w(X), and the flow's shift per unit h,
  // velocityShift, is added back to dq/dh by the DDM.
  const double eps = kMeshPartialMove * std::hypot(hi[0] - lo[0], hi[1] - lo[1]) / largest;
  const bool inflow = !problem.boundaryConditions().rigidInflow().group.empty();
  const Teuchos::RCP<const Vector> toolsAtState = toolVelocities(problem.contactWalls(), problem.dofMap(), x.getMap());
  // The tools move with the shape (Problem::moveShape): the mesh as made along V as well.
  const std::vector<std::array<double, 2>> made = problem.meshAsMade().coords;
  struct Moved {
    Teuchos::RCP<Vector> residual, tools;
    std::map<std::string, double> phi;
    double force = 0.0;
  };
  auto evaluateMoved = [&](double amount) {
    problem.moveShape(movedAlong(made, V, amount), movedAlong(base, V, amount));
    Vector xMoved(x.getMap());
    Moved moved;
    moved.tools = followTools(problem.contactWalls(), problem.dofMap(), x, toolsAtState, xMoved);
    moved.residual = Teuchos::rcp(new Vector(x.getMap()));
    problem.assembler().residual(xMoved, *moved.residual);
    moved.phi = problem.evaluateResponses(xMoved);
    moved.force = inflow ? problem.rigidInflowForce(xMoved) : 0.0;
    problem.moveShape(made, base);
    return moved;
  };
  const Moved plus = evaluateMoved(eps), minus = evaluateMoved(-eps);
  out.dRdh->update(1.0 / (2 * eps), *plus.residual, -1.0 / (2 * eps), *minus.residual, 0.0);
  for (const auto& [name, value] : plus.phi) out.dPhidh[name] = (value - minus.phi.at(name)) / (2 * eps);
  out.dInflowForce = (plus.force - minus.force) / (2 * eps);
  if (!toolsAtState.is_null()) {
    out.velocityShift = Teuchos::rcp(new Vector(x.getMap()));
    out.velocityShift->update(1.0 / (2 * eps), *plus.tools, -1.0 / (2 * eps), *minus.tools, 0.0);
  }
  return out;
}

GeoPartialsSource geoPartialsOf(Problem& problem) {
  return [&problem](const SensitivityParameter& h, const Vector& x) {
    if (h.isBoundaryValue()) return boundaryValuePartials(problem, h, x);
    std::vector<std::array<double, 2>> V = geoParameterMotion(problem, h);
    MeshPartials partials = meshPartials(problem, x, V);
    partials.motion = std::move(V);
    return partials;
  };
}

}  // namespace flowform
