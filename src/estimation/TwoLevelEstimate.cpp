#include "flowform/estimation/TwoLevelEstimate.hpp"

#include <chrono>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <nlohmann/json.hpp>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/estimation/ResponseAdjoint.hpp"
#include "flowform/mesh/PointLocator.hpp"

namespace flowform {

namespace {

/// Nodal shares of the localized estimate on the coarse mesh (TwoLevelEstimate.hpp):
/// e_i = |Σ_fields R_f,i (ζ_f − I_h ζ_f)_i| at each refined node i, spread over the coarse
/// cell that holds node i by its shape functions there. Replicated on every rank.
std::vector<double> coarseIndicator(const Problem& coarse, const Problem& fine, const Vector& residual,
                                    const Vector& zeta) {
  const DofMap& fineDofs = fine.dofMap();
  const DofMap& coarseDofs = coarse.dofMap();
  // I_h ζ_f: the adjoint at the coarse nodes (which are refined nodes), interpolated back.
  Vector zCoarse(coarseDofs.ownedMap()), zInterpolant(fineDofs.ownedMap());
  interpolate(fine.mesh(), fineDofs, replicate(zeta, fineDofs), coarse.mesh(), coarseDofs, zCoarse);
  interpolate(coarse.mesh(), coarseDofs, replicate(zCoarse, coarseDofs), fine.mesh(), fineDofs, zInterpolant);
  const auto r = residual.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto zf = zeta.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto zi = zInterpolant.getLocalViewHost(Tpetra::Access::ReadOnly);
  const PointLocator locator(coarse.mesh());
  const int npc = nodesPerCell(coarse.mesh().cellType);
  std::vector<double> local(coarse.mesh().numNodes(), 0.0), global(local.size(), 0.0);
  for (LO n = 0; n < fineDofs.numOwnedNodes(); ++n) {
    const GO node = fineDofs.overlapNodes()[n];
    double e = 0.0;
    for (int f = 0; f < fineDofs.numFields(node); ++f) {
      const LO d = fineDofs.dof(n, f);
      e += r(d, 0) * (zf(d, 0) - zi(d, 0));
    }
    const CellPoint at = locator.locate(fine.mesh().coords[node]);
    for (int a = 0; a < npc; ++a) local[coarse.mesh().cell(at.cell)[a]] += at.weights[a] * std::abs(e);
  }
  Teuchos::reduceAll(*coarseDofs.comm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                     global.data());
  return global;
}

}  // namespace

ErrorEstimate twoLevelEstimate(const CaseRun& coarseRun, const CaseRunFactory& makeRun,
                               const std::vector<std::string>& indicatorResponses) {
  const auto start = std::chrono::steady_clock::now();
  ErrorEstimate estimate;
  const Problem& coarse = coarseRun.problem();
  const Teuchos::ParameterList& caseParams = coarse.parameters();
  estimate.order = caseParams.sublist("Error Estimation").get<double>("Order");

  // The same case on the mesh refined once more; no estimate, adaptivity or FD check there.
  Teuchos::ParameterList params = caseParams;
  Teuchos::ParameterList& mesh = params.sublist("Mesh");
  mesh.set("Uniform Refinements", mesh.get<int>("Uniform Refinements") + 1);
  params.sublist("Error Estimation").set("Method", "None");
  if (params.isSublist("Adaptivity")) params.remove("Adaptivity");
  if (params.isSublist("Sensitivity")) params.sublist("Sensitivity").set("Finite Difference Check", false);
  const BudgetScope scope("the two-level error estimate (the case on the mesh refined once more)", nullptr);
  const std::unique_ptr<CaseRun> fineRun = makeRun(params, &coarse.sizeField());
  Problem& fine = fineRun->problem();
  estimate.refinedDofs = static_cast<GO>(fine.dofMap().numGlobalDofs());

  // Indicators: the refined residual at I u_h weighted by the refined adjoint there (ζ = c − z),
  // with the statuses carried over as they were (a node inside an old zone limit free). Measured
  // alternatives (docs/theory.md §7): z itself (its layer at the response's group refines there
  // for nothing); the zone limits decided first, as for the solve below, or the statuses the
  // refined solve converges to (the die lip's penalty residual then takes everything, the bulk
  // stays coarse and the force overshoots).
  if (!indicatorResponses.empty()) {
    fine.startFrom(coarse, false);
    Vector residual(fine.dofMap().ownedMap()), zeta(fine.dofMap().ownedMap());
    fine.model().residual(fine.solution(), residual);
    for (const std::string& name : indicatorResponses)
      if (responseAdjoint(fine.model(), fine.solution(), fine.responses(), name, fine.mesh(), zeta))
        estimate.indicators[name] = coarseIndicator(coarse, fine, residual, zeta);
  }
  fine.startFrom(coarse);
  fineRun->run();
  estimate.seconds = secondsSince(start);
  if (fineRun->exitStatus() != 0) {
    estimate.failure = "the solve on the refined mesh (" + std::to_string(estimate.refinedDofs) +
                       " dofs) did not converge: " + fine.report().message;
    return estimate;
  }
  const double factor = 1.0 / (1.0 - std::pow(2.0, -estimate.order));
  estimate.refinedFunctionals = fineRun->functionals();
  for (const auto& [name, value] : coarseRun.functionals()) {
    auto it = estimate.refinedFunctionals.find(name);
    if (it != estimate.refinedFunctionals.end()) estimate.functionals[name] = factor * (it->second - value);
  }
  if (!fine.freeSurfaces().empty()) estimate.refinedSurfaceUpdates = fine.freeSurfaceReport().iterations;
  // η of each derivative (response → parameter), from the coarse and the refined values.
  using Derivatives = std::map<std::string, std::map<std::string, double>>;
  auto estimateDerivatives = [&](const Derivatives& coarseValues, Derivatives& refined, Derivatives& eta) {
    for (const auto& [name, byParameter] : coarseValues)
      for (const auto& [parameter, value] : byParameter) eta[name][parameter] = factor * (refined[name][parameter] - value);
  };
  if (coarseRun.shapeDerivative().computed && fineRun->shapeDerivative().computed) {
    estimate.refinedSensitivitiesTotalShape = fineRun->shapeDerivative().responses;
    estimateDerivatives(coarseRun.shapeDerivative().responses, estimate.refinedSensitivitiesTotalShape,
                        estimate.sensitivitiesTotalShape);
  }
  if (coarseRun.sensitivity().computed() && fineRun->sensitivity().computed()) {
    estimate.refinedSensitivities = fineRun->sensitivity().responseDerivatives();
    estimateDerivatives(coarseRun.sensitivity().responseDerivatives(), estimate.refinedSensitivities,
                        estimate.sensitivities);
  }
  estimate.estimated = true;
  estimate.seconds = secondsSince(start);
  return estimate;
}

}  // namespace flowform
