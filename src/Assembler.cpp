#include "flowform/Assembler.hpp"

#include <Sacado.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Assembly_Helpers.hpp>

#include "flowform/kernels/ShapeFunctions.hpp"

namespace flowform {

namespace {

/// Integration order of the flow kernel: P1 in plane strain has constant integrands (one
/// point is exact); the axisymmetric terms (u_r/r, 2πr) and Q1 need the 3-point / 2×2 rules.
int integrationOrder(CellType type, Geometry geometry) {
  return (type == CellType::Triangle3 && geometry == Geometry::PlaneStrain) ? 1 : 2;
}

/// Geometry of this rank's cell k: node coordinates, quadrature, centroid rule, diameter.
struct CellGeometry {
  std::array<double, 2> xy[kMaxNodesPerCell];
  CellQuadrature rule, centroid;
  double diameter;
};

void computeCellGeometry(const Mesh& mesh, GO cell, Geometry geometry, CellGeometry& g) {
  const int npc = nodesPerCell(mesh.cellType);
  for (int a = 0; a < npc; ++a) g.xy[a] = mesh.coords[mesh.cell(cell)[a]];
  // The mesh reader rejects inverted cells, so the determinants are positive here.
  computeCellQuadrature(mesh.cellType, g.xy, integrationOrder(mesh.cellType, geometry), g.rule);
  computeCellQuadrature(mesh.cellType, g.xy, 1, g.centroid);
  g.diameter = cellDiameter(mesh.cellType, g.xy);
}

}  // namespace

Assembler::Assembler(const Mesh& mesh, const DofMap& dofMap, const BoundaryConditions& bcs)
    : m_mesh(mesh), m_dofMap(dofMap), m_bcs(bcs) {
  m_xOverlap = Teuchos::rcp(new Vector(dofMap.overlapMap()));
  m_fOverlap = Teuchos::rcp(new Vector(dofMap.overlapMap()));
}

Teuchos::RCP<FECrsMatrix> Assembler::createJacobian() const {
  return Teuchos::rcp(new FECrsMatrix(m_dofMap.graph()));
}

const Vector& Assembler::importSolution(const Vector& xOwned) const {
  m_xOverlap->doImport(xOwned, *m_dofMap.importer(), Tpetra::INSERT);
  return *m_xOverlap;
}

void Assembler::residual(const Vector& xOwned, Vector& fOwned) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: assembly (residual)"));
  const Vector& xOverlap = importSolution(xOwned);
  m_fOverlap->putScalar(0.0);
  {
    auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto f = m_fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite);
    const int npc = nodesPerCell(m_mesh.cellType);
    const int ndof = kDofsPerNode * npc;
    const auto& cells = m_dofMap.cells();
    const auto& cellNodes = m_dofMap.cellNodes();
    const auto& constraints = m_bcs.constraints();
    CellGeometry g;
    double dofs[kDofsPerNode * kMaxNodesPerCell], res[kDofsPerNode * kMaxNodesPerCell];
    for (size_t k = 0; k < cells.size(); ++k) {
      computeCellGeometry(m_mesh, cells[k], m_physics.kernel.geometry, g);
      const LO* nodes = &cellNodes[npc * k];
      for (int a = 0; a < npc; ++a)
        for (int c = 0; c < kDofsPerNode; ++c) dofs[kDofsPerNode * a + c] = x(kDofsPerNode * nodes[a] + c, 0);
      std::fill(res, res + ndof, 0.0);
      addFlowResidual(g.rule, g.centroid, g.diameter, m_physics.kernel, m_physics.material, dofs, res);
      for (int a = 0; a < npc; ++a) {
        applyConstraintRows(constraints[nodes[a]], res + kDofsPerNode * a);
        for (int c = 0; c < kDofsPerNode; ++c) f(kDofsPerNode * nodes[a] + c, 0) += res[kDofsPerNode * a + c];
      }
    }
  }
  addTractions(*m_fOverlap);
  addConstraintRows(xOverlap, nullptr, m_fOverlap.get());
  fOwned.putScalar(0.0);
  fOwned.doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
}

void Assembler::jacobian(const Vector& xOwned, FECrsMatrix& jacobian, Vector* fOwned) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: assembly (Jacobian)"));
  const Vector& xOverlap = importSolution(xOwned);
  if (fOwned) m_fOverlap->putScalar(0.0);
  Tpetra::beginAssembly(jacobian);
  jacobian.setAllToScalar(0.0);
  if (m_mesh.cellType == CellType::Triangle3)
    assembleJacobianCells<3>(xOverlap, jacobian, fOwned ? m_fOverlap.get() : nullptr);
  else
    assembleJacobianCells<4>(xOverlap, jacobian, fOwned ? m_fOverlap.get() : nullptr);
  addConstraintRows(xOverlap, &jacobian, fOwned ? m_fOverlap.get() : nullptr);
  Tpetra::endAssembly(jacobian);
  if (fOwned) {
    addTractions(*m_fOverlap);
    fOwned->putScalar(0.0);
    fOwned->doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
  }
}

template <int NumNodes>
void Assembler::assembleJacobianCells(const Vector& xOverlap, FECrsMatrix& jacobian, Vector* fOverlap) const {
  constexpr int N = kDofsPerNode * NumNodes;
  using Fad = Sacado::Fad::SFad<double, N>;
  auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  decltype(m_fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite)) f;
  if (fOverlap) f = fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite);

  const auto& cells = m_dofMap.cells();
  const auto& cellNodes = m_dofMap.cellNodes();
  const auto& constraints = m_bcs.constraints();
  CellGeometry g;
  Fad dofs[N], res[N];
  LO cols[N];
  double values[N];
  for (size_t k = 0; k < cells.size(); ++k) {
    computeCellGeometry(m_mesh, cells[k], m_physics.kernel.geometry, g);
    const LO* nodes = &cellNodes[NumNodes * k];
    // Gather and seed: dof i of the cell is the i-th independent variable.
    for (int a = 0; a < NumNodes; ++a)
      for (int c = 0; c < kDofsPerNode; ++c) {
        const int i = kDofsPerNode * a + c;
        dofs[i] = Fad(N, i, x(kDofsPerNode * nodes[a] + c, 0));
        cols[i] = m_dofMap.columnIndex(nodes[a], c);
        res[i] = 0.0;
      }
    addFlowResidual(g.rule, g.centroid, g.diameter, m_physics.kernel, m_physics.material, dofs, res);
    // Scatter: row i of the cell matrix is dR_i/d(dofs).
    for (int a = 0; a < NumNodes; ++a) {
      applyConstraintRows(constraints[nodes[a]], res + kDofsPerNode * a);
      for (int c = 0; c < kDofsPerNode; ++c) {
        const int i = kDofsPerNode * a + c;
        const LO row = kDofsPerNode * nodes[a] + c;
        for (int j = 0; j < N; ++j) values[j] = res[i].dx(j);
        jacobian.sumIntoLocalValues(row, N, values, cols);
        if (fOverlap) f(row, 0) += res[i].val();
      }
    }
  }
}

void Assembler::addConstraintRows(const Vector& xOverlap, FECrsMatrix* jacobian, Vector* fOverlap) const {
  // Only owned nodes (overlap indices 0..numOwnedNodes-1): each constraint row is added once.
  auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  decltype(m_fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite)) f;
  if (fOverlap) f = fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto& constraints = m_bcs.constraints();
  for (LO n = 0; n < m_dofMap.numOwnedNodes(); ++n) {
    const NodeConstraint& nc = constraints[n];
    const LO ux = kDofsPerNode * n + kUx, uy = kDofsPerNode * n + kUy;
    const LO cols[2] = {m_dofMap.columnIndex(n, kUx), m_dofMap.columnIndex(n, kUy)};
    if (nc.kind == NodeConstraint::Kind::Full) {
      // rows: u_x − v_x, u_y − v_y
      if (fOverlap) {
        f(ux, 0) += x(ux, 0) - nc.value[0];
        f(uy, 0) += x(uy, 0) - nc.value[1];
      }
      if (jacobian) {
        const double one = 1.0;
        jacobian->sumIntoLocalValues(ux, 1, &one, &cols[0]);
        jacobian->sumIntoLocalValues(uy, 1, &one, &cols[1]);
      }
    } else if (nc.kind == NodeConstraint::Kind::Single) {
      // row c: a·u − b
      const LO row = kDofsPerNode * n + nc.constrainedRow;
      if (fOverlap) f(row, 0) += nc.a[0] * x(ux, 0) + nc.a[1] * x(uy, 0) - nc.b;
      if (jacobian) jacobian->sumIntoLocalValues(row, 2, nc.a, cols);
    }
  }
}

void Assembler::addTractions(Vector& fOverlap) const {
  // R_u[a] −= ∫_edge N_a t̄ ds (× 2π r when axisymmetric), 2-point Gauss on each edge.
  auto f = fOverlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto& constraints = m_bcs.constraints();
  const auto& overlapNodes = m_dofMap.overlapNodes();
  const bool axisymmetric = m_physics.kernel.geometry == Geometry::Axisymmetric;
  const double gp[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  for (const TractionEdge& e : m_bcs.tractionEdges()) {
    const auto& x0 = m_mesh.coords[overlapNodes[e.nodes[0]]];
    const auto& x1 = m_mesh.coords[overlapNodes[e.nodes[1]]];
    const double length = std::hypot(x1[0] - x0[0], x1[1] - x0[1]);
    double load[2][2] = {{0.0, 0.0}, {0.0, 0.0}};  // [node][component]
    for (double s : gp) {
      const double N[2] = {1.0 - s, s};
      double w = 0.5 * length;
      if (axisymmetric) w *= 2.0 * M_PI * (N[0] * x0[0] + N[1] * x1[0]);
      for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2; ++c) load[a][c] -= w * N[a] * e.traction[c];
    }
    for (int a = 0; a < 2; ++a) {
      applyConstraintRows(constraints[e.nodes[a]], load[a]);
      for (int c = 0; c < 2; ++c) f(kDofsPerNode * e.nodes[a] + c, 0) += load[a][c];
    }
  }
}

}  // namespace flowform
