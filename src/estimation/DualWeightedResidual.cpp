#include "flowform/estimation/DualWeightedResidual.hpp"

#include <cmath>

#include <Teuchos_CommHelpers.hpp>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/contact/WallStates.hpp"

namespace flowform {

namespace {

using View = decltype(std::declval<const Vector&>().getLocalViewHost(Tpetra::Access::ReadOnly));

/// Recovered nodal gradients of every field of z (overlap vectors gx, gy: ∂z/∂x, ∂z/∂y per
/// dof): the area-weighted average of the gradients of z_h over the cells at the node.
void recoverGradients(const Assembler& assembler, const Vector& zOverlap, Vector& gxOverlap, Vector& gyOverlap) {
  const DofMap& dofMap = assembler.dofMap();
  const Mesh& mesh = assembler.mesh();
  const int npc = dofMap.nodesPerCell();
  Vector gx(dofMap.overlapMap()), gy(dofMap.overlapMap()), area(dofMap.overlapMap());
  {
    auto z = zOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto vx = gx.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto vy = gy.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto va = area.getLocalViewHost(Tpetra::Access::ReadWrite);
    CellGeometry g;
    LO dofs[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
    for (size_t k = 0; k < dofMap.cells().size(); ++k) {
      computeCellGeometry(mesh, dofMap.cells()[k], Geometry::PlaneStrain, g);  // plain area weights
      dofMap.cellDofs(k, dofs);
      const double w = g.centroid.weight[0];
      for (int f = 0; f < EqualOrderLayout::kFieldsPerNode; ++f) {
        double dx = 0.0, dy = 0.0;
        for (int a = 0; a < npc; ++a) {
          const double za = z(dofs[EqualOrderLayout::index(a, f)], 0);
          dx += g.centroid.dNdx[0][a] * za;
          dy += g.centroid.dNdy[0][a] * za;
        }
        for (int a = 0; a < npc; ++a) {
          const LO d = dofs[EqualOrderLayout::index(a, f)];
          vx(d, 0) += w * dx;
          vy(d, 0) += w * dy;
          va(d, 0) += w;
        }
      }
    }
  }
  // Sum over the ranks' cells on the owned dofs, divide, and bring back to the overlap.
  Vector ox(dofMap.ownedMap()), oy(dofMap.ownedMap()), oa(dofMap.ownedMap());
  ox.doExport(gx, *dofMap.exporter(), Tpetra::ADD);
  oy.doExport(gy, *dofMap.exporter(), Tpetra::ADD);
  oa.doExport(area, *dofMap.exporter(), Tpetra::ADD);
  {
    auto vx = ox.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto vy = oy.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto va = oa.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (size_t i = 0; i < vx.extent(0); ++i) {
      vx(i, 0) /= va(i, 0);
      vy(i, 0) /= va(i, 0);
    }
  }
  gxOverlap.doImport(ox, *dofMap.importer(), Tpetra::INSERT);
  gyOverlap.doImport(oy, *dofMap.importer(), Tpetra::INSERT);
}

/// Removes from the velocity weight (w_x, w_y) of an edge what the constraints at both of its
/// ends forbid: all of it where both are held fully (a prescribed velocity), the constrained
/// direction a where one is a Single constraint a·u = b (a symmetry line) and the other is held.
void constrainWeight(const NodeConstraint& a, const NodeConstraint& b, double& wx, double& wy) {
  using Kind = NodeConstraint::Kind;
  if (a.kind == Kind::None || b.kind == Kind::None) return;
  if (a.kind == Kind::Full && b.kind == Kind::Full) {
    wx = wy = 0.0;
    return;
  }
  const NodeConstraint& single = a.kind == Kind::Single ? a : b;
  const double an = wx * single.a[0] + wy * single.a[1];
  wx -= an * single.a[0];
  wy -= an * single.a[1];
}

/// The adjoint's weights w_e = (G_a − G_b)·(x_b − x_a)/8 of the edge between overlap nodes
/// a and b (at xa, xb), per field, with the constraints applied.
void edgeWeights(const DofMap& dofMap, const std::vector<NodeConstraint>& constraints, const View& gx, const View& gy,
                 LO a, LO b, const std::array<double, 2>& xa, const std::array<double, 2>& xb, double* w) {
  const double d[2] = {xb[0] - xa[0], xb[1] - xa[1]};
  for (int f = 0; f < EqualOrderLayout::kFieldsPerNode; ++f) {
    const LO da = dofMap.dof(a, f), db = dofMap.dof(b, f);
    w[f] = ((gx(da, 0) - gx(db, 0)) * d[0] + (gy(da, 0) - gy(db, 0)) * d[1]) / 8.0;
  }
  constrainWeight(constraints[a], constraints[b], w[kUx], w[kUy]);
}

/// −Σ over this rank's active wall segments of w_e · ∫_e φ_e t W ds: the contact traction t,
/// the nodal penalty and friction forces spread over each node's tributary length (linear
/// along the segment), against the segment's edge functions. The cells' part does not see it.
double contactPart(const Assembler& assembler, const std::vector<ContactWall>& walls, const Vector& xOwned,
                   const View& gx, const View& gy) {
  const DofMap& dofMap = assembler.dofMap();
  const Mesh& mesh = assembler.mesh();
  const Geometry geometry = assembler.physics().kernel.geometry;
  const auto& constraints = assembler.boundaryConditions().constraints();
  double eta = 0.0;
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (const ContactWall& wall : walls) {
    wallValues(wall, dofMap, xOwned, p, u);  // collective
    const int n = wall.numNodes();
    // Nodal forces and tributary areas, then tractions.
    std::vector<std::array<double, 2>> t(n, {0.0, 0.0});
    for (int k = 0; k < n; ++k) {
      if (!wall.isActive(k)) continue;
      auto pressure = [&](int j) { return j < 0 ? 0.0 : p[j]; };
      const double pk[3] = {pressure(wall.previous(k)), p[k], pressure(wall.next(k))};
      double R[2] = {0.0, 0.0};
      wall.addNodeResidual(k, u[k].data(), pk, R);
      double area = 0.0;
      for (int j : {wall.previous(k), wall.next(k)}) {
        if (j < 0 || !wall.isActive(j)) continue;
        integrateSegment(mesh.coords[wall.curve().nodes[k]], mesh.coords[wall.curve().nodes[j]], geometry,
                         [&](double Nk, double, double w) { area += w * Nk; });
      }
      if (area > 0.0) t[k] = {R[0] / area, R[1] / area};
    }
    for (int k = 0; k < n; ++k) {
      const int j = wall.next(k);
      if (j < 0 || !wall.isActive(k) || !wall.isActive(j)) continue;
      const LO a = dofMap.overlapIndex(wall.curve().nodes[k]), b = dofMap.overlapIndex(wall.curve().nodes[j]);
      if (a < 0 || b < 0 || a >= dofMap.numOwnedNodes()) continue;  // each segment once, by the owner of k
      const auto& xa = mesh.coords[wall.curve().nodes[k]];
      const auto& xb = mesh.coords[wall.curve().nodes[j]];
      double w[EqualOrderLayout::kFieldsPerNode];
      edgeWeights(dofMap, constraints, gx, gy, a, b, xa, xb, w);
      integrateSegment(xa, xb, geometry, [&](double Na, double Nb, double ws) {
        const double phi = 4.0 * Na * Nb;
        for (int c = 0; c < 2; ++c) eta -= ws * phi * w[c == 0 ? kUx : kUy] * (Na * t[k][c] + Nb * t[j][c]);
      });
    }
  }
  return eta;
}

/// −Σ_e w_e · R_K(u_h; φ_e) over this rank's triangles: the residual of cell K against the
/// edge functions φ_e = 4 N_a N_b of its three edges, weighted by the adjoint's w_e.
double weightedResidual(const Assembler& assembler, const Vector& xOverlap, const Vector& zOverlap,
                        const Vector& gxOverlap, const Vector& gyOverlap) {
  const DofMap& dofMap = assembler.dofMap();
  const Mesh& mesh = assembler.mesh();
  const FlowPhysics& physics = assembler.physics();
  const Geometry geometry = physics.kernel.geometry;
  const auto& constraints = assembler.boundaryConditions().constraints();
  auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto gx = gxOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto gy = gyOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto z = zOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const double fx = physics.kernel.bodyForce[0], fy = physics.kernel.bodyForce[1];
  double eta = 0.0;
  CellGeometry g;
  CellQuadrature rule;  // degree 2: ∇φ_e is linear, s and p are P1 (axisymmetric: approximate)
  constexpr int N = EqualOrderLayout::numDofs(3);
  LO dofs[N];
  double values[N];
  for (size_t k = 0; k < dofMap.cells().size(); ++k) {
    computeCellGeometry(mesh, dofMap.cells()[k], geometry, g);
    computeCellQuadrature(CellType::Triangle3, g.xy, 2, rule);
    const LO* nodes = dofMap.cellNodes(k);
    dofMap.cellDofs(k, dofs);
    for (int i = 0; i < N; ++i) values[i] = x(dofs[i], 0);
    const double muK = centroidViscosity(g.centroid, geometry, physics.material, values);
    const double tau = stabilizationTau(physics.kernel.beta, g.diameter, muK);
    // The stabilization's consistency error, S(u_h)(z_h) = −τ ∫ ∇z_p·(∇p − f): the discrete
    // residual R_h = R + S vanishes against z_h, so −R(u_h)(z) = −R(u_h)(z⁺ − z_h) + S(u_h)(z_h).
    for (int q = 0; q < g.rule.numPoints; ++q) {
      double px = 0.0, py = 0.0, zx = 0.0, zy = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double pc = values[EqualOrderLayout::index(c, kP)], zc = z(dofs[EqualOrderLayout::index(c, kP)], 0);
        px += g.rule.dNdx[q][c] * pc;
        py += g.rule.dNdy[q][c] * pc;
        zx += g.rule.dNdx[q][c] * zc;
        zy += g.rule.dNdy[q][c] * zc;
      }
      eta -= measureWeight(g.rule, q, geometry) * tau * (zx * (px - fx) + zy * (py - fy));
    }
    for (int e = 0; e < 3; ++e) {
      const int a = e, b = (e + 1) % 3;
      double w[EqualOrderLayout::kFieldsPerNode];
      edgeWeights(dofMap, constraints, gx, gy, nodes[a], nodes[b], g.xy[a], g.xy[b], w);
      // R_K(u_h; φ_e e_f) at the rule's points.
      for (int q = 0; q < rule.numPoints; ++q) {
        const double wq = measureWeight(rule, q, geometry);
        const StrainRate<double> D = strainRateAt(rule, q, geometry, values);
        const double twoMu = 2.0 * viscosity(regularizedStrainRate(D.ddot(), physics.material), physics.material);
        double p = 0.0, px = 0.0, py = 0.0;
        for (int c = 0; c < 3; ++c) {
          const double pc = values[EqualOrderLayout::index(c, kP)];
          p += rule.N[q][c] * pc;
          px += rule.dNdx[q][c] * pc;
          py += rule.dNdy[q][c] * pc;
        }
        const double Na = rule.N[q][a], Nb = rule.N[q][b];
        const double phi = 4.0 * Na * Nb;
        const double phix = 4.0 * (rule.dNdx[q][a] * Nb + Na * rule.dNdx[q][b]);
        const double phiy = 4.0 * (rule.dNdy[q][a] * Nb + Na * rule.dNdy[q][b]);
        const double invR = geometry == Geometry::Axisymmetric ? 1.0 / rule.x[q] : 0.0;
        const double rx = twoMu * D.xx * phix + twoMu * D.xy * phiy + twoMu * D.tt * phi * invR -
                          p * (phix + phi * invR) - phi * fx;
        const double ry = twoMu * D.xy * phix + twoMu * D.yy * phiy - p * phiy - phi * fy;
        // The continuous problem's residual: no stabilization term (it enters below).
        const double rp = -phi * D.divergence();
        eta -= wq * (w[kUx] * rx + w[kUy] * ry + w[kP] * rp);
      }
    }
  }
  // The prescribed tractions against the edge functions of their edges: R −= ∫ φ_e t̄ ds.
  const auto& overlapNodes = dofMap.overlapNodes();
  for (const TractionEdge& te : assembler.boundaryConditions().tractionEdges()) {
    const auto& xa = mesh.coords[overlapNodes[te.nodes[0]]];
    const auto& xb = mesh.coords[overlapNodes[te.nodes[1]]];
    double w[EqualOrderLayout::kFieldsPerNode];
    edgeWeights(dofMap, constraints, gx, gy, te.nodes[0], te.nodes[1], xa, xb, w);
    integrateSegment(xa, xb, geometry, [&](double Na, double Nb, double ws) {
      eta += ws * 4.0 * Na * Nb * (w[kUx] * te.traction[0] + w[kUy] * te.traction[1]);
    });
  }
  return eta;
}

}  // namespace

std::map<std::string, double> dualWeightedResidual(FlowModel& model, const Vector& x, const Responses& responses,
                                                   const Mesh& mesh, const std::vector<ContactWall>& walls) {
  std::map<std::string, double> estimates;
  if (mesh.cellType != CellType::Triangle3) return estimates;
  const Assembler& assembler = model.assembler();
  const DofMap& dofMap = assembler.dofMap();
  const Geometry geometry = assembler.physics().kernel.geometry;
  auto unconstrained = assembler.createJacobian();
  bool factored = false;
  Vector c(dofMap.ownedMap()), gradient(dofMap.ownedMap()), z(dofMap.ownedMap());
  Vector xOverlap(dofMap.overlapMap()), zOverlap(dofMap.overlapMap());
  Vector gxOverlap(dofMap.overlapMap()), gyOverlap(dofMap.overlapMap());
  xOverlap.doImport(x, *dofMap.importer(), Tpetra::INSERT);
  for (const std::string& name : responses.names()) {
    if (!responses.reactionWeights(name, mesh, dofMap, geometry, c)) continue;
    if (!factored) {
      assembler.unconstrainedJacobian(x, *unconstrained);
      model.restartLinearization();  // the exact K_t at x
      model.computeJacobian(x);
      factored = true;
    }
    // ∂φ/∂x = J_uncᵀ c, then K_tᵀ z = ∂φ/∂x.
    unconstrained->apply(c, gradient, Teuchos::TRANS);
    model.solveTranspose(gradient, z);
    // The adjoint lives in the test space: K_tᵀ's constraint columns leave junk at the held
    // velocity components (z_c = g_c − J_fcᵀ z_f); the continuous z vanishes there.
    assembler.boundaryConditions().imposeOnSolution(z, true);
    // The weights come from ζ = c − z, the adjoint with the response's Dirichlet data (c on
    // the group's held components, 0 on the others' held ones): z carries c's one-element layer
    // next to the group, ζ is smooth there, so only ζ can be reconstructed. With it
    // φ(u) − φ(u_h) ≈ R(u_h)(ζ⁺ − ζ_h) − S(u_h)(ζ_h): the sign of the functions below flipped.
    z.update(1.0, c, -1.0);
    zOverlap.doImport(z, *dofMap.importer(), Tpetra::INSERT);
    gxOverlap.putScalar(0.0);
    gyOverlap.putScalar(0.0);
    recoverGradients(assembler, zOverlap, gxOverlap, gyOverlap);
    double local = weightedResidual(assembler, xOverlap, zOverlap, gxOverlap, gyOverlap);
    local += contactPart(assembler, walls, x, gxOverlap.getLocalViewHost(Tpetra::Access::ReadOnly),
                         gyOverlap.getLocalViewHost(Tpetra::Access::ReadOnly));
    double global = 0.0;
    Teuchos::reduceAll(*dofMap.comm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
    estimates[name] = -global;
  }
  return estimates;
}

}  // namespace flowform
