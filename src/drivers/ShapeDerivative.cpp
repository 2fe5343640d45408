#include "flowform/drivers/ShapeDerivative.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <Teuchos_SerialDenseMatrix.hpp>
#include <Teuchos_SerialDenseSolver.hpp>
#include <nlohmann/json.hpp>

#include "flowform/core/Log.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/drivers/Simulation.hpp"
#include "flowform/freesurface/MeshMotion.hpp"

namespace flowform {

void ShapeDerivative::report(nlohmann::json& summary) const {
  summary["shape_derivative"] = {{"computed", computed}, {"surface_unknowns", unknowns},
                                 {"contraction", contraction}, {"seconds", seconds}};
  if (!failure.empty()) summary["shape_derivative"]["failure"] = failure;
  nlohmann::json& s = summary["sensitivities_total_shape"];
  s = nlohmann::json::object();
  for (const auto& [response, byParameter] : responses)
    for (const auto& [parameter, value] : byParameter) s[response][parameter] = value;
}

ShapeDerivative totalShapeDerivative(Simulation& sim) {
  const auto start = std::chrono::steady_clock::now();
  ShapeDerivative out;
  const Sensitivity& sensitivity = sim.sensitivity();
  if (!sensitivity.computed()) {
    out.failure = "no DDM sensitivities to extend";
    return out;
  }
  const DofMap& dofMap = sim.dofMap();
  const Geometry geometry = sim.physics().kernel.geometry;
  const FreeSurfaces& surfaces = sim.freeSurfaces();
  const Vector q(sim.solution(), Teuchos::Copy);
  const Mesh base = sim.mesh();
  const double noRelease = std::numeric_limits<double>::infinity();  // statuses held

  // The unknowns: the surface nodes the update places (a start, a node on the tool: fixed).
  const FreeSurfaceStep step0 = surfaces.step(base, dofMap, replicate(q, dofMap), sim.contactWalls(), geometry, noRelease);
  if (!step0.failure.empty()) {
    out.failure = step0.failure;
    return out;
  }
  // An unknown: a move index and a direction (spines: the normal; arc length: x and y).
  struct Unknown {
    size_t move;
    std::array<double, 2> direction;
  };
  std::vector<Unknown> unknown;
  for (size_t i = 0; i < step0.moves.size(); ++i)
    if (step0.moves[i].integrated)
      for (const auto& d : step0.moves[i].directions()) unknown.push_back({i, d});
  const int nb = static_cast<int>(unknown.size());
  out.unknowns = nb;
  if (nb == 0) {
    out.failure = "no surface node is placed by the update";
    return out;
  }
  std::vector<std::array<double, 2>> zero(base.numNodes(), {0.0, 0.0});
  HarmonicExtension extension(base, step0.prescribed);

  // U(x) at the current mesh, for the unknowns (by node: the same nodes at every evaluation).
  auto update = [&](const Vector& x) {
    const FreeSurfaceStep s = surfaces.step(sim.mesh(), dofMap, replicate(x, dofMap), sim.contactWalls(), geometry,
                                            noRelease);
    std::vector<double> u(nb, 0.0);
    for (int j = 0; j < nb; ++j) {
      const FreeSurfaceStep::Move& m = s.moves[unknown[j].move];
      const auto& x = sim.mesh().coords[m.node];
      const auto& d = unknown[j].direction;
      u[j] = (x[0] + m.residual[0]) * d[0] + (x[1] + m.residual[1]) * d[1];  // where the update puts it
    }
    return u;
  };
  auto responses = [&](const Vector& x) {
    return sim.responses().evaluate(x, sim.mesh(), dofMap, sim.model().assembler(), sim.contactWalls());
  };
  // The mesh with unknown j moved by `amount` along its direction (and the group its surface drags).
  auto moveUnknown = [&](int j, double amount) {
    std::vector<std::array<double, 2>> d = zero;
    const auto& dir = unknown[j].direction;
    d[step0.moves[unknown[j].move].node] = {amount * dir[0], amount * dir[1]};
    for (const FreeSurfaceStep::Drag& drag : step0.drags)
      if (drag.end == unknown[j].move) d[drag.node] = {drag.fraction * amount * dir[0], drag.fraction * amount * dir[1]};
    sim.moveNodes(extension.positions(d));
  };

  // Pass 1, the positions: ∂R/∂b_j (with the interior following), ∂U/∂b_j, ∂φ/∂b_j.
  const double eps = 1e-6 * surfaces.lengthScale();
  MultiVector rx(q.getMap(), nb);
  Teuchos::SerialDenseMatrix<int, double> G(nb, nb);
  std::vector<std::map<std::string, double>> phiB(nb), phiQ(nb);
  Vector rPlus(q.getMap()), rMinus(q.getMap());
  try {
    for (int j = 0; j < nb; ++j) {
      moveUnknown(j, eps);
      sim.model().assembler().residual(q, rPlus);
      const std::vector<double> uPlus = update(q);
      const auto phiPlus = responses(q);
      moveUnknown(j, -eps);
      sim.model().assembler().residual(q, rMinus);
      const std::vector<double> uMinus = update(q);
      const auto phiMinus = responses(q);
      rx.getVectorNonConst(j)->update(-1.0 / (2 * eps), rPlus, 1.0 / (2 * eps), rMinus, 0.0);  // −∂R/∂b_j
      for (int i = 0; i < nb; ++i) G(i, j) = (uPlus[i] - uMinus[i]) / (2 * eps);
      for (const auto& [name, value] : phiPlus) phiB[j][name] = (value - phiMinus.at(name)) / (2 * eps);
    }
  } catch (const std::exception& e) {  // a move that inverts a cell
    sim.moveNodes(base.coords);
    out.failure = std::string("moving a surface node: ") + e.what();
    return out;
  }
  sim.moveNodes(base.coords);

  // Y = −K_t⁻¹ ∂R/∂b with the converged factors.
  FlowModel& model = sim.model();
  model.restartLinearization();
  model.computeJacobian(q);
  MultiVector Y(q.getMap(), nb);
  model.solve(rx, Y);

  // Pass 2, the state: U_q Y_j and φ_q Y_j by central differences along Y_j.
  const double qScale = std::max(q.normInf(), 1e-300);
  auto along = [&](const Vector& direction, std::vector<double>& dU, std::map<std::string, double>& dPhi) {
    const double size = std::max(direction.normInf(), 1e-300);
    const double delta = 1e-6 * qScale / size;
    Vector x(q, Teuchos::Copy);
    x.update(delta, direction, 1.0);
    const std::vector<double> uPlus = update(x);
    const auto phiPlus = responses(x);
    x.update(-2.0 * delta, direction, 1.0);
    const std::vector<double> uMinus = update(x);
    const auto phiMinus = responses(x);
    dU.assign(nb, 0.0);
    for (int i = 0; i < nb; ++i) dU[i] = (uPlus[i] - uMinus[i]) / (2 * delta);
    for (const auto& [name, value] : phiPlus) dPhi[name] = (value - phiMinus.at(name)) / (2 * delta);
  };
  for (int j = 0; j < nb; ++j) {
    std::vector<double> dU;
    along(*Y.getVector(j), dU, phiQ[j]);
    for (int i = 0; i < nb; ++i) G(i, j) += dU[i];
  }
  // The linearized update's spectral radius by power iteration: < 1 where the plain update
  // converges (its ratio of successive moves).
  {
    std::vector<double> v(nb, 1.0), w(nb);
    double norm = 0.0;
    for (int it = 0; it < 200; ++it) {
      for (int i = 0; i < nb; ++i) {
        w[i] = 0.0;
        for (int j = 0; j < nb; ++j) w[i] += G(i, j) * v[j];
      }
      norm = 0.0;
      for (double x : w) norm = std::max(norm, std::abs(x));
      if (!(norm > 0.0)) break;
      for (int i = 0; i < nb; ++i) v[i] = w[i] / norm;
    }
    out.contraction = norm;
  }
  // (I − G) db = U_q dq_frozen for every parameter, then the responses.
  const auto& parameters = sensitivity.parameters();
  Teuchos::SerialDenseMatrix<int, double> A(nb, nb), rhs(nb, static_cast<int>(parameters.size()));
  std::vector<std::map<std::string, double>> phiFrozenQ(parameters.size());
  for (int i = 0; i < nb; ++i)
    for (int j = 0; j < nb; ++j) A(i, j) = (i == j ? 1.0 : 0.0) - G(i, j);
  for (size_t p = 0; p < parameters.size(); ++p) {
    std::vector<double> dU;
    std::map<std::string, double> unused;
    along(*sensitivity.solutionDerivatives().getVector(p), dU, unused);
    for (int i = 0; i < nb; ++i) rhs(i, static_cast<int>(p)) = dU[i];
  }
  Teuchos::SerialDenseMatrix<int, double> db(nb, static_cast<int>(parameters.size()));
  Teuchos::SerialDenseSolver<int, double> solver;
  solver.setMatrix(Teuchos::rcpFromRef(A));
  solver.setVectors(Teuchos::rcpFromRef(db), Teuchos::rcpFromRef(rhs));
  solver.factorWithEquilibration(true);
  if (solver.factor() != 0 || solver.solve() != 0) {
    out.failure = "I − G is singular: the surface's fixed point is not isolated";
    return out;
  }
  for (const auto& [name, byParameter] : sensitivity.responseDerivatives())
    for (size_t p = 0; p < parameters.size(); ++p) {
      double total = byParameter.at(parameters[p].name);
      for (int j = 0; j < nb; ++j) {
        const double shape = phiB[j].at(name) + phiQ[j].at(name);
        total += shape * db(j, static_cast<int>(p));
      }
      out.responses[name][parameters[p].name] = total;
    }
  out.computed = true;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log() << "sensitivity: total derivatives through the free surfaces (" << nb << " surface unknowns, |G| = "
        << out.contraction << ", " << out.seconds << " s)\n";
  for (const auto& [name, byParameter] : out.responses)
    for (const auto& [parameter, value] : byParameter)
      log() << "sensitivity:   d" << name << "/d(" << parameter << ") total = " << value << "\n";
  return out;
}

}  // namespace flowform
