#include "flowform/Responses.hpp"

#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/BoundaryCurve.hpp"
#include "flowform/InputError.hpp"
#include "flowform/kernels/FlowResidual.hpp"

namespace flowform {

Teuchos::RCP<const Teuchos::ParameterList> Responses::validParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Response"));
  Teuchos::setStringToIntegralParameter<int>(
      "Type", "Boundary Force", "what to compute (see include/flowform/Responses.hpp)",
      Teuchos::tuple<std::string>("Boundary Force", "Mean Pressure", "Boundary Power", "Plastic Power",
                                  "Friction Power", "Dead Zone"),
      valid.get());
  valid->set("Boundary", "", "boundary group (Boundary Force, Mean Pressure, Boundary Power)");
  Teuchos::setStringToIntegralParameter<int>("Component", "X", "force component (Boundary Force)",
                                             Teuchos::tuple<std::string>("X", "Y"), valid.get());
  valid->set("Fraction", 0.01, "Dead Zone: |u| below this fraction of the reference speed",
             Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(0.0, 1.0)));
  valid->set("Reference Speed", 1.0, "Dead Zone: the process speed (e.g. the ram's) [velocity]");
  return valid;
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
    Response resp{name, r.get<std::string>("Type"), r.get<std::string>("Boundary"), r.get<std::string>("Component"),
                  r.get<double>("Fraction"), r.get<double>("Reference Speed")};
    const bool needsBoundary = resp.type == "Boundary Force" || resp.type == "Mean Pressure" || resp.type == "Boundary Power";
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

/// ∫ 2μ D:D dΩ (plastic power) and the dead-zone area over this rank's cells.
void cellIntegrals(const Vector& xOverlap, const Mesh& mesh, const DofMap& dofMap, const FlowPhysics& physics,
                   double deadSpeed, double& plasticPower, double& deadArea) {
  auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const int npc = nodesPerCell(mesh.cellType);
  const Geometry geometry = physics.kernel.geometry;
  CellQuadrature rule, centroid;
  std::array<double, 2> xy[kMaxNodesPerCell];
  double dofs[kDofsPerNode * kMaxNodesPerCell];
  plasticPower = deadArea = 0.0;
  for (size_t k = 0; k < dofMap.cells().size(); ++k) {
    const LO* nodes = &dofMap.cellNodes()[npc * k];
    for (int a = 0; a < npc; ++a) {
      xy[a] = mesh.coords[dofMap.overlapNodes()[nodes[a]]];
      for (int c = 0; c < kDofsPerNode; ++c) dofs[kDofsPerNode * a + c] = x(kDofsPerNode * nodes[a] + c, 0);
    }
    computeCellQuadrature(mesh.cellType, xy, 2, rule);
    computeCellQuadrature(mesh.cellType, xy, 1, centroid);
    for (int q = 0; q < rule.numPoints; ++q) {
      const auto d = strainRateAt(rule, q, geometry, dofs);
      const double mu = viscosity(regularizedStrainRate(d.ddot(), physics.material), physics.material);
      plasticPower += measureWeight(rule, q, geometry) * 2.0 * mu * d.ddot();
    }
    double ux = 0.0, uy = 0.0;
    for (int a = 0; a < npc; ++a) {
      ux += centroid.N[0][a] * dofs[kDofsPerNode * a + kUx];
      uy += centroid.N[0][a] * dofs[kDofsPerNode * a + kUy];
    }
    if (std::hypot(ux, uy) < deadSpeed) {
      for (int q = 0; q < rule.numPoints; ++q) deadArea += measureWeight(rule, q, geometry);
    }
  }
}

}  // namespace

std::map<std::string, double> Responses::evaluate(const Vector& xOwned, const Mesh& mesh, const DofMap& dofMap,
                                                  const Assembler& assembler,
                                                  const std::vector<ContactWall>& walls) const {
  std::map<std::string, double> values;
  if (m_responses.empty()) return values;
  const Comm& comm = *dofMap.comm();
  const Geometry geometry = assembler.physics().kernel.geometry;

  Vector reactions(dofMap.ownedMap()), xOverlap(dofMap.overlapMap());
  assembler.residual(xOwned, reactions, false);
  xOverlap.doImport(xOwned, *dofMap.importer(), Tpetra::INSERT);
  auto R = reactions.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);

  for (const Response& r : m_responses) {
    double local = 0.0;
    if (r.type == "Boundary Force" || r.type == "Mean Pressure" || r.type == "Boundary Power") {
      const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(r.boundary));
      for (size_t k = 0; k < curve.nodes.size(); ++k) {
        const LO n = dofMap.overlapIndex(curve.nodes[k]);
        if (n < 0 || n >= dofMap.numOwnedNodes()) continue;  // each node once, by its owner
        const double Rx = R(kDofsPerNode * n + kUx, 0), Ry = R(kDofsPerNode * n + kUy, 0);
        if (r.type == "Boundary Force") local += r.component == "X" ? Rx : Ry;
        if (r.type == "Mean Pressure") local -= Rx * curve.normals[k][0] + Ry * curve.normals[k][1];
        if (r.type == "Boundary Power") local += Rx * x(kDofsPerNode * n + kUx, 0) + Ry * x(kDofsPerNode * n + kUy, 0);
      }
      double value = sumOverRanks(comm, local);
      if (r.type == "Mean Pressure") {
        double area = 0.0;  // the same on every rank: the curve is replicated
        for (size_t s = 0; s < curve.segmentLength.size(); ++s) {
          const auto& a = mesh.coords[curve.nodes[s]];
          const auto& b = mesh.coords[curve.nodes[(s + 1) % curve.nodes.size()]];
          area += curve.segmentLength[s] * (geometry == Geometry::Axisymmetric ? M_PI * (a[0] + b[0]) : 1.0);
        }
        value /= area;
      }
      values[r.name] = value;
    } else if (r.type == "Plastic Power" || r.type == "Dead Zone") {
      double plastic, dead;
      cellIntegrals(xOverlap, mesh, dofMap, assembler.physics(), r.fraction * r.referenceSpeed, plastic, dead);
      values[r.name] = sumOverRanks(comm, r.type == "Plastic Power" ? plastic : dead);
    } else if (r.type == "Friction Power") {
      for (const ContactWall& wall : walls)
        for (int k = 0; k < wall.numNodes(); ++k) {
          const LO n = dofMap.overlapIndex(wall.curve().nodes[k]);
          if (n < 0 || n >= dofMap.numOwnedNodes()) continue;
          auto pressure = [&](int j) { return j < 0 ? 0.0 : x(kDofsPerNode * dofMap.overlapIndex(wall.curve().nodes[j]) + kP, 0); };
          const double u[2] = {x(kDofsPerNode * n + kUx, 0), x(kDofsPerNode * n + kUy, 0)};
          const double p[3] = {pressure(wall.previous(k)), x(kDofsPerNode * n + kP, 0), pressure(wall.next(k))};
          const auto& nk = wall.curve().normals[k];
          const double ut = -nk[1] * u[0] + nk[0] * u[1];
          local += wall.tangentialForce(k, u, p) * ut;
        }
      values[r.name] = sumOverRanks(comm, local);
    }
  }
  return values;
}

}  // namespace flowform
