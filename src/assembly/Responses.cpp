#include "flowform/assembly/Responses.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <Sacado.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/assembly/EvaluationTypes.hpp"
#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/physics/FlowResidual.hpp"

namespace flowform {

Teuchos::RCP<const Teuchos::ParameterList> Responses::validParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Response"));
  Teuchos::setStringToIntegralParameter<int>(
      "Type", "Boundary Force", "what to compute (see include/flowform/assembly/Responses.hpp)",
      Teuchos::tuple<std::string>("Boundary Force", "Mean Pressure", "Boundary Power", "Flow Rate", "Plastic Power",
                                  "Friction Power", "Penalty Power", "Stabilization Power", "Dead Zone",
                                  "Boundary Extent", "Wall Gap", "Contact Length", "Wall Force", "Thickness Ratio",
                                  "Shear Angle"),
      valid.get());
  valid->set("Boundary", "",
             "boundary group (Boundary Force, Mean Pressure, Boundary Power, Flow Rate, Boundary Extent; Thickness "
             "Ratio and Shear Angle: the group a stream leaves through, e.g. a chip's outlet) or contact wall (Wall "
             "Gap, Contact Length, Wall Force)");
  valid->set("Reference Thickness", 1.0,
             "Thickness Ratio, Shear Angle: the thickness t the stream had upstream (cutting: the uncut thickness) "
             "[length]", positive());
  valid->set("Rake Angle", 0.0, "Shear Angle: the tool's rake angle α [degrees]",
             inRange(-89.0, 89.0));
  Teuchos::setStringToIntegralParameter<int>("Component", "X", "force component (Boundary Force, Wall Force), coordinate (Boundary Extent)",
                                             Teuchos::tuple<std::string>("X", "Y"), valid.get());
  valid->set("Fraction", 0.01, "Dead Zone: |u| below this fraction of the reference speed (0 would count no cell)",
             inRange(0.0, 1.0, true, false));
  valid->set("Reference Speed", 1.0, "Dead Zone: the process speed (e.g. the ram's) [velocity]", positive());
  return valid;
}

void Responses::checkWalls(const std::vector<ContactWall>& walls) const {
  for (const Response& r : m_responses) {
    if (r.type != "Wall Gap" && r.type != "Contact Length" && r.type != "Wall Force") continue;
    const auto wall = std::find_if(walls.begin(), walls.end(), [&](const ContactWall& w) { return w.name() == r.boundary; });
    if (wall == walls.end())
      throw InputError("Responses/" + r.name + "/Boundary: '" + r.boundary + "' is not a Contact Wall (a " + r.type +
                       " measures one)");
  }
}

Responses::Responses(const Teuchos::ParameterList& list, const Mesh& mesh) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    if (!list.isSublist(name)) throw InputError("Responses/" + name + " must be a sublist (one per response)");
    Teuchos::ParameterList r = list.sublist(name);
    try {
      r.validateParametersAndSetDefaults(*validParameters());
    } catch (const std::exception& e) {
      throw InputError("Responses/" + name + ": " + e.what());
    }
    Response resp{name,
                  r.get<std::string>("Type"),
                  r.get<std::string>("Boundary"),
                  r.get<std::string>("Component"),
                  r.get<double>("Fraction"),
                  r.get<double>("Reference Speed"),
                  r.get<double>("Reference Thickness"),
                  r.get<double>("Rake Angle")};
    const bool needsBoundary = resp.type == "Boundary Force" || resp.type == "Mean Pressure" ||
                               resp.type == "Boundary Power" || resp.type == "Flow Rate" ||
                               resp.type == "Boundary Extent" || resp.type == "Wall Gap" ||
                               resp.type == "Contact Length" || resp.type == "Wall Force" ||
                               resp.type == "Thickness Ratio" ||
                               resp.type == "Shear Angle";
    if (needsBoundary && !mesh.hasBoundary(resp.boundary))
      throw InputError("Responses/" + name + "/Boundary: mesh '" + mesh.source + "' has no boundary group '" +
                       resp.boundary + "'; it has: " + mesh.boundaryNames());
    m_responses.push_back(resp);
  }
}

namespace {

double sumOverRanks(const Comm& comm, double local) {
  double global = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}
TangentFad sumOverRanks(const Comm& comm, const TangentFad& local) {
  return dual<TangentFad>(sumOverRanks(comm, local.val()), sumOverRanks(comm, local.dx(0)));
}

/// Value (Scalar double) or value and derivative (tangent) of dof `d` of a workset.
template <typename Scalar>
Scalar valueAt(const Workset& ws, LO d) {
  Scalar s;
  gather(ws, &d, 1, &s);
  return s;
}

/// A workset that reads `x` (and the direction `dx`) on their own map.
Workset reader(const Vector& x, const Vector* dx) {
  Workset ws;
  ws.x = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  if (dx) {
    ws.dx = dx->getLocalViewHost(Tpetra::Access::ReadOnly);
    ws.hasDirection = true;
  }
  return ws;
}

/// ∫ 2μ D:D dΩ (plastic power) and Σ τ_K ∫ ∇p·(∇p − f) (stabilization power) over this
/// rank's cells, and (values only) the dead-zone area.
template <typename Scalar>
void cellIntegrals(const Workset& x, const Mesh& mesh, const DofMap& dofMap, const FlowPhysics& physics,
                   const MaterialParameters<Scalar>& material, double deadSpeed, Scalar& plasticPower,
                   Scalar& stabilizationPower, double& deadArea) {
  const int npc = dofMap.nodesPerCell();
  const Geometry geometry = physics.kernel.geometry;
  CellGeometry g;  // the kernel's own rule, so that the powers match the discrete equations exactly
  LO dofs[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
  Scalar values[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
  plasticPower = stabilizationPower = 0.0;
  deadArea = 0.0;
  for (size_t k = 0; k < dofMap.cells().size(); ++k) {
    computeCellGeometry(mesh, dofMap.cells()[k], geometry, g);
    dofMap.cellDofs(k, dofs);
    gather(x, dofs, EqualOrderLayout::numDofs(npc), values);
    const Scalar tau =
        stabilizationTau(physics.kernel.beta, g.diameter, centroidViscosity(g.centroid, geometry, material, values));
    for (int q = 0; q < g.rule.numPoints; ++q) {
      const auto d = strainRateAt(g.rule, q, geometry, values);
      const Scalar mu = viscosity(regularizedStrainRate(d.ddot(), material), material);
      const double w = measureWeight(g.rule, q, geometry);
      plasticPower += w * 2.0 * mu * d.ddot();
      Scalar px = 0.0, py = 0.0;
      for (int a = 0; a < npc; ++a) {
        px += g.rule.dNdx[q][a] * values[EqualOrderLayout::index(a, kP)];
        py += g.rule.dNdy[q][a] * values[EqualOrderLayout::index(a, kP)];
      }
      stabilizationPower += w * tau * (px * (px - physics.kernel.bodyForce[0]) + py * (py - physics.kernel.bodyForce[1]));
    }
    double ux = 0.0, uy = 0.0;
    for (int a = 0; a < npc; ++a) {
      ux += g.centroid.N[0][a] * x.x(dofs[EqualOrderLayout::index(a, kUx)], 0);  // values only
      uy += g.centroid.N[0][a] * x.x(dofs[EqualOrderLayout::index(a, kUy)], 0);
    }
    if (std::hypot(ux, uy) < deadSpeed) {
      for (int q = 0; q < g.rule.numPoints; ++q) deadArea += measureWeight(g.rule, q, geometry);
    }
  }
}

/// The length of the curve, or the area 2π r ds it sweeps when axisymmetric (the same on
/// every rank: the curve is replicated).
double curveArea(const Mesh& mesh, const BoundaryCurve& curve, Geometry geometry) {
  double area = 0.0;
  for (size_t s = 0; s < curve.segmentLength.size(); ++s) {
    const auto& a = mesh.coords[curve.nodes[s]];
    const auto& b = mesh.coords[curve.nodes[(s + 1) % curve.nodes.size()]];
    area += curve.segmentLength[s] * (geometry == Geometry::Axisymmetric ? M_PI * (a[0] + b[0]) : 1.0);
  }
  return area;
}

}  // namespace

bool Responses::reactionWeights(const std::string& name, const Mesh& mesh, const DofMap& dofMap, Geometry geometry,
                                Vector& c) const {
  for (const Response& r : m_responses) {
    if (r.name != name || (r.type != "Boundary Force" && r.type != "Mean Pressure")) continue;
    c.putScalar(0.0);
    const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(r.boundary));
    const double area = r.type == "Mean Pressure" ? curveArea(mesh, curve, geometry) : 1.0;
    auto view = c.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (size_t k = 0; k < curve.nodes.size(); ++k) {
      const LO n = dofMap.overlapIndex(curve.nodes[k]);
      if (n < 0 || n >= dofMap.numOwnedNodes()) continue;  // owned dofs are the overlap's first ones
      if (r.type == "Boundary Force") {
        view(dofMap.dof(n, r.component == "X" ? kUx : kUy), 0) = 1.0;
      } else {
        view(dofMap.dof(n, kUx), 0) = -curve.normals[k][0] / area;
        view(dofMap.dof(n, kUy), 0) = -curve.normals[k][1] / area;
      }
    }
    return true;
  }
  return false;
}

template <typename Scalar>
std::map<std::string, Scalar> Responses::evaluateAs(const Vector& xOwned, const Vector* dxOwned,
                                                    const SensitivityParameter* h, const Mesh& mesh,
                                                    const DofMap& dofMap, const Assembler& assembler,
                                                    const std::vector<ContactWall>& walls) const {
  std::map<std::string, Scalar> values;
  if (m_responses.empty()) return values;
  const Comm& comm = *dofMap.comm();
  const Geometry geometry = assembler.physics().kernel.geometry;
  const bool tangent = !std::is_same_v<Scalar, double>;

  // The reactions (unconstrained residual) and, for the tangent, their derivative.
  Vector reactions(dofMap.ownedMap()), dReactions(dofMap.ownedMap());
  Vector xOverlap(dofMap.overlapMap()), dxOverlap(dofMap.overlapMap());
  assembler.residual(xOwned, reactions, false);
  if (tangent) assembler.tangent(xOwned, dxOwned, h, dReactions, false);
  xOverlap.doImport(xOwned, *dofMap.importer(), Tpetra::INSERT);
  if (dxOwned) dxOverlap.doImport(*dxOwned, *dofMap.importer(), Tpetra::INSERT);
  const Workset R = reader(reactions, tangent ? &dReactions : nullptr);  // owned dofs: the overlap's first ones
  const Workset x = reader(xOverlap, dxOwned ? &dxOverlap : nullptr);
  auto at = [](const Workset& ws, LO d) { return valueAt<Scalar>(ws, d); };
  const MaterialParameters<Scalar> material = materialFor<Scalar>(assembler.physics().material, h);

  for (const Response& r : m_responses) {
    Scalar local = 0.0;
    if (r.type == "Boundary Force" || r.type == "Mean Pressure" || r.type == "Boundary Power") {
      const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(r.boundary));
      for (size_t k = 0; k < curve.nodes.size(); ++k) {
        const LO n = dofMap.overlapIndex(curve.nodes[k]);
        if (n < 0 || n >= dofMap.numOwnedNodes()) continue;  // each node once, by its owner
        const Scalar Rx = at(R, dofMap.dof(n, kUx)), Ry = at(R, dofMap.dof(n, kUy));
        if (r.type == "Boundary Force") local += r.component == "X" ? Rx : Ry;
        if (r.type == "Mean Pressure") local -= Rx * curve.normals[k][0] + Ry * curve.normals[k][1];
        if (r.type == "Boundary Power") local += Rx * at(x, dofMap.dof(n, kUx)) + Ry * at(x, dofMap.dof(n, kUy));
      }
      Scalar value = sumOverRanks(comm, local);
      if (r.type == "Mean Pressure") value /= curveArea(mesh, curve, geometry);
      values[r.name] = value;
    } else if (r.type == "Flow Rate") {
      // Q = ∫_Γ u·n dΓ with u linear on each segment: Q = Σ_k u_k·w_k, w_k = Σ_segments n_s ∫ N_k dΓ
      // (n_s the segment's outward normal; dΓ = 2πr ds when axisymmetric). Each node by its owner.
      const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(r.boundary));
      const size_t numNodes = curve.nodes.size();
      std::vector<std::array<double, 2>> w(numNodes, {0.0, 0.0});
      for (size_t sgm = 0; sgm < curve.segmentLength.size(); ++sgm) {
        const size_t a = sgm, b = (sgm + 1) % numNodes;
        const auto& normal = curve.segmentNormals[sgm];
        integrateSegment(mesh.coords[curve.nodes[a]], mesh.coords[curve.nodes[b]], geometry,
                         [&](double Na, double Nb, double ws) {
          for (int c = 0; c < 2; ++c) {
            w[a][c] += Na * ws * normal[c];
            w[b][c] += Nb * ws * normal[c];
          }
        });
      }
      for (size_t k = 0; k < numNodes; ++k) {
        const LO n = dofMap.overlapIndex(curve.nodes[k]);
        if (n < 0 || n >= dofMap.numOwnedNodes()) continue;
        local += w[k][0] * at(x, dofMap.dof(n, kUx)) + w[k][1] * at(x, dofMap.dof(n, kUy));
      }
      values[r.name] = sumOverRanks(comm, local);
    } else if (r.type == "Boundary Extent") {
      // Node positions do not depend on q: no derivative on a frozen shape (docs/theory.md §3).
      double extent = -std::numeric_limits<double>::max();
      for (const auto& e : mesh.boundary(r.boundary).edges)
        for (GO n : e) extent = std::max(extent, mesh.coords[n][r.component == "X" ? 0 : 1]);
      values[r.name] = extent;
    } else if (r.type == "Wall Gap") {
      // At the wall's downstream end (away from its Start Group): where the product leaves. Not the
      // largest gap: the separated surface is flat there, and a maximum over tied nodes has no
      // derivative.
      for (const ContactWall& wall : walls)
        if (wall.name() == r.boundary && !wall.releasedFreeSurface()) {
          values[r.name] = 0.0;  // its nodes never leave the tool
        } else if (wall.name() == r.boundary) {
          const BoundaryGroup& upstream = mesh.boundary(wall.upstreamGroup());
          bool firstIsUpstream = false;
          for (const auto& e : upstream.edges)
            firstIsUpstream = firstIsUpstream || e[0] == wall.curve().nodes.front() || e[1] == wall.curve().nodes.front();
          values[r.name] = wall.gap(firstIsUpstream ? wall.numNodes() - 1 : 0);
        }
    } else if (r.type == "Contact Length") {
      // The arc length along the tool from the wall's upstream end (its Start Group's end, else its
      // first node) to the last node of the contact zone that starts there (the separation point):
      // the zone's length, to within a segment. Piecewise constant in q: no derivative.
      if (tangent) continue;
      for (const ContactWall& wall : walls) {
        if (wall.name() != r.boundary) continue;
        const BoundaryCurve& curve = wall.curve();
        bool firstIsUpstream = true;
        if (!wall.upstreamGroup().empty() && mesh.hasBoundary(wall.upstreamGroup())) {
          firstIsUpstream = false;
          for (const auto& e : mesh.boundary(wall.upstreamGroup()).edges)
            firstIsUpstream = firstIsUpstream || e[0] == curve.nodes.front() || e[1] == curve.nodes.front();
        }
        double length = 0.0;
        for (int j = 0; j < wall.numNodes(); ++j) {
          const int k = firstIsUpstream ? j : wall.numNodes() - 1 - j;
          if (!wall.isActive(k)) break;
          length = firstIsUpstream ? curve.arcLength[k] : curve.arcLength.back() - curve.arcLength[k];
        }
        values[r.name] = length;
      }
    } else if (r.type == "Thickness Ratio" || r.type == "Shear Angle") {
      // The stream leaving through the group: its mean velocity ū = Σ_k u_k ∫N_k ds / ∫ds, its
      // thickness normal to ū  w = |Δx × ū| / |ū|  (Δx the chord between the group's ends; a chip's
      // outlet that the chip crosses at a slant is longer than the chip is thick), and the ratio
      // r = t / w (t the Reference Thickness; cutting: t/t_c, the chip ratio; mass balance makes it
      // the chip's speed over the cutting speed for a uniform stream). Shear Angle: the thin shear
      // plane's kinematics, tan φ = r cos α / (1 − r sin α) (α the Rake Angle), in degrees.
      const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(r.boundary));
      const size_t numNodes = curve.nodes.size();
      std::vector<double> w(numNodes, 0.0);
      for (size_t sgm = 0; sgm < curve.segmentLength.size(); ++sgm) {
        w[sgm] += 0.5 * curve.segmentLength[sgm];
        w[(sgm + 1) % numNodes] += 0.5 * curve.segmentLength[sgm];
      }
      Scalar ux = 0.0, uy = 0.0;
      for (size_t k = 0; k < numNodes; ++k) {
        const LO n = dofMap.overlapIndex(curve.nodes[k]);
        if (n < 0 || n >= dofMap.numOwnedNodes()) continue;
        ux += w[k] * at(x, dofMap.dof(n, kUx));
        uy += w[k] * at(x, dofMap.dof(n, kUy));
      }
      ux = sumOverRanks(comm, ux);
      uy = sumOverRanks(comm, uy);
      const auto& a = mesh.coords[curve.nodes.front()];
      const auto& b = mesh.coords[curve.nodes.back()];
      Scalar cross = (b[0] - a[0]) * uy - (b[1] - a[1]) * ux;
      if (cross < 0.0) cross = -cross;
      const Scalar ratio = r.referenceThickness * std::sqrt(ux * ux + uy * uy) / cross;
      if (r.type == "Thickness Ratio") {
        values[r.name] = ratio;
      } else {
        const double alpha = r.rakeAngle * M_PI / 180.0;
        values[r.name] = std::atan2(ratio * std::cos(alpha), 1.0 - ratio * std::sin(alpha)) * (180.0 / M_PI);
      }
    } else if (r.type == "Plastic Power" || r.type == "Stabilization Power" || r.type == "Dead Zone") {
      if (tangent && r.type == "Dead Zone") continue;  // piecewise constant in x: no derivative
      Scalar plastic, stabilization;
      double dead;
      cellIntegrals(x, mesh, dofMap, assembler.physics(), material, r.fraction * r.referenceSpeed, plastic,
                    stabilization, dead);
      if (r.type == "Dead Zone") values[r.name] = sumOverRanks(comm, dead);
      else values[r.name] = sumOverRanks(comm, r.type == "Plastic Power" ? plastic : stabilization);
    } else if (r.type == "Wall Force" || r.type == "Friction Power" || r.type == "Penalty Power") {
      // Node by node over the walls (each node by its owner), from the wall's part of the momentum
      // residual R_k = α_n (u·n) n + g t (normal penalty and friction):
      //   Wall Force: Σ R_k on the named wall, the force the material exerts on it (a tool's
      //     cutting (X) and thrust (Y) forces; by the balance of the whole body, the sum of the
      //     Boundary Forces on the velocity-driven groups when the rest is traction-free);
      //   Friction Power: Σ g_k u_t,k;  Penalty Power: Σ (normal part of R_k)·u = α_n (u·n)².
      for (size_t w = 0; w < walls.size(); ++w) {
        const ContactWall& wall = walls[w];
        if (r.type == "Wall Force" && wall.name() != r.boundary) continue;
        const FrictionParameters<Scalar> fp = frictionFor<Scalar>(wall, static_cast<int>(w), h);
        for (int k = 0; k < wall.numNodes(); ++k) {
          const LO n = dofMap.overlapIndex(wall.curve().nodes[k]);
          if (n < 0 || n >= dofMap.numOwnedNodes()) continue;
          auto pressure = [&](int j) {
            return j < 0 ? Scalar(0.0) : at(x, dofMap.dof(dofMap.overlapIndex(wall.curve().nodes[j]), kP));
          };
          const Scalar u[2] = {at(x, dofMap.dof(n, kUx)), at(x, dofMap.dof(n, kUy))};
          const Scalar p[3] = {pressure(wall.previous(k)), at(x, dofMap.dof(n, kP)), pressure(wall.next(k))};
          Scalar Rk[2] = {0.0, 0.0};
          wall.addNodeResidual(k, fp, u, p, Rk);
          if (r.type == "Wall Force") {
            local += r.component == "X" ? Rk[0] : Rk[1];
            continue;
          }
          const auto& nk = wall.curve().normals[k];
          const Scalar g = wall.tangentialForce(k, fp, u, p);
          if (r.type == "Friction Power") local += g * (-nk[1] * u[0] + nk[0] * u[1]);
          else local += (Rk[0] + g * nk[1]) * u[0] + (Rk[1] - g * nk[0]) * u[1];
        }
      }
      values[r.name] = sumOverRanks(comm, local);
    }
  }
  return values;
}

std::map<std::string, double> Responses::evaluate(const Vector& xOwned, const Mesh& mesh, const DofMap& dofMap,
                                                  const Assembler& assembler,
                                                  const std::vector<ContactWall>& walls) const {
  return evaluateAs<double>(xOwned, nullptr, nullptr, mesh, dofMap, assembler, walls);
}

std::map<std::string, double> Responses::derivatives(const Vector& xOwned, const Vector& dxOwned,
                                                     const SensitivityParameter& h, const Mesh& mesh,
                                                     const DofMap& dofMap, const Assembler& assembler,
                                                     const std::vector<ContactWall>& walls) const {
  std::map<std::string, double> d;
  for (const auto& [name, value] : evaluateAs<TangentFad>(xOwned, &dxOwned, &h, mesh, dofMap, assembler, walls))
    d[name] = value.dx(0);
  return d;
}

}  // namespace flowform
