#include "flowform/estimation/CoarserMeshEstimate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/estimation/NewtonStepEstimate.hpp"
#include "flowform/estimation/RefinedRun.hpp"
#include "flowform/estimation/ResponseAdjoint.hpp"
#include "flowform/estimation/TwoLevelEstimate.hpp"

namespace flowform {

int CoarserMeshEstimate::levelsOf(const Problem& run, bool indicatorsWanted) {
  const int refinements = run.parameters().sublist("Mesh").get<int>("Uniform Refinements");
  // With free surfaces each level converges its own surfaces: the values compare, but the
  // indicators, interpolated between meshes whose surfaces differ, would not (the header).
  if (refinements < 1 || (!run.freeSurfaces().empty() && indicatorsWanted)) return 0;
  return std::min(run.parameters().sublist("Error Estimation").get<int>("Coarser Levels"), refinements);
}

std::vector<std::unique_ptr<CaseRun>> CoarserMeshEstimate::solveLevels(const Problem& run, int levels,
                                                                       const CaseRunFactory& makeRun,
                                                                       std::string& failure, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  const int refinements = run.parameters().sublist("Mesh").get<int>("Uniform Refinements");
  std::vector<std::unique_ptr<CaseRun>> solved(levels);
  for (int level = levels; level >= 1; --level) {
    std::unique_ptr<CaseRun>& at = solved[level - 1];
    at = makeLevelRun(run, refinements - level, makeRun);
    if (level < levels) at->problem().startFrom(solved[level]->problem());
    else if (run.startsFromOtherState()) at->problem().startFrom(run);  // injected: its nodes are the run's
    log() << "nested start: the case on the mesh " << level << " refinement(s) coarser ("
          << at->problem().dofMap().numGlobalDofs() << " dofs)\n";
    at->run();
    if (at->exitStatus() != 0) {
      failure = "the mesh " + std::to_string(level) + " refinement(s) coarser (" +
                std::to_string(at->problem().dofMap().numGlobalDofs()) + " dofs) did not converge: " +
                at->statusMessage();
      solved.clear();
      break;
    }
  }
  seconds = secondsSince(start);
  return solved;
}

ErrorEstimate CoarserMeshEstimate::estimate(CaseRun& run, const CaseRunFactory& makeRun,
                                            const std::vector<std::string>& indicatorResponses,
                                            const IndicatorsWanted& wanted) {
  const auto start = std::chrono::steady_clock::now();
  Problem& fine = run.problem();
  const int levels = levelsOf(fine, !indicatorResponses.empty());
  if (levels == 0) {
    const bool unrefined = fine.parameters().sublist("Mesh").get<int>("Uniform Refinements") < 1;
    log() << "error estimate: "
          << (unrefined ? "the mesh is not refined (Mesh/Uniform Refinements = 0): the Newton Step estimate"
                        : "indicators with free surfaces: the two-level estimate")
          << " instead of the coarser mesh's\n";
    ErrorEstimate other = unrefined ? NewtonStepEstimate::estimate(run, makeRun, indicatorResponses, wanted)
                                    : TwoLevelEstimate::estimate(run, makeRun, indicatorResponses, wanted);
    other.details["coarser_mesh_fallback"] = 1.0;
    return other;
  }
  ErrorEstimate estimate;
  estimate.method = kName;
  estimate.otherLevel = "coarser";
  estimate.order = fine.parameters().sublist("Error Estimation").get<double>("Order");
  const BudgetScope scope("the coarser-mesh error estimate (the case on the mesh one refinement coarser)", nullptr);
  Laps lap(estimate.timings);

  // The same case one (and two) refinements coarser, on the size field the run's mesh was made
  // with: solved before the run (nested start), or now, each from the next finer level's solution.
  const Teuchos::ParameterList& settings = fine.parameters().sublist("Error Estimation");
  const int refinements = fine.parameters().sublist("Mesh").get<int>("Uniform Refinements");
  std::vector<std::unique_ptr<CaseRun>> coarser;
  if (static_cast<int>(run.coarserLevels().size()) == levels) {
    coarser = std::move(run.coarserLevels());
    estimate.details["nested_start"] = 1.0;
  }
  run.coarserLevels().clear();
  for (int level = static_cast<int>(coarser.size()) + 1; level <= levels; ++level) {
    coarser.push_back(makeLevelRun(fine, refinements - level, makeRun));
    Problem& problem = coarser.back()->problem();
    const std::string name = "level_" + std::to_string(level);
    lap(name + "_setup");
    problem.startFrom(level == 1 ? static_cast<const Problem&>(fine) : coarser[level - 2]->problem());
    coarser.back()->run();
    lap(name + "_run");
    if (coarser.back()->exitStatus() != 0) {
      estimate.failure = "the solve on the mesh " + std::to_string(level) + " refinement(s) coarser (" +
                         std::to_string(problem.dofMap().numGlobalDofs()) + " dofs) did not converge: " +
                         problem.report().message;
      estimate.seconds = secondsSince(start);
      return estimate;
    }
  }
  for (int level = 1; level <= levels; ++level) {
    const Problem& problem = coarser[level - 1]->problem();
    const std::string name = "level_" + std::to_string(level);
    estimate.details[name + "_dofs"] = static_cast<double>(problem.dofMap().numGlobalDofs());
    estimate.details[name + "_newton_iterations"] = problem.report().newtonIterations;
  }
  Problem& coarse = coarser.front()->problem();
  estimate.refinedDofs = static_cast<GO>(coarse.dofMap().numGlobalDofs());
  if (!coarse.freeSurfaces().empty()) estimate.refinedSurfaceUpdates = coarse.freeSurfaceReport().iterations;
  // One coarser level: η = (φ_h − φ_2h) / (2^p − 1) = −(φ_2h − φ_h) / (2^p − 1). Two: with
  // D1 = φ_2h − φ_h, D2 = φ_4h − φ_2h and the error A h^p + B h^q, a = A h^p (2^p − 1) and
  // b = B h^q (2^q − 1) solve D1 = a + b, D2 = 2^p a + 2^q b, and η = −a/(2^p − 1) − b/(2^q − 1)
  // = c1 D1 + c2 D2 (CoarserMeshEstimate.hpp).
  const double p = estimate.order, q = settings.get<double>("Second Order");
  const double k = 1.0 / (std::pow(2.0, p) - 1.0) - 1.0 / (std::pow(2.0, q) - 1.0);
  const double c2 = levels == 2 ? k / (std::pow(2.0, q) - std::pow(2.0, p)) : 0.0;
  const double c1 = -1.0 / (std::pow(2.0, p) - 1.0) - std::pow(2.0, p) * c2;
  estimate.details["c1"] = c1;
  estimate.details["c2"] = c2;
  const ResponseDerivatives* sensitivities =
      coarser.front()->sensitivity().computed() ? &coarser.front()->sensitivity().responseDerivatives() : nullptr;
  const ResponseDerivatives* totalShape =
      coarser.front()->shapeDerivative().computed ? &coarser.front()->shapeDerivative().responses : nullptr;
  estimateFromOtherLevel(run, coarser.front()->functionals(), sensitivities, totalShape, c1, estimate);
  if (levels == 2) {  // + c2 D2 for every response and sensitivity both levels have
    const CaseRun& second = *coarser.back();
    for (auto& [name, eta] : estimate.functionals) {
      const auto at = second.functionals().find(name);
      if (at == second.functionals().end()) continue;
      eta += c2 * (at->second - coarser.front()->functionals().at(name));
      estimate.details["level_2_" + name] = at->second;
    }
    // + c2 D2 for each derivative both levels have (DDM on the frozen shape, total through the surfaces)
    auto addSecondLevel = [&](const ResponseDerivatives& near, const ResponseDerivatives& far, ResponseDerivatives& etas) {
      for (auto& [name, byParameter] : etas)
        for (auto& [parameter, eta] : byParameter) {
          const auto response = far.find(name);
          if (response == far.end() || !response->second.count(parameter)) continue;
          eta += c2 * (response->second.at(parameter) - near.at(name).at(parameter));
        }
    };
    if (sensitivities && second.sensitivity().computed())
      addSecondLevel(*sensitivities, second.sensitivity().responseDerivatives(), estimate.sensitivities);
    if (totalShape && second.shapeDerivative().computed)
      addSecondLevel(*totalShape, second.shapeDerivative().responses, estimate.sensitivitiesTotalShape);
  }

  if (!indicatorResponses.empty() && (!wanted || wanted(estimate))) {
    Vector interpolated(fine.dofMap().ownedMap()), residual(fine.dofMap().ownedMap()), zeta(fine.dofMap().ownedMap());
    interpolate(coarse.mesh(), coarse.dofMap(), replicate(coarse.solution(), coarse.dofMap()), fine.mesh(),
                fine.dofMap(), interpolated);
    fine.boundaryConditions().imposeOnSolution(interpolated);
    // The coarser level's statuses, carried as they are (no zone limit decided, no
    // complementarity), for the indicators' linearization; the run's own afterwards.
    std::vector<ContactWall>& walls = fine.contactWalls();
    std::vector<ContactWall::State> kept;
    std::vector<bool> complementarity;
    for (ContactWall& wall : walls) {
      kept.push_back(wall.state());
      complementarity.push_back(wall.complementarity());
      wall.leaveComplementarity();
      for (const ContactWall& from : coarse.contactWalls())
        if (from.name() == wall.name()) wall.takeStatusesFrom(from);
    }
    FlowModel& model = fine.model();
    model.residual(interpolated, residual);
    bool factor = true;
    for (const std::string& name : indicatorResponses) {
      if (responseAdjoint(model, interpolated, fine.responses(), name, fine.mesh(), zeta, factor))
        estimate.indicators[name] = coarseIndicator(coarse, fine, residual, zeta);
      factor = false;  // the first adjoint factored K_h at I u_2h
    }
    for (std::size_t w = 0; w < walls.size(); ++w) {
      if (complementarity[w]) walls[w].enterComplementarity();
      walls[w].restore(kept[w]);
    }
    estimate.indicatorMesh = std::make_shared<const Mesh>(coarse.meshAsMade());
    lap("indicators");
  }
  estimate.estimated = true;
  estimate.seconds = secondsSince(start);
  log() << "error estimate: " << levels << " coarser level(s), the first " << estimate.refinedDofs << " dofs, in "
        << estimate.seconds << " s\n";
  return estimate;
}

}  // namespace flowform
