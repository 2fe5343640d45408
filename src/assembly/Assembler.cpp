#include "flowform/assembly/Assembler.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Assembly_Helpers.hpp>

#include "flowform/assembly/CellMaterial.hpp"
#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/kernels/FlowKernel.hpp"

namespace flowform {

Assembler::Assembler(const Mesh& mesh, const DofMap& dofMap, const BoundaryConditions& bcs)
    : m_mesh(mesh), m_dofMap(dofMap), m_bcs(bcs) {
  // The flow kernel alone; a case with more fields must give its kernels (setKernels).
  m_kernels = {makeCellKernel(FlowKernel{}, dofMap.fields())};
  m_kernelError = checkKernels(m_kernels);
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

Workset Assembler::workset(const Vector& xOverlap, const Vector* dxOverlap, Vector* fOverlap,
                           FECrsMatrix* jacobian) const {
  Workset ws;
  ws.dofMap = &m_dofMap;
  ws.x = xOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  if (dxOverlap) {
    ws.dx = dxOverlap->getLocalViewHost(Tpetra::Access::ReadOnly);
    ws.hasDirection = true;
  }
  if (fOverlap) {
    ws.f = fOverlap->getLocalViewHost(Tpetra::Access::ReadWrite);
    ws.hasResidual = true;
  }
  ws.jacobian = jacobian;
  return ws;
}

void Assembler::setContactWalls(const std::vector<ContactWall>* walls) {
  m_walls = walls;
  m_wallNodes.clear();
  if (!walls) return;
  for (size_t w = 0; w < walls->size(); ++w) {
    const ContactWall& wall = (*walls)[w];
    for (int k = 0; k < wall.numNodes(); ++k) {
      const LO node = m_dofMap.overlapIndex(wall.curve().nodes[k]);
      if (!m_dofMap.ownsNode(node)) continue;  // the owner assembles it
      WallNodeRef r{static_cast<int>(w), k, node, {}};
      const auto stencil = wall.nodeStencil(k);
      for (int i = 0; i < ContactWall::kNodeStencilSize; ++i) {
        const int j = stencil[i].node;
        r.dofs[i] = j < 0 ? LO(-1) : m_dofMap.dof(m_dofMap.overlapIndex(wall.curve().nodes[j]), stencil[i].component);
      }
      m_wallNodes.push_back(r);
    }
  }
}

std::string Assembler::checkKernels(const std::vector<std::shared_ptr<const CellKernel>>& kernels) const {
  // Square system: each component of the case's fields is some kernel's rows, once.
  std::vector<int> owners(m_dofMap.fields().numComponents(), 0);
  for (const auto& kernel : kernels)
    for (int c : kernel->ownedComponents()) ++owners[c];
  for (size_t c = 0; c < owners.size(); ++c)
    if (owners[c] != 1)
      return "Assembler: node component " + std::to_string(c) + " is owned by " + std::to_string(owners[c]) +
             " kernels (must be 1)";
  return "";
}

void Assembler::setKernels(std::vector<std::shared_ptr<const CellKernel>> kernels) {
  const std::string error = checkKernels(kernels);
  if (!error.empty()) throw std::invalid_argument(error);
  m_kernels = std::move(kernels);
  m_kernelError.clear();
}

void Assembler::setPrescribedValues(const std::vector<PrescribedValue>& values) {
  m_prescribedDof.assign(values.empty() ? 0 : m_dofMap.overlapMap()->getNodeNumElements(), 0);
  m_prescribedRows.clear();
  for (const PrescribedValue& v : values) {
    if (v.component == kUx || v.component == kUy)
      throw std::invalid_argument("Assembler: velocity values are boundary conditions, not prescribed values");
    const LO n = m_dofMap.overlapIndex(v.node);
    if (n < 0) continue;
    const LO d = m_dofMap.dof(n, v.component);
    m_prescribedDof[d] = 1;
    if (m_dofMap.ownsNode(n)) m_prescribedRows.emplace_back(d, v.value);
  }
}

void Assembler::setFrictionHeat(std::vector<double> fractions, int component) {
  m_frictionHeat = std::move(fractions);
  m_frictionHeatComponent = component;
}

void Assembler::setHeatTransfer(std::vector<ThermalBoundaryConditions::TransferEdge> edges, int component) {
  m_transferEdges = std::move(edges);
  m_transferComponent = component;
}

// --- the loops ------------------------------------------------------------------------------

template <typename EvalT>
void Assembler::assembleHeatTransfer(Workset& ws) const {
  // R_T[a] += ∫_edge N_a h (T − T_a) dΓ, T linear along the edge (× 2π r axisymmetric).
  using Scalar = typename EvalT::template Scalar<2>;
  const auto& overlapNodes = m_dofMap.overlapNodes();
  for (const auto& e : m_transferEdges) {
    const LO dofs[2] = {m_dofMap.dof(e.nodes[0], m_transferComponent), m_dofMap.dof(e.nodes[1], m_transferComponent)};
    Scalar T[2], R[2] = {0.0, 0.0};
    gather(ws, dofs, 2, T);
    integrateSegment(m_mesh.coords[overlapNodes[e.nodes[0]]], m_mesh.coords[overlapNodes[e.nodes[1]]],
                     m_physics.kernel.geometry, [&](double N0, double N1, double w) {
                       const Scalar excess = N0 * T[0] + N1 * T[1] - e.ambient;
                       R[0] += w * N0 * e.coefficient * excess;
                       R[1] += w * N1 * e.coefficient * excess;
                     });
    for (int a = 0; a < 2; ++a)
      if (!m_prescribedDof.empty() && m_prescribedDof[dofs[a]]) R[a] = 0.0;  // the owner adds T − T_b
    scatter(ws, dofs, 2, dofs, 2, R);
  }
}

template <typename EvalT>
void Assembler::assembleCells(Workset& ws, const SensitivityParameter* h, bool applyConstraints) const {
  if (!m_kernelError.empty()) throw std::logic_error(m_kernelError);
  const CellLoop loop{m_mesh, m_dofMap, m_physics, m_bcs.constraints(), m_prescribedDof, h, applyConstraints};
  for (const auto& kernel : m_kernels) kernel->assemble(loop, ws, EvalT{});
}

template <typename EvalT>
void Assembler::assembleContact(Workset& ws, const SensitivityParameter* h, bool applyConstraints) const {
  // A wall node's rows are its two momentum rows, and its temperature row where the wall's
  // friction heats the workpiece; its stencil is the wall's (nodeStencil: u_x, u_y of the node,
  // the pressures of its previous neighbour, itself and its next one, the neighbours' velocities).
  constexpr int N = ContactWall::kNodeStencilSize;
  using Scalar = typename EvalT::template Scalar<N>;
  using PScalar = typename EvalT::ParamScalar;
  std::vector<FrictionParameters<PScalar>> friction;
  for (size_t w = 0; w < m_walls->size(); ++w)
    friction.push_back(frictionFor<PScalar>((*m_walls)[w], static_cast<int>(w), h));
  const auto& constraints = m_bcs.constraints();
  for (size_t i = 0; i < m_wallNodes.size(); ++i) {
    const WallNodeRef& r = m_wallNodes[i];
    const LO* dofs = r.dofs;
    Scalar values[N], R[ContactWall::kNodeRows] = {0.0, 0.0};
    gather(ws, dofs, N, values);
    FrictionDualPoint* dual = ws.dual ? ws.dual->wallNode(i, m_wallNodes.size()) : nullptr;
    (*m_walls)[r.wall].addNodeResidual(r.k, friction[r.wall], values, R, dual);
    if (applyConstraints) applyConstraintRows(constraints[r.node], R);
    scatter(ws, dofs, ContactWall::kNodeRows, dofs, N, R);
    if (m_frictionHeat.empty() || m_frictionHeat[r.wall] == 0.0) continue;
    // Friction heat: R_T[k] −= β g_k (u_k − v_w)·t_k (g_k the law's force along t_k, which has
    // the slip's sign: the node's friction power, ≥ 0). A held temperature's row is the owner's T − T_b.
    const LO t = m_dofMap.dof(r.node, m_frictionHeatComponent);
    if (applyConstraints && !m_prescribedDof.empty() && m_prescribedDof[t]) continue;
    const ContactWall& wall = (*m_walls)[r.wall];
    Scalar heat = -m_frictionHeat[r.wall] * wall.tangentialForce(r.k, friction[r.wall], values) *
                  wall.relativeSlip(r.k, values);
    scatter(ws, &t, 1, dofs, N, &heat);
  }
}

void Assembler::addConstraintRows(const HostView& x, Workset& ws, bool withOffsets) const {
  // Only owned nodes (overlap indices 0..numOwnedNodes-1): each constraint row is added once.
  // Without the offsets (v, b) the rows are their own derivative along x = du.
  const double offset = withOffsets ? 1.0 : 0.0;
  const auto& constraints = m_bcs.constraints();
  for (LO n = 0; n < m_dofMap.numOwnedNodes(); ++n) {
    const NodeConstraint& nc = constraints[n];
    const LO ux = m_dofMap.dof(n, kUx), uy = m_dofMap.dof(n, kUy);
    const LO cols[2] = {m_dofMap.column(ux), m_dofMap.column(uy)};
    if (nc.kind == NodeConstraint::Kind::Full) {
      // rows: u_x − v_x, u_y − v_y
      if (ws.hasResidual) {
        ws.f(ux, 0) += x(ux, 0) - offset * nc.value[0];
        ws.f(uy, 0) += x(uy, 0) - offset * nc.value[1];
      }
      if (ws.jacobian) {
        const double one = 1.0;
        ws.jacobian->sumIntoLocalValues(ux, 1, &one, &cols[0]);
        ws.jacobian->sumIntoLocalValues(uy, 1, &one, &cols[1]);
      }
    } else if (nc.kind == NodeConstraint::Kind::Single) {
      // row c: a·u − b
      const LO row = m_dofMap.dof(n, nc.constrainedRow);
      if (ws.hasResidual) ws.f(row, 0) += nc.a[0] * x(ux, 0) + nc.a[1] * x(uy, 0) - offset * nc.b;
      if (ws.jacobian) ws.jacobian->sumIntoLocalValues(row, 2, nc.a, cols);
    }
  }
  // Prescribed values of other fields: rows x − g (the cells' contributions were dropped).
  for (const auto& [d, value] : m_prescribedRows) {
    if (ws.hasResidual) ws.f(d, 0) += x(d, 0) - offset * value;
    if (ws.jacobian) {
      const double one = 1.0;
      const LO col = m_dofMap.column(d);
      ws.jacobian->sumIntoLocalValues(d, 1, &one, &col);
    }
  }
}

void Assembler::addTractions(Workset& ws, bool applyConstraints) const {
  // R_u[a] −= ∫_edge N_a t̄ ds (× 2π r when axisymmetric).
  const auto& constraints = m_bcs.constraints();
  const auto& overlapNodes = m_dofMap.overlapNodes();
  for (const TractionEdge& e : m_bcs.tractionEdges()) {
    double load[2][2] = {{0.0, 0.0}, {0.0, 0.0}};  // [node][component]
    integrateSegment(m_mesh.coords[overlapNodes[e.nodes[0]]], m_mesh.coords[overlapNodes[e.nodes[1]]],
                     m_physics.kernel.geometry, [&](double N0, double N1, double w) {
                       const double N[2] = {N0, N1};
                       for (int a = 0; a < 2; ++a)
                         for (int c = 0; c < 2; ++c) load[a][c] -= w * N[a] * e.traction[c];
                     });
    for (int a = 0; a < 2; ++a) {
      if (applyConstraints) applyConstraintRows(constraints[e.nodes[a]], load[a]);
      for (int c = 0; c < 2; ++c) ws.f(m_dofMap.dof(e.nodes[a], c), 0) += load[a][c];
    }
  }
}

// --- the evaluations ------------------------------------------------------------------------

void Assembler::residual(const Vector& xOwned, Vector& fOwned, bool applyConstraints) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: assembly (residual)"));
  const Vector& xOverlap = importSolution(xOwned);
  m_fOverlap->putScalar(0.0);
  {
    Workset ws = workset(xOverlap, nullptr, m_fOverlap.get(), nullptr);
    assembleCells<ResidualEval>(ws, nullptr, applyConstraints);
    addTractions(ws, applyConstraints);
    if (m_walls) assembleContact<ResidualEval>(ws, nullptr, applyConstraints);
    if (applyConstraints) {
      assembleHeatTransfer<ResidualEval>(ws);
      addConstraintRows(ws.x, ws);
    }
  }
  fOwned.putScalar(0.0);
  fOwned.doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
}

void Assembler::constrainResidual(const Vector& xOwned, Vector& fOwned) const {
  // Owned nodes come first in the overlap numbering, so their overlap dofs index the owned map.
  const Vector& xOverlap = importSolution(xOwned);
  m_fOverlap->putScalar(0.0);
  {
    Workset ws = workset(xOverlap, nullptr, m_fOverlap.get(), nullptr);
    auto f = fOwned.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto& constraints = m_bcs.constraints();
    for (LO n = 0; n < m_dofMap.numOwnedNodes(); ++n) {
      for (int c = 0; c < m_dofMap.numFields(m_dofMap.overlapNodes()[n]); ++c)
        ws.f(m_dofMap.dof(n, c), 0) = f(m_dofMap.dof(n, c), 0);
      double row[2] = {f(m_dofMap.dof(n, kUx), 0), f(m_dofMap.dof(n, kUy), 0)};
      applyConstraintRows(constraints[n], row);
      ws.f(m_dofMap.dof(n, kUx), 0) = row[0];
      ws.f(m_dofMap.dof(n, kUy), 0) = row[1];
    }
    for (const auto& prescribed : m_prescribedRows) ws.f(prescribed.first, 0) = 0.0;
    assembleHeatTransfer<ResidualEval>(ws);
    addConstraintRows(ws.x, ws);
  }
  fOwned.putScalar(0.0);
  fOwned.doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
}

void Assembler::jacobian(const Vector& xOwned, FECrsMatrix& jacobian, Vector* fOwned, NewtonDual* dual) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: assembly (Jacobian)"));
  const Vector& xOverlap = importSolution(xOwned);
  if (fOwned) m_fOverlap->putScalar(0.0);
  Tpetra::beginAssembly(jacobian);
  jacobian.setAllToScalar(0.0);
  {
    Workset ws = workset(xOverlap, nullptr, fOwned ? m_fOverlap.get() : nullptr, &jacobian);
    ws.dual = dual;
    assembleCells<JacobianEval>(ws, nullptr, true);
    if (m_walls) assembleContact<JacobianEval>(ws, nullptr, true);
    assembleHeatTransfer<JacobianEval>(ws);
    addConstraintRows(ws.x, ws);
    if (fOwned) addTractions(ws);
  }
  Tpetra::endAssembly(jacobian);
  if (fOwned) {
    fOwned->putScalar(0.0);
    fOwned->doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
  }
}

void Assembler::unconstrainedJacobian(const Vector& xOwned, FECrsMatrix& jacobian) const {
  const Vector& xOverlap = importSolution(xOwned);
  Tpetra::beginAssembly(jacobian);
  jacobian.setAllToScalar(0.0);
  {
    Workset ws = workset(xOverlap, nullptr, nullptr, &jacobian);
    assembleCells<JacobianEval>(ws, nullptr, false);
    if (m_walls) assembleContact<JacobianEval>(ws, nullptr, false);
  }
  Tpetra::endAssembly(jacobian);
}

void Assembler::tangent(const Vector& xOwned, const Vector* dxOwned, const SensitivityParameter* h, Vector& dfOwned,
                        bool applyConstraints) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: assembly (tangent)"));
  const Vector& xOverlap = importSolution(xOwned);
  if (dxOwned) m_dxOverlap->doImport(*dxOwned, *m_dofMap.importer(), Tpetra::INSERT);
  m_fOverlap->putScalar(0.0);
  {
    Workset ws = workset(xOverlap, dxOwned ? m_dxOverlap.get() : nullptr, m_fOverlap.get(), nullptr);
    // A friction parameter enters the walls only: with x held its cells' derivative is zero.
    if (dxOwned || !h || !h->isFriction()) assembleCells<TangentEval>(ws, h, applyConstraints);
    // The tractions depend on neither x nor h.
    if (m_walls) assembleContact<TangentEval>(ws, h, applyConstraints);
    if (applyConstraints) assembleHeatTransfer<TangentEval>(ws);
    // The constraint rows a·u − b are linear in u and independent of h: their derivative is a·du.
    if (applyConstraints && dxOwned) addConstraintRows(ws.dx, ws, false);
  }
  dfOwned.putScalar(0.0);
  dfOwned.doExport(*m_fOverlap, *m_dofMap.exporter(), Tpetra::ADD);
}

void Assembler::parameterDerivative(const Vector& xOwned, const SensitivityParameter& h, Vector& dRdh) const {
  tangent(xOwned, nullptr, &h, dRdh, true);
}

// --- cell values ----------------------------------------------------------------------------

std::vector<CellState> Assembler::cellStates(const Vector& xOwned) const {
  const Vector& xOverlap = importSolution(xOwned);
  const Workset ws = workset(xOverlap, nullptr, nullptr, nullptr);
  const Geometry geometry = m_physics.kernel.geometry;
  const int npc = m_dofMap.nodesPerCell();
  std::vector<CellState> states(m_dofMap.cells().size());
  CellGeometry g;
  LO dofs[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
  double values[EqualOrderLayout::numDofs(kMaxNodesPerCell)];
  const LawFieldComponents lawFields = lawFieldComponents(m_dofMap, m_physics);
  for (size_t k = 0; k < m_dofMap.cells().size(); ++k) {
    computeCellGeometry(m_mesh, m_dofMap.cells()[k], geometry, g);
    m_dofMap.cellDofs(k, dofs);
    gather(ws, dofs, EqualOrderLayout::numDofs(npc), values);
    const MaterialParameters<double> material = cellMaterial(ws, m_dofMap, k, g, m_physics.material, lawFields);
    const auto d = strainRateAt(g.centroid, 0, geometry, values);
    const double eReg = regularizedStrainRate(d.ddot(), material);
    states[k] = {std::sqrt(2.0 / 3.0 * d.ddot()), eReg, viscosity(eReg, material), flowStress(eReg, material)};
  }
  return states;
}

void Assembler::nodalCellMaxima(const Vector& xOwned, std::vector<double>& viscosity,
                                std::vector<double>& flowStress) const {
  const std::vector<CellState> states = cellStates(xOwned);
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
    auto v = local.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t k = 0; k < states.size(); ++k) {
      const LO* nodes = m_dofMap.cellNodes(k);
      for (int a = 0; a < m_dofMap.nodesPerCell(); ++a) {
        v(nodes[a], 0) = std::max(v(nodes[a], 0), states[k].viscosity);
        v(nodes[a], 1) = std::max(v(nodes[a], 1), states[k].flowStress);
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

}  // namespace flowform
