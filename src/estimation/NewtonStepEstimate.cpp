#include "flowform/estimation/NewtonStepEstimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/estimation/RefinedRun.hpp"
#include "flowform/responses/ResponseRegistry.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"
#include "flowform/sensitivity/ShapeDerivative.hpp"

namespace flowform {

ErrorEstimate NewtonStepEstimate::estimate(const CaseRun& coarseRun, const CaseRunFactory& makeRun,
                                           const std::vector<std::string>& indicatorResponses) {
  const auto start = std::chrono::steady_clock::now();
  ErrorEstimate estimate;
  estimate.method = kName;
  const Problem& coarse = coarseRun.problem();
  const Teuchos::ParameterList& settings = coarse.parameters().sublist("Error Estimation");
  estimate.order = settings.get<double>("Order");
  const int maxSteps = settings.get<int>("Newton Steps");
  const double settled = settings.get<double>("Step Tolerance");
  const BudgetScope scope("the Newton step error estimate (Newton steps on the mesh refined once more)", nullptr);
  auto clock = std::chrono::steady_clock::now();
  auto lap = [&](const std::string& what) {
    estimate.timings[what] += secondsSince(clock);
    clock = std::chrono::steady_clock::now();
  };

  const std::unique_ptr<CaseRun> fineRun = makeRefinedRun(coarse, makeRun);
  Problem& fine = fineRun->problem();
  estimate.refinedDofs = static_cast<GO>(fine.dofMap().numGlobalDofs());
  lap("refined_setup");
  fine.startFrom(coarse);
  lap("transfer");

  // Newton's steps from I u_h: the first with the exact K_f there (whose factors the indicators'
  // adjoints use), the next ones with the case's Newton linearization (the dual one by default,
  // which does not overshoot where the exact tangent does: docs/theory.md §9).
  FlowModel& model = fine.model();
  Vector& x = *fine.solutionPtr();
  Vector residual(fine.dofMap().ownedMap()), step(fine.dofMap().ownedMap());
  model.useDualLinearization(fine.parameters().sublist("Solver").get<std::string>("Newton Linearization") ==
                             "Stress-Velocity");
  model.restartLinearization();
  // Steps until every differentiable response has settled: its last step moved it by at most
  // Step Tolerance times its distance from φ_h (the estimate is then that accurate, if Newton
  // converges at least linearly from there), or Newton Steps. The others (a dead-zone area,
  // a contact length) jump with single cells or nodes and would keep the steps going.
  const Teuchos::ParameterList& responseLists = coarse.parameters().sublist("Responses");
  auto smooth = [&](const std::string& name) {
    const Teuchos::ParameterList& r = responseLists.sublist(name);
    const int type = responseTypeIndex(r.isParameter("Type") ? r.get<std::string>("Type") : responseTypes().front().name);
    return type >= 0 && responseTypes()[type].differentiable;
  };
  std::map<std::string, double> refined = coarseRun.functionals();
  int steps = 0;
  double change = 0.0;  // the largest |φ^k − φ^(k−1)| / |φ^k − φ_h| of the last step
  while (steps < maxSteps) {
    const int k = steps++;
    model.residual(x, residual);
    estimate.details["residual_" + std::to_string(k)] = residual.norm2();
    model.assembleJacobian(x);
    lap("assembly");
    try {
      model.factorJacobian();
    } catch (const std::exception& e) {
      estimate.failure = "the refined Jacobian (Newton step " + std::to_string(k + 1) + ") could not be factored: " + e.what();
      estimate.seconds = secondsSince(start);
      return estimate;
    }
    lap("factorization");
    if (k == 0) {
      addIndicators(coarse, fine, indicatorResponses, true, estimate);
      lap("indicators");
    }
    model.solve(residual, step);
    x.update(-1.0, step, 1.0);
    lap("solves");
    const std::map<std::string, double> next = fine.evaluateResponses(x);
    change = 0.0;
    for (const auto& [name, value] : next) {
      const auto h = coarseRun.functionals().find(name);
      if (h == coarseRun.functionals().end() || !smooth(name)) continue;
      const double moved = std::abs(value - refined[name]), distance = std::abs(value - h->second);
      // A response that does not move (zero to round-off, or exact on both meshes) is settled.
      if (moved > 1e-12 * std::max(std::abs(value), 1.0)) change = std::max(change, moved / std::max(distance, 1e-300));
    }
    refined = next;
    lap("responses");
    if (change <= settled) break;
  }
  model.residual(x, residual);  // what the steps left
  estimate.details["residual_" + std::to_string(steps)] = residual.norm2();
  estimate.details["steps"] = steps;
  estimate.details["last_step_change"] = change;

  // DDM on the refined mesh at u_f with the factors of K_f at I u_h (back-substitutions only).
  std::unique_ptr<Sensitivity> sensitivity;
  ShapeDerivative shape;
  if (coarseRun.sensitivity().computed()) {
    Teuchos::ParameterList list = fine.parameters().sublist("Sensitivity");
    list.set("Jacobian", std::getenv("FLOWFORM_EST_SENS_EXACT") ? "Converged" : "Last Newton Iterate");
    list.set("Finite Difference Check", false);
    sensitivity = std::make_unique<Sensitivity>(&list, fine.contactWalls(), fine.responses(),
                                                fine.physics().material.law);
    sensitivity->compute(model, x, fine.responses(), fine.mesh(), fine.dofMap(), fine.contactWalls());
    if (sensitivity->computed() && coarseRun.shapeDerivative().computed) shape = totalShapeDerivative(fine, *sensitivity);
    lap("sensitivities");
  }
  extrapolate(coarseRun, refined, sensitivity && sensitivity->computed() ? &sensitivity->responseDerivatives() : nullptr,
              shape.computed ? &shape.responses : nullptr, estimate);
  estimate.estimated = true;
  estimate.seconds = secondsSince(start);
  log() << "error estimate: " << steps << " Newton step(s) on the refined mesh (" << estimate.refinedDofs
        << " dofs): |R_f| " << estimate.details["residual_0"] << " -> " << residual.norm2() << "\n";
  return estimate;
}

}  // namespace flowform
