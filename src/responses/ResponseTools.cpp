#include "flowform/responses/ResponseContext.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/assembly/CellMaterial.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/responses/CellPowers.hpp"
#include "flowform/responses/ShearAngle.hpp"

namespace flowform {

double sumOverRanks(const Comm& comm, double local) {
  double global = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

TangentFad sumOverRanks(const Comm& comm, const TangentFad& local) {
  return dual<TangentFad>(sumOverRanks(comm, local.val()), sumOverRanks(comm, local.dx(0)));
}

GradientFad sumOverRanks(const Comm& comm, const GradientFad& local) {
  GradientFad global(local);
  global.val() = sumOverRanks(comm, local.val());
  return global;
}

double curveArea(const Mesh& mesh, const BoundaryCurve& curve, Geometry geometry) {
  double area = 0.0;
  for (size_t s = 0; s < curve.segmentLength.size(); ++s) {
    const auto& a = mesh.coords[curve.nodes[s]];
    const auto& b = mesh.coords[curve.nodes[(s + 1) % curve.nodes.size()]];
    area += curve.segmentLength[s] * (geometry == Geometry::Axisymmetric ? M_PI * (a[0] + b[0]) : 1.0);
  }
  return area;
}

const ContactWall& wallNamed(const std::vector<ContactWall>& walls, const std::string& name) {
  const auto wall = std::find_if(walls.begin(), walls.end(), [&](const ContactWall& w) { return w.name() == name; });
  if (wall == walls.end()) throw InputError("'" + name + "' is not a Contact Wall");
  return *wall;
}

Workset vectorReader(const Vector& x, const Vector* dx) {
  Workset ws;
  ws.x = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  if (dx) {
    ws.dx = dx->getLocalViewHost(Tpetra::Access::ReadOnly);
    ws.hasDirection = true;
  }
  return ws;
}

namespace {

/// Cell k's plastic power ∫_K 2μ D:D and stabilization power τ_K ∫_K ∇p·(∇p − f), added to
/// `plastic` and `stabilization`, from the cell's gathered values (u_x, u_y, p per node) and its
/// material (at the cell's temperature).
template <typename Scalar>
void addCellPowers(const CellGeometry& g, int npc, const FlowPhysics& physics, const MaterialParameters<Scalar>& cell,
                   const Scalar* values, Scalar& plastic, Scalar& stabilization) {
  const Geometry geometry = physics.kernel.geometry;
  const Scalar tau = stabilizationTau(physics.kernel.beta, g.diameter, centroidViscosity(g.centroid, geometry, cell, values));
  for (int q = 0; q < g.rule.numPoints; ++q) {
    const auto d = strainRateAt(g.rule, q, geometry, values);
    const Scalar mu = viscosity(regularizedStrainRate(d.ddot(), cell), cell);
    const double w = measureWeight(g.rule, q, geometry);
    plastic += w * 2.0 * mu * d.ddot();
    Scalar px = 0.0, py = 0.0;
    for (int a = 0; a < npc; ++a) {
      px += g.rule.dNdx[q][a] * values[EqualOrderLayout::index(a, kP)];
      py += g.rule.dNdy[q][a] * values[EqualOrderLayout::index(a, kP)];
    }
    stabilization += w * tau * (px * (px - physics.kernel.bodyForce[0]) + py * (py - physics.kernel.bodyForce[1]));
  }
}

/// The area (volume) of cell k when |u| at its centroid is below deadSpeed, else 0 (values only).
double deadCellArea(const Workset& x, const CellGeometry& g, int npc, const LO* dofs, Geometry geometry, double deadSpeed) {
  double ux = 0.0, uy = 0.0;
  for (int a = 0; a < npc; ++a) {
    ux += g.centroid.N[0][a] * x.x(dofs[EqualOrderLayout::index(a, kUx)], 0);
    uy += g.centroid.N[0][a] * x.x(dofs[EqualOrderLayout::index(a, kUy)], 0);
  }
  double area = 0.0;
  if (std::hypot(ux, uy) < deadSpeed)
    for (int q = 0; q < g.rule.numPoints; ++q) area += measureWeight(g.rule, q, geometry);
  return area;
}

}  // namespace

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
  // A law that reads a Temperature or Strain field: the law at each cell's values, as the flow
  // kernel has it (assembly/CellMaterial.hpp).
  const LawFieldComponents lawFields = lawFieldComponents(dofMap, physics);
  for (size_t k = 0; k < dofMap.cells().size(); ++k) {
    computeCellGeometry(mesh, dofMap.cells()[k], geometry, g);
    dofMap.cellDofs(k, dofs);
    gather(x, dofs, EqualOrderLayout::numDofs(npc), values);
    addCellPowers(g, npc, physics, cellMaterial(x, dofMap, k, g, material, lawFields), values, plasticPower,
                  stabilizationPower);
    deadArea += deadCellArea(x, g, npc, dofs, geometry, deadSpeed);
  }
}

/// The gradient: each cell differentiated by its own dofs (a fixed-size Fad over the cell's flow
/// dofs and its temperatures and strains), its derivatives added into the totals' components — the
/// cost of one Jacobian assembly, not of n-component arithmetic in every cell.
template <>
void cellIntegrals<GradientFad>(const Workset& x, const Mesh& mesh, const DofMap& dofMap, const FlowPhysics& physics,
                                const MaterialParameters<GradientFad>& material, double deadSpeed,
                                GradientFad& plasticPower, GradientFad& stabilizationPower, double& deadArea) {
  constexpr int kFlow = EqualOrderLayout::numDofs(kMaxNodesPerCell);
  constexpr int kCell = kFlow + 2 * kMaxNodesPerCell;
  using CellFad = Sacado::Fad::SFad<double, kCell>;
  const int npc = dofMap.nodesPerCell();
  const int nFlow = EqualOrderLayout::numDofs(npc);
  const Geometry geometry = physics.kernel.geometry;
  CellGeometry g;
  LO dofs[kCell];
  CellFad values[kFlow], temperatures[kMaxNodesPerCell], strains[kMaxNodesPerCell];
  plasticPower = GradientFad(x.gradientSize, 0.0);
  stabilizationPower = GradientFad(x.gradientSize, 0.0);
  deadArea = 0.0;
  MaterialParameters<CellFad> base;  // the material's values: its parameters are not seeded here
  base.law = material.law;
  for (int i = 0; i < kMaxMaterialParameters; ++i) base.values[i] = material.values[i].val();
  base.cutoff = material.cutoff.val();
  const LawFieldComponents lawFields = lawFieldComponents(dofMap, physics);
  // The cell's nodal values of the field in `component`, seeded after the n dofs seeded so far.
  auto seedField = [&](int component, CellFad* nodal, int& n, size_t k) {
    dofMap.cellDofs(k, &component, 1, dofs + n);
    for (int a = 0; a < npc; ++a) nodal[a] = CellFad(kCell, n + a, x.x(dofs[n + a], 0));
    n += npc;
  };
  for (size_t k = 0; k < dofMap.cells().size(); ++k) {
    computeCellGeometry(mesh, dofMap.cells()[k], geometry, g);
    dofMap.cellDofs(k, dofs);
    int n = nFlow;
    for (int i = 0; i < nFlow; ++i) values[i] = CellFad(kCell, i, x.x(dofs[i], 0));
    if (lawFields.temperature >= 0) seedField(lawFields.temperature, temperatures, n, k);
    if (lawFields.strain >= 0) seedField(lawFields.strain, strains, n, k);
    const MaterialParameters<CellFad> cell =
        lawFields.any() ? materialAtCellFields(g, base, lawFields.temperature >= 0 ? temperatures : nullptr,
                                               lawFields.strain >= 0 ? strains : nullptr, lawFields.strainField)
                        : base;
    CellFad plastic = 0.0, stabilization = 0.0;
    addCellPowers(g, npc, physics, cell, values, plastic, stabilization);
    plasticPower.val() += plastic.val();
    stabilizationPower.val() += stabilization.val();
    for (int i = 0; i < n; ++i) {
      if (dofs[i] < 0) continue;
      plasticPower.fastAccessDx(x.gradientOffset + dofs[i]) += plastic.dx(i);
      stabilizationPower.fastAccessDx(x.gradientOffset + dofs[i]) += stabilization.dx(i);
    }
    deadArea += deadCellArea(x, g, npc, dofs, geometry, deadSpeed);
  }
}

template void cellIntegrals<double>(const Workset&, const Mesh&, const DofMap&, const FlowPhysics&,
                                    const MaterialParameters<double>&, double, double&, double&, double&);
template void cellIntegrals<TangentFad>(const Workset&, const Mesh&, const DofMap&, const FlowPhysics&,
                                        const MaterialParameters<TangentFad>&, double, TangentFad&, TangentFad&,
                                        double&);

void declareBoundary(Teuchos::ParameterList& list, const std::string& doc) { list.set("Boundary", "", doc); }

void declareComponent(Teuchos::ParameterList& list, const std::string& doc) {
  Teuchos::setStringToIntegralParameter<int>("Component", "X", doc, Teuchos::tuple<std::string>("X", "Y"), &list);
}

void declareReferenceThickness(Teuchos::ParameterList& list) {
  list.set("Reference Thickness", 1.0,
           "the thickness t the stream had upstream (cutting: the uncut thickness) [length]", positive());
}

void ShearAngle::declareParameters(Teuchos::ParameterList& list) {
  ThicknessRatio::declareParameters(list);
  list.set("Rake Angle", 0.0, "the tool's rake angle α [degrees]", inRange(-89.0, 89.0));
}

void DeadZone::declareParameters(Teuchos::ParameterList& list) {
  list.set("Fraction", 0.01, "|u| below this fraction of the reference speed (0 would count no cell)",
           inRange(0.0, 1.0, true, false));
  list.set("Reference Speed", 1.0, "the process speed (e.g. the ram's) [velocity]", positive());
}

}  // namespace flowform
