#include "flowform/freesurface/UpdateLinearization.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Teuchos_SerialDenseSolver.hpp>

#include "flowform/contact/ToolVelocities.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/freesurface/MeshMotion.hpp"

namespace flowform {

namespace {
constexpr double kNoRelease = std::numeric_limits<double>::infinity();  // statuses held
}

UpdateLinearization::UpdateLinearization(const SurfaceLinearizationState& at, bool responses) : m_at(at) {
  const DofMap& dofMap = at.dofMap;
  const Geometry geometry = at.geometry;
  m_state = Teuchos::rcp(new Vector(at.solution, Teuchos::Copy));
  const Vector& q = *m_state;
  const Mesh base = at.mesh;

  m_step = at.surfaces.step(base, dofMap, replicate(q, dofMap), at.walls, geometry, kNoRelease);
  if (!m_step.failure.empty()) {
    m_failure = m_step.failure;
    return;
  }
  for (size_t i = 0; i < m_step.moves.size(); ++i)
    if (m_step.moves[i].integrated)
      for (const auto& d : m_step.moves[i].directions()) m_unknowns.push_back({i, d});
  const int nb = size();
  if (nb == 0) {
    m_failure = "no surface node is placed by the update";
    return;
  }
  std::vector<std::array<double, 2>> zero(base.numNodes(), {0.0, 0.0});
  HarmonicExtension extension(base, m_step.prescribed);
  // The boundary displacement of unknown j moved by `amount` along its direction (and the group
  // its surface drags).
  auto displacementOf = [&](int j, double amount) {
    std::vector<std::array<double, 2>> d = zero;
    const auto& dir = m_unknowns[j].direction;
    d[m_step.moves[m_unknowns[j].move].node] = {amount * dir[0], amount * dir[1]};
    for (const FreeSurfaceStep::Drag& drag : m_step.drags)
      if (drag.end == m_unknowns[j].move) {  // a wall node slid by an attachment point: along its own tangent
        const auto& along = drag.slide.on ? drag.slide.tangent : dir;
        d[drag.node] = {drag.fraction * amount * along[0], drag.fraction * amount * along[1]};
      }
    return d;
  };
  // A moving tool's nodes slid by an attachment point carry the tool's velocity with them
  // (contact/ToolVelocities.hpp): the differences are taken at q + v_w(X ± εE_j) − v_w(X), and Y_j
  // below is then dq/db_j less that shift per unit b_j, which leaves G and dφ/db_j as they are. With
  // the velocity held, the normal penalty sees (u − v_w)·n change by ω d_k and answers with ~10⁵
  // per unit move near a roll's neutral point (the metal turns with the roll there, at a large
  // viscosity), to be cancelled by the flow's response to a few units: a cancellation the
  // differences' round-off did not survive on fine meshes.
  const Teuchos::RCP<const Vector> toolsAtState = toolVelocities(at.walls, dofMap, q.getMap());

  // Pass 1, the positions: ∂R/∂b_j (with the interior following), ∂U/∂b_j, ∂φ/∂b_j.
  // An unknown that slides a contact wall's nodes along their tool (an attachment point) moves
  // them by 10⁻⁹ of the surface's length: at 10⁻⁶ a wall node crosses its stick window and the
  // differences meet the friction's kink (as the mesh partials of a shape parameter do,
  // kMeshPartialMove); other unknowns by 10⁻⁶.
  MultiVector rx(q.getMap(), nb);
  m_G.shape(nb, nb);
  m_phiB.assign(responses ? nb : 0, {});
  m_phiQ.assign(responses ? nb : 0, {});
  Vector rPlus(q.getMap()), rMinus(q.getMap()), qMoved(q.getMap());
  const bool inflow = static_cast<bool>(at.inflowForce);
  std::vector<double> dFdb(nb, 0.0);  // a Rigid Inflow's ∂F/∂b_j
  try {
    // One assembly per move: the unconstrained residual gives the responses' reactions and the
    // inflow's force, then R by constraining it.
    auto evaluateMoved = [&](const Vector& x, Vector& r, double& force, std::map<std::string, double>& phi) {
      at.model.assembler().residual(x, r, false);
      if (inflow) force = at.inflowForce(r);
      if (responses) phi = responsesAt(x, &r);
      at.model.assembler().constrainResidual(x, r);
    };
    for (int j = 0; j < nb; ++j) {
      const bool slidesWall = m_step.moves[m_unknowns[j].move].slide.on;  // the attachment: a wall node
      const double eps = (slidesWall ? 1e-9 : 1e-6) * at.surfaces.lengthScale();
      double forcePlus = 0.0, forceMinus = 0.0;
      std::map<std::string, double> phiPlus, phiMinus;
      at.moveNodes(extension.positions(displacementOf(j, eps)));
      followTools(at.walls, dofMap, q, toolsAtState, qMoved);
      evaluateMoved(qMoved, rPlus, forcePlus, phiPlus);
      const std::vector<double> uPlus = updateAt(qMoved);
      at.moveNodes(extension.positions(displacementOf(j, -eps)));
      followTools(at.walls, dofMap, q, toolsAtState, qMoved);
      evaluateMoved(qMoved, rMinus, forceMinus, phiMinus);
      const std::vector<double> uMinus = updateAt(qMoved);
      dFdb[j] = (forcePlus - forceMinus) / (2 * eps);
      rx.getVectorNonConst(j)->update(-1.0 / (2 * eps), rPlus, 1.0 / (2 * eps), rMinus, 0.0);  // −∂R/∂b_j
      for (int i = 0; i < nb; ++i) m_G(i, j) = (uPlus[i] - uMinus[i]) / (2 * eps);
      for (const auto& [name, value] : phiPlus) m_phiB[j][name] = (value - phiMinus.at(name)) / (2 * eps);
    }
  } catch (const std::exception& e) {  // a move that inverts a cell
    at.moveNodes(base.coords);
    m_failure = std::string("moving a surface node: ") + e.what();
    return;
  }
  at.moveNodes(base.coords);

  // Y = −K_t⁻¹ ∂R/∂b with the factors at the state (Y' of the tool-following differences); then
  // U_q Y_j (and φ_q Y_j).
  FlowModel& model = at.model;
  model.restartLinearization();
  model.computeJacobian(q);
  MultiVector Y(q.getMap(), nb);
  model.solve(rx, Y);
  if (inflow) {  // the inflow's speed follows the surface: Y_j += dU_j g
    MultiVector g(q.getMap(), 1);
    model.solve(*at.minusDfDU, g);
    const Vector gU = *g.getVector(0);
    const double slope = at.inflowForceTangent(gU);
    for (int j = 0; j < nb; ++j) {
      const double dU = -(dFdb[j] + at.inflowForceTangent(*Y.getVector(j))) / slope;
      Y.getVectorNonConst(j)->update(dU, gU, 1.0);
    }
  }
  for (int j = 0; j < nb; ++j) {
    const Vector y = *Y.getVector(j);
    const std::vector<double> dU = updateAlong(y);
    for (int i = 0; i < nb; ++i) m_G(i, j) += dU[i];
    if (responses) {
      const double delta = 1e-6 * std::max(q.normInf(), 1e-300) / std::max(y.normInf(), 1e-300);
      Vector x(q, Teuchos::Copy);
      x.update(delta, y, 1.0);
      const auto plus = responsesAt(x);
      x.update(-2.0 * delta, y, 1.0);
      const auto minus = responsesAt(x);
      for (const auto& [name, value] : plus) m_phiQ[j][name] = (value - minus.at(name)) / (2 * delta);
    }
  }
  // Spectral radius by power iteration.
  std::vector<double> v(nb, 1.0), w(nb);
  for (int it = 0; it < 200; ++it) {
    for (int i = 0; i < nb; ++i) {
      w[i] = 0.0;
      for (int j = 0; j < nb; ++j) w[i] += m_G(i, j) * v[j];
    }
    m_spectralRadius = 0.0;
    for (double x : w) m_spectralRadius = std::max(m_spectralRadius, std::abs(x));
    if (!(m_spectralRadius > 0.0)) break;
    for (int i = 0; i < nb; ++i) v[i] = w[i] / m_spectralRadius;
  }
}

std::vector<double> UpdateLinearization::updateAt(const Vector& x) const {
  const FreeSurfaceStep s = m_at.surfaces.step(m_at.mesh, m_at.dofMap, replicate(x, m_at.dofMap),
                                                      m_at.walls, m_at.geometry, kNoRelease);
  std::vector<double> u(m_unknowns.size(), 0.0);
  for (size_t j = 0; j < m_unknowns.size(); ++j) {
    const FreeSurfaceStep::Move& m = s.moves[m_unknowns[j].move];
    const auto& p = m_at.mesh.coords[m.node];
    const auto& d = m_unknowns[j].direction;
    u[j] = (p[0] + m.residual[0]) * d[0] + (p[1] + m.residual[1]) * d[1];  // where the update puts it
  }
  return u;
}

std::map<std::string, double> UpdateLinearization::responsesAt(const Vector& x, const Vector* reactions) const {
  return m_at.responses.evaluate(x, m_at.mesh, m_at.dofMap, m_at.model.assembler(), m_at.walls, reactions);
}

std::vector<double> UpdateLinearization::updateAlong(const Vector& d) const {
  const Vector& q = *m_state;
  const double delta = 1e-6 * std::max(q.normInf(), 1e-300) / std::max(d.normInf(), 1e-300);
  Vector x(q, Teuchos::Copy);
  x.update(delta, d, 1.0);
  const std::vector<double> plus = updateAt(x);
  x.update(-2.0 * delta, d, 1.0);
  const std::vector<double> minus = updateAt(x);
  std::vector<double> dU(plus.size());
  for (size_t i = 0; i < plus.size(); ++i) dU[i] = (plus[i] - minus[i]) / (2 * delta);
  return dU;
}

std::vector<double> UpdateLinearization::residualAlongMotion(const std::vector<std::array<double, 2>>& V) const {
  const Vector& q = *m_state;
  const std::vector<std::array<double, 2>> base = m_at.mesh.coords;
  double largest = 0.0;
  for (const auto& v : V) largest = std::max(largest, std::hypot(v[0], v[1]));
  std::vector<double> dr(m_unknowns.size(), 0.0);
  if (!(largest > 0.0)) return dr;
  const double eps = 1e-6 * m_at.surfaces.lengthScale() / largest;
  // The update's residual along each unknown: where it puts the node less where the node is.
  auto residualAt = [&](double amount) {
    std::vector<std::array<double, 2>> moved = base;
    for (size_t n = 0; n < moved.size(); ++n) moved[n] = {base[n][0] + amount * V[n][0], base[n][1] + amount * V[n][1]};
    m_at.moveNodes(moved);
    std::vector<double> r = updateAt(q);
    for (size_t j = 0; j < m_unknowns.size(); ++j) {
      const auto& p = m_at.mesh.coords[m_step.moves[m_unknowns[j].move].node];
      r[j] -= p[0] * m_unknowns[j].direction[0] + p[1] * m_unknowns[j].direction[1];
    }
    return r;
  };
  const std::vector<double> plus = residualAt(eps), minus = residualAt(-eps);
  m_at.moveNodes(base);
  for (size_t j = 0; j < dr.size(); ++j) dr[j] = (plus[j] - minus[j]) / (2 * eps);
  return dr;
}

bool UpdateLinearization::solve(const Teuchos::SerialDenseMatrix<int, double>& B,
                                Teuchos::SerialDenseMatrix<int, double>& X) const {
  const int nb = size();
  Teuchos::SerialDenseMatrix<int, double> A(nb, nb), rhs(B);
  for (int i = 0; i < nb; ++i)
    for (int j = 0; j < nb; ++j) A(i, j) = (i == j ? 1.0 : 0.0) - m_G(i, j);
  X.shape(nb, B.numCols());
  Teuchos::SerialDenseSolver<int, double> solver;
  solver.setMatrix(Teuchos::rcpFromRef(A));
  solver.setVectors(Teuchos::rcpFromRef(X), Teuchos::rcpFromRef(rhs));
  solver.factorWithEquilibration(true);
  return solver.factor() == 0 && solver.solve() == 0;
}

bool UpdateLinearization::newtonMoves(std::vector<std::array<double, 2>>& moves) const {
  const int nb = size();
  Teuchos::SerialDenseMatrix<int, double> r(nb, 1), delta;
  for (int j = 0; j < nb; ++j) {
    const FreeSurfaceStep::Move& m = m_step.moves[m_unknowns[j].move];
    r(j, 0) = m.residual[0] * m_unknowns[j].direction[0] + m.residual[1] * m_unknowns[j].direction[1];
  }
  if (!solve(r, delta)) return false;
  moves.assign(m_step.moves.size(), {0.0, 0.0});
  std::vector<char> unknown(m_step.moves.size(), 0);
  for (int j = 0; j < nb; ++j) {
    const size_t i = m_unknowns[j].move;
    unknown[i] = 1;
    moves[i][0] += delta(j, 0) * m_unknowns[j].direction[0];
    moves[i][1] += delta(j, 0) * m_unknowns[j].direction[1];
  }
  for (size_t i = 0; i < moves.size(); ++i)
    if (!unknown[i]) moves[i] = m_step.moves[i].residual;
  return true;
}

}  // namespace flowform
