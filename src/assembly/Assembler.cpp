#include "flowform/Assembler.hpp"

#include <Sacado.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Assembly_Helpers.hpp>

#include "flowform/EvaluationTypes.hpp"
#include "flowform/SensitivityParameter.hpp"
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
  m_dxOverlap = Teuchos::rcp(new Vector(dofMap.overlapMap()));
}

Teuchos::RCP<FECrsMatrix> Assembler::createJacobian() const {
  return Teuchos::rcp(new FECrsMatrix(m_dofMap.graph()));
}

const Vector& Assembler::importSolution(const Vector& xOwned) const {
  m_xOverlap->doImport(xOwned, *m_dofMap.importer(), Tpetra::INSERT);
  return *m_xOverlap;
}

void Assembler::setContactWalls(const std::vector<ContactWall>* walls) {
  m_walls = walls;
  m_wallNodes.clear();
  if (!walls) return;
  for (size_t w = 0; w < walls->size(); ++w) {
    const ContactWall& wall = (*walls)[w];
    for (int k = 0; k < wall.numNodes(); ++k) {
      const LO node = m_dofMap.overlapIndex(wall.curve().nodes[k]);
      if (node < 0 || node >= m_dofMap.numOwnedNodes()) continue;  // the owner assembles it
      auto local = [&](int j) { return j < 0 ? LO(-1) : m_dofMap.overlapIndex(wall.curve().nodes[j]); };
      m_wallNodes.push_back({static_cast<int>(w), k, node, local(wall.previous(k)), local(wall.next(k))});
    }
  }
}

template <typename Scalar>
void Assembler::gatherWallNode(const Vector& xOverlap, int ref, Scalar* u, Scalar* p) const {
  auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const WallNodeRef& r = m_wallNodes[ref];
  u[0] = x(kDofsPerNode * r.node + kUx, 0);
  u[1] = x(kDofsPerNode * r.node + kUy, 0);
  p[0] = r.previous >= 0 ? x(kDofsPerNode * r.previous + kP, 0) : 0.0;
  p[1] = x(kDofsPerNode * r.node + kP, 0);
  p[2] = r.next >= 0 ? x(kDofsPerNode * r.next + kP, 0) : 0.0;
}

template <typename Scalar>
void Assembler::addContactResidual(const Vector& xOverlap, const Vector* dxOverlap, const SensitivityParameter* h,
                                   Vector& fOverlap, bool applyConstraints) const {
  auto f = fOverlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  std::vector<FrictionParameters<Scalar>> friction;
  for (size_t w = 0; w < m_walls->size(); ++w)
    friction.push_back(frictionFor<Scalar>((*m_walls)[w], static_cast<int>(w), h));
  for (size_t i = 0; i < m_wallNodes.size(); ++i) {
    const WallNodeRef& r = m_wallNodes[i];
    double u0[2], p0[3], du[2] = {0.0, 0.0}, dp[3] = {0.0, 0.0, 0.0};
    gatherWallNode(xOverlap, static_cast<int>(i), u0, p0);
    if (dxOverlap) gatherWallNode(*dxOverlap, static_cast<int>(i), du, dp);
    Scalar u[2], p[3], R[2] = {0.0, 0.0};
    for (int c = 0; c < 2; ++c) setInput(u[c], u0[c], du[c]);
    for (int c = 0; c < 3; ++c) setInput(p[c], p0[c], dp[c]);
    (*m_walls)[r.wall].addNodeResidual(r.k, friction[r.wall], u, p, R);
    if (applyConstraints) applyConstraintRows(m_bcs.constraints()[r.node], R);
    f(kDofsPerNode * r.node + kUx, 0) += output(R[0]);
    f(kDofsPerNode * r.node + kUy, 0) += output(R[1]);
  }
}

void Assembler::addContactJacobian(const Vector& xOverlap, FECrsMatrix& jacobian, Vector* fOverlap) const {
  // Dofs of a wall node's rows: u_x, u_y of the node and the pressures of previous, node, next.
  using Fad = Sacado::Fad::SFad<double, 5>;
  decltype(m_fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite)) f;
  if (fOverlap) f = fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite);
  for (size_t i = 0; i < m_wallNodes.size(); ++i) {
    const WallNodeRef& r = m_wallNodes[i];
    Fad u[2], p[3], R[2] = {0.0, 0.0};
    gatherWallNode(xOverlap, static_cast<int>(i), u, p);
    u[0].diff(0, 5); u[1].diff(1, 5);
    p[0].diff(2, 5); p[1].diff(3, 5); p[2].diff(4, 5);
    (*m_walls)[r.wall].addNodeResidual(r.k, u, p, R);
    applyConstraintRows(m_bcs.constraints()[r.node], R);
    LO cols[5];
    double values[5];
    int n = 0;
    const LO owners[5] = {r.node, r.node, r.previous, r.node, r.next};
    const int comps[5] = {kUx, kUy, kP, kP, kP};
    for (int c = 0; c < 2; ++c) {
      n = 0;
      for (int j = 0; j < 5; ++j) {
        if (owners[j] < 0) continue;
        cols[n] = m_dofMap.columnIndex(owners[j], comps[j]);
        values[n++] = R[c].dx(j);
      }
      jacobian.sumIntoLocalValues(kDofsPerNode * r.node + c, n, values, cols);
      if (fOverlap) f(kDofsPerNode * r.node + c, 0) += R[c].val();
    }
  }
}

void Assembler::nodalCellMaxima(const Vector& xOwned, std::vector<double>& viscosity,
                                std::vector<double>& flowStress) const {
  const Vector& xOverlap = importSolution(xOwned);
  const LO numOverlap = static_cast<LO>(m_dofMap.overlapNodes().size());
  // Node maps (one entry per node): the overlap-to-owned export with ABSMAX takes the
  // largest value over the ranks, which makes the result independent of the partition.
  std::vector<GO> gids(m_dofMap.overlapNodes().begin(), m_dofMap.overlapNodes().end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto overlapNodes = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(gids), 0, m_dofMap.comm()));
  auto ownedNodes = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(gids.data(), m_dofMap.numOwnedNodes()), 0,
                                         m_dofMap.comm()));
  MultiVector local(overlapNodes, 2), owned(ownedNodes, 2);
  {
    auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto v = local.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const int npc = nodesPerCell(m_mesh.cellType);
    CellGeometry g;
    double dofs[kDofsPerNode * kMaxNodesPerCell];
    for (size_t k = 0; k < m_dofMap.cells().size(); ++k) {
      computeCellGeometry(m_mesh, m_dofMap.cells()[k], m_physics.kernel.geometry, g);
      const LO* nodes = &m_dofMap.cellNodes()[npc * k];
      for (int a = 0; a < npc; ++a)
        for (int c = 0; c < kDofsPerNode; ++c) dofs[kDofsPerNode * a + c] = x(kDofsPerNode * nodes[a] + c, 0);
      const auto d = strainRateAt(g.centroid, 0, m_physics.kernel.geometry, dofs);
      const double eReg = regularizedStrainRate(d.ddot(), m_physics.material);
      const double mu = flowform::viscosity(eReg, m_physics.material);
      const double sigma = flowform::flowStress(eReg, m_physics.material);
      for (int a = 0; a < npc; ++a) {
        v(nodes[a], 0) = std::max(v(nodes[a], 0), mu);
        v(nodes[a], 1) = std::max(v(nodes[a], 1), sigma);
      }
    }
  }
  owned.doExport(local, Export(overlapNodes, ownedNodes), Tpetra::ABSMAX);
  local.doImport(owned, Import(ownedNodes, overlapNodes), Tpetra::INSERT);
  auto v = local.getLocalViewHost(Tpetra::Access::ReadOnly);
  viscosity.resize(numOverlap);
  flowStress.resize(numOverlap);
  for (LO i = 0; i < numOverlap; ++i) {
    viscosity[i] = v(i, 0);
    flowStress[i] = v(i, 1);
  }
}

template <typename Scalar>
void Assembler::addCellResiduals(const Vector& xOverlap, const Vector* dxOverlap, const SensitivityParameter* h,
                                 Vector& fOverlap, bool applyConstraints) const {
  auto x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  decltype(x) dx;
  if (dxOverlap) dx = dxOverlap->getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = fOverlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  const MaterialParameters<Scalar> material = materialFor<Scalar>(m_physics.material, h);
  const int npc = nodesPerCell(m_mesh.cellType);
  const int ndof = kDofsPerNode * npc;
  const auto& cells = m_dofMap.cells();
  const auto& cellNodes = m_dofMap.cellNodes();
  const auto& constraints = m_bcs.constraints();
  CellGeometry g;
  Scalar dofs[kDofsPerNode * kMaxNodesPerCell], res[kDofsPerNode * kMaxNodesPerCell];
  for (size_t k = 0; k < cells.size(); ++k) {
    computeCellGeometry(m_mesh, cells[k], m_physics.kernel.geometry, g);
    const LO* nodes = &cellNodes[npc * k];
    for (int a = 0; a < npc; ++a)
      for (int c = 0; c < kDofsPerNode; ++c) {
        const LO i = kDofsPerNode * nodes[a] + c;
        setInput(dofs[kDofsPerNode * a + c], x(i, 0), dxOverlap ? dx(i, 0) : 0.0);
      }
    std::fill(res, res + ndof, Scalar(0.0));
    addFlowResidual(g.rule, g.centroid, g.diameter, m_physics.kernel, material, dofs, res);
    for (int a = 0; a < npc; ++a) {
      if (applyConstraints) applyConstraintRows(constraints[nodes[a]], res + kDofsPerNode * a);
      for (int c = 0; c < kDofsPerNode; ++c) f(kDofsPerNode * nodes[a] + c, 0) += output(res[kDofsPerNode * a + c]);
    }
  }
}

void Assembler::residual(const Vector& xOwned, Vector& fOwned, bool applyConstraints) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: assembly (residual)"));
  const Vector& xOverlap = importSolution(xOwned);
  m_fOverlap->putScalar(0.0);
  addCellResiduals<double>(xOverlap, nullptr, nullptr, *m_fOverlap, applyConstraints);
  addTractions(*m_fOverlap, applyConstraints);
  if (m_walls) addContactResidual<double>(xOverlap, nullptr, nullptr, *m_fOverlap, applyConstraints);
  if (applyConstraints) addConstraintRows(xOverlap, nullptr, m_fOverlap.get());
  fOwned.putScalar(0.0);
  fOwned.doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
}

void Assembler::tangent(const Vector& xOwned, const Vector* dxOwned, const SensitivityParameter* h, Vector& dfOwned,
                        bool applyConstraints) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: assembly (tangent)"));
  const Vector& xOverlap = importSolution(xOwned);
  const Vector* dxOverlap = nullptr;
  if (dxOwned) {
    m_dxOverlap->doImport(*dxOwned, *m_dofMap.importer(), Tpetra::INSERT);
    dxOverlap = m_dxOverlap.get();
  }
  m_fOverlap->putScalar(0.0);
  addCellResiduals<TangentFad>(xOverlap, dxOverlap, h, *m_fOverlap, applyConstraints);
  // The tractions depend on neither x nor h.
  if (m_walls) addContactResidual<TangentFad>(xOverlap, dxOverlap, h, *m_fOverlap, applyConstraints);
  // The constraint rows a·u − b are linear in u and independent of h: their derivative is a·du.
  if (applyConstraints && dxOverlap) addConstraintRows(*dxOverlap, nullptr, m_fOverlap.get(), false);
  dfOwned.putScalar(0.0);
  dfOwned.doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
}

void Assembler::parameterDerivative(const Vector& xOwned, const SensitivityParameter& h, Vector& dRdh) const {
  tangent(xOwned, nullptr, &h, dRdh, true);
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
  if (m_walls) addContactJacobian(xOverlap, jacobian, fOwned ? m_fOverlap.get() : nullptr);
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

void Assembler::addConstraintRows(const Vector& xOverlap, FECrsMatrix* jacobian, Vector* fOverlap,
                                  bool withOffsets) const {
  // Only owned nodes (overlap indices 0..numOwnedNodes-1): each constraint row is added once.
  // Without the offsets (v, b) the rows are their own derivative along xOverlap = du.
  const double offset = withOffsets ? 1.0 : 0.0;
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
        f(ux, 0) += x(ux, 0) - offset * nc.value[0];
        f(uy, 0) += x(uy, 0) - offset * nc.value[1];
      }
      if (jacobian) {
        const double one = 1.0;
        jacobian->sumIntoLocalValues(ux, 1, &one, &cols[0]);
        jacobian->sumIntoLocalValues(uy, 1, &one, &cols[1]);
      }
    } else if (nc.kind == NodeConstraint::Kind::Single) {
      // row c: a·u − b
      const LO row = kDofsPerNode * n + nc.constrainedRow;
      if (fOverlap) f(row, 0) += nc.a[0] * x(ux, 0) + nc.a[1] * x(uy, 0) - offset * nc.b;
      if (jacobian) jacobian->sumIntoLocalValues(row, 2, nc.a, cols);
    }
  }
}

void Assembler::addTractions(Vector& fOverlap, bool applyConstraints) const {
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
      if (applyConstraints) applyConstraintRows(constraints[e.nodes[a]], load[a]);
      for (int c = 0; c < 2; ++c) f(kDofsPerNode * e.nodes[a] + c, 0) += load[a][c];
    }
  }
}

}  // namespace flowform
