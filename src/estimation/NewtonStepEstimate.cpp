#include "flowform/estimation/NewtonStepEstimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/estimation/RefinedRun.hpp"
#include "flowform/estimation/TwoLevelEstimate.hpp"
#include "flowform/responses/ResponseRegistry.hpp"
#include "flowform/sensitivity/BoundaryValuePartials.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"

namespace flowform {

ErrorEstimate NewtonStepEstimate::estimate(const CaseRun& coarseRun, const CaseRunFactory& makeRun,
                                           const std::vector<std::string>& indicatorResponses,
                                           const IndicatorsWanted& /*wanted: made before the estimate, always*/) {
  const auto start = std::chrono::steady_clock::now();
  ErrorEstimate estimate;
  estimate.method = kName;
  const Problem& coarse = coarseRun.problem();
  // Where Newton steps cannot estimate, the two-level estimate (its refined solve converged),
  // the reason logged and flagged in its details.
  auto twoLevelInstead = [&](const std::string& why, const char* flag) {
    log() << "error estimate: " << why << "\n";
    ErrorEstimate twoLevel = TwoLevelEstimate::estimate(coarseRun, makeRun, indicatorResponses);
    twoLevel.details[flag] = 1.0;
    return twoLevel;
  };
  // At the carried shape a step leaves every shape response (the swell) as it is: free-surface
  // cases get the two-level estimate (NewtonStepEstimate.hpp).
  if (!coarse.freeSurfaces().empty())
    return twoLevelInstead("free surfaces: the two-level estimate (a Newton step at the carried shape does not move them)",
                           "free_surface_fallback");
  // Likewise a Rigid Inflow: Newton steps at the coarse run's speed would not balance it on the
  // refined mesh (its speed is found by re-solves, Problem::balanceRigidInflow).
  if (!coarse.boundaryConditions().rigidInflow().group.empty())
    return twoLevelInstead("a Rigid Inflow: the two-level estimate (Newton steps do not balance its speed)",
                           "rigid_inflow_fallback");
  const Teuchos::ParameterList& settings = coarse.parameters().sublist("Error Estimation");
  estimate.order = settings.get<double>("Order");
  const int maxSteps = settings.get<int>("Newton Steps");
  const double settled = settings.get<double>("Step Tolerance");
  const BudgetScope scope("the Newton step error estimate (Newton steps on the mesh refined once more)", nullptr);
  Laps lap(estimate.timings);

  const std::unique_ptr<CaseRun> fineRun = makeRefinedRun(coarse, makeRun);
  Problem& fine = fineRun->problem();
  estimate.refinedDofs = static_cast<GO>(fine.dofMap().numGlobalDofs());
  lap("refined_setup");
  // The indicators exactly as the two-level estimate makes them (at I u_h with the statuses
  // carried as they were, a node inside an old zone limit free: TwoLevelEstimate.cpp says why),
  // at the cost of one more factorization; then the steps' start, the zone limits decided.
  if (!indicatorResponses.empty()) {
    fine.startFrom(coarse, false);
    addIndicators(coarse, fine, indicatorResponses, false, estimate);
    lap("indicators");
  }
  fine.startFrom(coarse);
  lap("transfer");

  // Newton's steps from I u_h: the first with the exact K_f there, the next ones with the case's
  // Newton linearization (the dual one by default, which does not overshoot where the exact
  // tangent does: docs/theory.md §9). Before each new factorization a chord step with the
  // factors at hand (one back-substitution) says whether the responses have settled: every
  // differentiable response moved by at most Step Tolerance times its distance from φ_h (the
  // estimate is then about that accurate, Newton converging at least linearly from there); the
  // chord step is then kept and no more factorizations are made. At most Newton Steps
  // factorizations. The other responses (a dead-zone area, a contact length) jump with single
  // cells or nodes and would keep the steps going.
  FlowModel& model = fine.model();
  Vector& x = *fine.solutionPtr();
  Vector residual(fine.dofMap().ownedMap()), step(fine.dofMap().ownedMap()), trial(fine.dofMap().ownedMap());
  model.useDualLinearization(fine.parameters().sublist("Solver").get<std::string>("Newton Linearization") ==
                             "Stress-Velocity");
  model.restartLinearization();
  const Teuchos::ParameterList& responseLists = coarse.parameters().sublist("Responses");
  auto smooth = [&](const std::string& name) {
    const Teuchos::ParameterList& r = responseLists.sublist(name);
    const int type = responseTypeIndex(r.isParameter("Type") ? r.get<std::string>("Type") : responseTypes().front().name);
    return type >= 0 && responseTypes()[type].differentiable;
  };
  // The largest |φ(to) − φ(from)| / |φ(to) − φ_h| over the differentiable responses; infinite when
  // a response is not finite (steps that diverged have settled nothing).
  auto moved = [&](const std::map<std::string, double>& from, const std::map<std::string, double>& to) {
    double largest = 0.0;
    for (const auto& [name, value] : to) {
      const auto h = coarseRun.functionals().find(name);
      if (h == coarseRun.functionals().end() || !smooth(name)) continue;
      if (!std::isfinite(value)) return std::numeric_limits<double>::infinity();
      const double by = std::abs(value - from.at(name)), distance = std::abs(value - h->second);
      // A response that does not move (zero to round-off, or exact on both meshes) is settled.
      if (by > 1e-12 * std::max(std::abs(value), 1.0)) largest = std::max(largest, by / std::max(distance, 1e-300));
    }
    return largest;
  };
  std::map<std::string, double> refined = coarseRun.functionals();
  int factorizations = 0, chordSteps = 0;
  double change = 1.0;  // of the last step taken
  model.residual(x, residual);
  estimate.details["residual_0"] = residual.norm2();
  while (true) {
    if (factorizations > 0) {  // the chord step: settled?
      model.solve(residual, step);
      trial.update(1.0, x, -1.0, step, 0.0);
      lap("solves");
      const std::map<std::string, double> next = fine.evaluateResponses(trial);
      const double chordChange = moved(refined, next);
      lap("responses");
      if (chordChange <= settled) {
        x.update(1.0, trial, 0.0);
        refined = next;
        change = chordChange;
        ++chordSteps;
        break;
      }
      if (factorizations == maxSteps) {  // not settled: the last Newton iterate, and how far it is
        change = chordChange;
        break;
      }
    }
    model.assembleJacobian(x);
    lap("assembly");
    try {
      model.factorJacobian();
    } catch (const std::exception& e) {
      estimate.failure = "the refined Jacobian (Newton step " + std::to_string(factorizations + 1) +
                         ") could not be factored: " + e.what();
      estimate.seconds = secondsSince(start);
      return estimate;
    }
    ++factorizations;
    lap("factorization");
    model.solve(residual, step);
    x.update(-1.0, step, 1.0);
    lap("solves");
    const std::map<std::string, double> next = fine.evaluateResponses(x);
    change = moved(refined, next);
    refined = next;
    lap("responses");
    model.residual(x, residual);
    estimate.details["residual_" + std::to_string(factorizations)] = residual.norm2();
    lap("assembly");
    if (!std::isfinite(change) || !std::isfinite(residual.norm2())) break;  // diverged: no more steps
  }
  estimate.details["newton_steps"] = factorizations;
  estimate.details["chord_steps"] = chordSteps;
  estimate.details["last_step_change"] = change;
  estimate.details["settled"] = change <= settled ? 1.0 : 0.0;
  if (change > settled) {
    // Steps that do not settle (or diverge to a non-finite state) estimate nothing (a step that
    // moved a response by its whole estimate): the refined solve is converged instead, with its
    // own fallbacks.
    std::ostringstream why;
    if (std::isfinite(change))
      why << "the responses did not settle in " << factorizations << " Newton steps (the last step moved one by "
          << change << " of its estimate; Error Estimation/Newton Steps): the two-level estimate instead";
    else
      why << "the Newton steps diverged (a response or the residual not finite after " << factorizations
          << " step(s)): the two-level estimate instead";
    ErrorEstimate twoLevel = twoLevelInstead(why.str(), "unsettled_fallback");
    twoLevel.details["unsettled_newton_steps"] = factorizations;
    twoLevel.details["unsettled_last_step_change"] = change;
    return twoLevel;
  }

  // DDM on the refined mesh at u_f, K_f factored there exactly (NewtonStepEstimate.hpp).
  std::unique_ptr<Sensitivity> sensitivity;
  if (coarseRun.sensitivity().computed()) {
    Teuchos::ParameterList list = fine.parameters().sublist("Sensitivity");
    list.set("Jacobian", "Converged");
    list.set("Finite Difference Check", false);
    sensitivity = std::make_unique<Sensitivity>(&list, fine.contactWalls(), fine.responses(),
                                                fine.physics().material.law, givenGeoParameters(fine.parameters()),
                                                givenBoundaryValues(fine.parameters()),
                                                fine.dofMap().fields());
    const GeoPartialsSource geo = geoPartialsOf(fine);
    sensitivity->compute(model, x, fine.responses(), fine.mesh(), fine.dofMap(), fine.contactWalls(), nullptr, &geo);
    lap("sensitivities");
  }
  extrapolate(coarseRun, refined, sensitivity && sensitivity->computed() ? &sensitivity->responseDerivatives() : nullptr,
              nullptr, estimate);
  estimate.estimated = true;
  estimate.seconds = secondsSince(start);
  log() << "error estimate: " << factorizations << " Newton step(s) and " << chordSteps
        << " chord step(s) on the refined mesh (" << estimate.refinedDofs << " dofs): |R_f| "
        << estimate.details["residual_0"] << " at I u_h, "
        << estimate.details["residual_" + std::to_string(factorizations)] << " at the last Newton iterate\n";
  return estimate;
}

}  // namespace flowform
