#include "flowform/estimation/AdaptiveLoop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/estimation/EstimationMethods.hpp"
#include "flowform/mesh/SizeField.hpp"

namespace flowform {

namespace {

/// Mean length of the edges at each node (a cell's edges, each counted from both cells).
std::vector<double> nodalSizes(const Mesh& mesh) {
  std::vector<double> sum(mesh.numNodes(), 0.0), count(mesh.numNodes(), 0.0);
  const int npc = nodesPerCell(mesh.cellType);
  for (GO c = 0; c < mesh.numCells(); ++c)
    for (int a = 0; a < npc; ++a) {
      const GO i = mesh.cell(c)[a], j = mesh.cell(c)[(a + 1) % npc];
      const double l = std::hypot(mesh.coords[i][0] - mesh.coords[j][0], mesh.coords[i][1] - mesh.coords[j][1]);
      sum[i] += l;
      sum[j] += l;
      count[i] += 1.0;
      count[j] += 1.0;
    }
  for (GO n = 0; n < mesh.numNodes(); ++n) sum[n] /= std::max(count[n], 1.0);
  return sum;
}

/// What the loop adapts to: a response, or the derivative of one by a sensitivity parameter
/// (sized by the response's indicators scaled to the derivative's estimate).
struct Target {
  std::string response, parameter;  ///< parameter empty: the response itself
  std::string label() const { return parameter.empty() ? response : "d(" + response + ")/d(" + parameter + ")"; }
  double value(const CaseRun& run) const {
    return parameter.empty() ? run.functionals().at(response)
                             : run.sensitivity().responseDerivatives().at(response).at(parameter);
  }
  /// η, or NaN when the estimate has none (no sensitivities on the other level).
  double eta(const ErrorEstimate& estimate) const {
    if (parameter.empty()) return estimate.functionals.at(response);
    const auto byResponse = estimate.sensitivities.find(response);
    if (byResponse == estimate.sensitivities.end() || !byResponse->second.count(parameter))
      return std::numeric_limits<double>::quiet_NaN();
    return byResponse->second.at(parameter);
  }
  /// |η| / |value| (NaN without an estimate).
  double relativeError(const CaseRun& run, const ErrorEstimate& estimate) const {
    return std::abs(eta(estimate)) / std::max(std::abs(value(run)), 1e-300);
  }
};

constexpr double kMaxGrowth = 16.0;  ///< the next cycle's dofs at most this many times this one's
constexpr double kLocalOrder = 2.0;  ///< s: a node's share of the estimate ∝ h^s (AdaptiveLoop.hpp)
constexpr double kMinRatio = 1.0 / 32.0, kMaxRatio = 1.5;  ///< h'/h per cycle at most this much finer, coarser
/// No size below this fraction of the first mesh's smallest: gmsh made a sliver (a zero-area
/// cell at the die lip) from sizes 10⁴ times finer than the first mesh's.
constexpr double kSmallestSize = 1.0 / 128.0;

/// The sizes the next run's mesh should have, at the nodes of the mesh the indicators are on
/// (AdaptiveLoop.hpp); that mesh (as made) is `on`.
std::vector<double> nextSizes(const CaseRun& sim, const std::vector<Target>& targets, double tolerance,
                              double minSize, double maxSize, double maxDofs, Mesh& on, double& predictedDofs) {
  const ErrorEstimate& estimate = sim.errorEstimate();
  // The free surfaces' moves stretch this mesh and the next alike (carryShape maps the next mesh
  // as it maps this one): the sizes are those of the mesh as made, where the next mesh is made.
  on = estimate.indicatorMesh ? *estimate.indicatorMesh : sim.problem().meshAsMade();
  // The coarser level's cells are split in four in the run's mesh: its sizes are twice the run's.
  const double level = estimate.indicatorMesh ? 0.5 : 1.0;
  const Mesh& mesh = on;
  std::vector<double> e(mesh.numNodes(), 0.0);
  for (const Target& target : targets) {
    const std::vector<double>& shares = estimate.indicators.at(target.response);
    double total = 0.0;
    for (double v : shares) total += v;
    if (total <= 0.0) continue;
    // Scaled so that the shares add up to |η_φ| / (tol |φ|).
    const double scale = std::abs(target.eta(estimate)) /
                         (tolerance * std::max(std::abs(target.value(sim)), 1e-300) * total);
    for (GO n = 0; n < mesh.numNodes(); ++n) e[n] += scale * shares[n];
  }
  // Equidistribution at the least node count: with e_a' = e_a (h_a'/h_a)^s and N' = Σ (h_a/h_a')²,
  // minimizing N' under Σ e_a' = 1/2 gives h_a'/h_a = (λ/e_a)^(1/(s+2)), λ^(s/(s+2)) = ½ / Σ e_a^(2/(s+2)).
  const double s = kLocalOrder;
  double sum = 0.0;
  for (double v : e) sum += std::pow(v, 2.0 / (s + 2.0));
  const double lambda = sum > 0.0 ? std::pow(0.5 / sum, (s + 2.0) / s) : 0.0;
  std::vector<double> h = nodalSizes(mesh), next(h.size());
  for (double& v : h) v *= level;
  double predictedNodes = 0.0;
  for (GO n = 0; n < mesh.numNodes(); ++n) {
    const double ratio = e[n] > 0.0 ? std::clamp(std::pow(lambda / e[n], 1.0 / (s + 2.0)), kMinRatio, kMaxRatio) : kMaxRatio;
    next[n] = std::clamp(h[n] * ratio, minSize, maxSize);
    predictedNodes += (h[n] / next[n]) * (h[n] / next[n]);
  }
  const double dofsPerNode = 3.0;
  predictedDofs = dofsPerNode * predictedNodes;
  if (predictedDofs > maxDofs) {
    const double grow = std::sqrt(predictedDofs / maxDofs);
    for (double& v : next) v *= grow;
    predictedDofs = maxDofs;
  }
  return next;
}

}  // namespace

int runAdaptive(const Teuchos::ParameterList& caseParams, const CaseRunFactory& makeRun, const std::string& outDir,
                std::string* message) {
  const Teuchos::ParameterList& adaptivity = caseParams.sublist("Adaptivity");
  std::vector<Target> targets;
  std::vector<std::string> indicatorResponses;  // each target's response, once
  for (const std::string& name : adaptivity.get<Teuchos::Array<std::string>>("Responses")) targets.push_back({name, ""});
  for (const std::string& entry : adaptivity.get<Teuchos::Array<std::string>>("Sensitivities")) {
    const std::size_t slash = entry.find('/');  // validateCase checked the form
    targets.push_back({entry.substr(0, slash), entry.substr(slash + 1)});
  }
  for (const Target& target : targets)
    if (std::find(indicatorResponses.begin(), indicatorResponses.end(), target.response) == indicatorResponses.end())
      indicatorResponses.push_back(target.response);
  const double tolerance = adaptivity.get<double>("Target Relative Error");
  // The estimate's effectivity (estimate / true error) is measured in [0.7, 1.1] on the extrusion
  // (docs/theory.md §7): the loop stops when Safety Factor × the estimate meets the target, so
  // that the true error does too, and sizes the next mesh for that.
  const double safety = adaptivity.get<double>("Safety Factor");
  const int maxCycles = adaptivity.get<int>("Maximum Cycles");
  const double maxDofs = adaptivity.get<int>("Maximum Dofs");

  const auto loopStart = std::chrono::steady_clock::now();
  nlohmann::json cycles = nlohmann::json::array();
  // Later cycles are meshed with the sizes the field gives, as they are: the case's Uniform
  // Refinements and Size Factor shaped the first mesh, from which the field's sizes are taken.
  Teuchos::ParameterList remeshed = caseParams;
  remeshed.sublist("Mesh").set("Size Factor", 1.0);
  // With the coarser-mesh estimate (CoarserMeshEstimate.hpp) each later cycle's mesh is the
  // field's mesh at 2^L times the sizes refined L times (L ≤ its Coarser Levels, fewer where the
  // coarsest would have less than a quarter of the first mesh's dofs): the estimate's coarsest
  // level is the field's mesh itself. Not with free surfaces (that estimate falls back to the
  // two-level one there).
  const std::string method = caseParams.sublist("Error Estimation").get<std::string>("Method");
  const bool nested = adaptiveEstimationMethod(method) == CoarserMeshEstimate::kName;
  int levelsAllowed = 0;  // Coarser Levels, when the loop nests its meshes
  double firstDofs = 0.0;
  std::unique_ptr<CaseRun> sim, previous;
  SizeField field;
  double minSize = 0.0, maxSize = 0.0;
  bool met = false;
  std::string why;
  int done = 0;  // cycles solved and estimated
  const BudgetScope scope("the adaptivity loop", [&] { return std::to_string(done) + " cycle(s)"; });
  // A response whose value is below what the solver resolves (|value| <= the absolute residual
  // tolerance, in either mesh) is zero to round-off: its relative error means nothing, and the
  // loop would refine to Maximum Dofs for Maximum Cycles chasing it.
  auto number = [](double v) {
    std::ostringstream os;
    os << std::setprecision(3) << v;
    return os.str();
  };
  for (int cycle = 0; cycle < maxCycles; ++cycle) {
    const auto start = std::chrono::steady_clock::now();
    sim = makeRun(cycle == 0 ? caseParams : remeshed, cycle == 0 ? nullptr : &field);
    if (cycle == 0) {  // the targets and the .geo were checked with the case (validateCase)
      const std::vector<double> h = nodalSizes(sim->problem().meshAsMade());
      maxSize = *std::max_element(h.begin(), h.end());
      minSize = kSmallestSize * *std::min_element(h.begin(), h.end());
      if (nested && sim->problem().freeSurfaces().empty())
        levelsAllowed = caseParams.sublist("Error Estimation").get<int>("Coarser Levels");
      firstDofs = static_cast<double>(sim->problem().dofMap().numGlobalDofs());
    }
    if (previous) sim->problem().startFrom(previous->problem());
    sim->deferFiniteDifferenceCheck();  // only the last cycle's sensitivities are checked
    log() << "adaptivity: cycle " << cycle << ": " << sim->problem().dofMap().numGlobalDofs() << " dofs\n";
    sim->run();
    if (sim->exitStatus() != 0) {
      why = budgetWasSpent() ? budgetMessage()
                             : "cycle " + std::to_string(cycle) + ": the solve did not converge: " + sim->statusMessage();
      break;
    }
    // A target met: Safety Factor × its estimated relative error within the target.
    auto meets = [&](double relative) { return safety * relative <= tolerance; };  // false for NaN
    // The indicators only size a next cycle: none after one that meets the target, or the last.
    sim->estimateErrors(indicatorResponses, [&](const ErrorEstimate& e) {
      return cycle + 1 < maxCycles && std::any_of(targets.begin(), targets.end(), [&](const Target& target) {
               return !meets(target.relativeError(*sim, e));
             });
    });
    const ErrorEstimate& estimate = sim->errorEstimate();
    if (!estimate.estimated) {
      why = budgetWasSpent() ? budgetMessage()
                             : "cycle " + std::to_string(cycle) + ": no error estimate (" + estimate.failure + ")";
      break;
    }
    ++done;
    nlohmann::json entry = {{"cycle", cycle},
                            {"dofs", sim->problem().dofMap().numGlobalDofs()},
                            {"newton_iterations", sim->problem().report().newtonIterations},
                            {"contact_changes", sim->problem().contactChanges()},
                            {"free_surface_iterations", sim->problem().freeSurfaceReport().iterations},
                            {"functionals", sim->functionals()},
                            {"error_estimate", estimate.functionals},
                            {"error_estimation_method", estimate.method},
                            {"error_estimation_seconds", estimate.seconds}};
    if (sim->sensitivity().computed()) entry["sensitivities"] = sim->sensitivity().responseDerivatives();
    if (!estimate.sensitivities.empty()) entry["sensitivities_error_estimate"] = estimate.sensitivities;
    met = true;
    for (const Target& target : targets) {
      const double relative = target.relativeError(*sim, estimate);
      if (!std::isfinite(relative)) {  // a derivative the estimate did not reach
        why = "cycle " + std::to_string(cycle) + ": no error estimate of " + target.label() + " (" + estimate.method +
              " estimated no sensitivities)";
        met = false;
        break;
      }
      entry["relative_error_estimate"][target.label()] = relative;
      log() << "adaptivity: cycle " << cycle << ": " << target.label() << " = " << target.value(*sim)
            << ", estimated relative error " << relative << " (target " << tolerance << ", safety factor " << safety
            << ")\n";
      met = met && meets(relative);
    }
    entry["seconds"] = secondsSince(start);
    cycles.push_back(entry);
    const double resolution = sim->problem().parameters().sublist("Solver").get<double>("Absolute Residual Tolerance");
    for (const Target& target : targets) {
      if (!target.parameter.empty()) continue;  // a derivative may vanish (ν = 0 at a kink)
      const std::string& name = target.response;
      const double value = sim->functionals().at(name);
      const auto refined = estimate.refinedFunctionals.find(name);
      const double fine = refined == estimate.refinedFunctionals.end() ? value : refined->second;
      if (std::max(std::abs(value), std::abs(fine)) <= resolution && why.empty())
        why = "cycle " + std::to_string(cycle) + ": the target response " + name + " = " + number(value) +
              " (refined mesh: " + number(fine) + ") is zero to the solver's resolution (|value| <= " +
              "Solver/Absolute Residual Tolerance = " + number(resolution) +
              "): its relative error cannot be met by refining. The flow carries (almost) no load: are the loads "
              "and walls as meant (a tiny Normal Penalty Factor lets the material pass through a wall)? "
              "Adaptivity/Enabled=false solves the first mesh once";
    }
    if (!why.empty()) {
      met = false;
      break;
    }
    if (met) break;
    if (cycle + 1 == maxCycles) {
      why = "the target relative error " + std::to_string(tolerance) + " was not met in " +
            std::to_string(maxCycles) + " cycles (Adaptivity/Maximum Cycles)";
      break;
    }
    if (budgetSpent()) {  // the run's wall-clock budget (core/Budget.hpp): this cycle's results
      why = budgetMessage();
      break;
    }
    // On the mesh as made: a free-surface update moved boundary nodes off the .geo's curves.
    // The floor is gmsh's (the coarsest level's sizes): uniform refinement below it makes no sliver.
    Mesh on;
    double predictedDofs = 0.0;
    // At most kMaxGrowth times this cycle's dofs: an estimate far off (a contact zone that jumped
    // between the levels) would otherwise ask for a mesh the loop cannot afford.
    const double dofs = static_cast<double>(sim->problem().dofMap().numGlobalDofs());
    std::vector<double> sizes = nextSizes(*sim, targets, tolerance / safety, minSize / std::pow(2.0, levelsAllowed),
                                          maxSize, std::min(maxDofs, kMaxGrowth * dofs), on, predictedDofs);
    // Nested only when the coarsest level keeps a quarter of the first mesh's dofs at least:
    // coarser than that, the levels' fit sees no asymptotic error (ν = 1: 250 dofs gave η = 52 %
    // of F). With fewer levels than asked (one: the two error terms cancel in φ_2h − φ_h,
    // effectivity 0.2 at the 1 % target) the cycle is not nested and gets the Newton Step estimate.
    const int levels =
        levelsAllowed > 0 && predictedDofs / std::pow(4.0, levelsAllowed) >= 0.25 * firstDofs ? levelsAllowed : 0;
    remeshed.sublist("Mesh").set("Uniform Refinements", levels);
    for (double& v : sizes) v = std::max(v * std::pow(2.0, levels), minSize);  // the coarsest level's sizes
    field = sizeFieldOnMesh(on, sizes);
    previous = std::move(sim);
  }
  nlohmann::json block = {{"cycles", cycles},
                          {"target_met", met},
                          {"target_relative_error", tolerance},
                          {"safety_factor", safety},
                          {"seconds", secondsSince(loopStart)}};
  if (!met) {
    block["message"] = why;
    sim->setNotMet(why);
    log() << "adaptivity: " << why << "\n";
  }
  if (sim->problem().report().converged) sim->checkSensitivities();
  sim->addSummaryBlock("adaptivity", block);
  sim->writeOutput(outDir);
  if (message) *message = sim->statusMessage();
  return sim->exitStatus();
}

}  // namespace flowform
