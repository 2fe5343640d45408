#include "flowform/estimation/TwoLevelEstimate.hpp"

#include <chrono>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Clock.hpp"
#include "flowform/estimation/RefinedRun.hpp"

namespace flowform {

ErrorEstimate TwoLevelEstimate::estimate(const CaseRun& coarseRun, const CaseRunFactory& makeRun,
                                         const std::vector<std::string>& indicatorResponses,
                                         const IndicatorsWanted& /*wanted: made before the estimate, always*/) {
  const auto start = std::chrono::steady_clock::now();
  ErrorEstimate estimate;
  estimate.method = kName;
  const Problem& coarse = coarseRun.problem();
  estimate.order = coarse.parameters().sublist("Error Estimation").get<double>("Order");

  // The same case on the mesh refined once more; no estimate, adaptivity or FD check there.
  const BudgetScope scope("the two-level error estimate (the case on the mesh refined once more)", nullptr);
  const std::unique_ptr<CaseRun> fineRun = makeRefinedRun(coarse, makeRun);
  Problem& fine = fineRun->problem();
  estimate.refinedDofs = static_cast<GO>(fine.dofMap().numGlobalDofs());
  estimate.timings["refined_setup"] = secondsSince(start);

  // Indicators: the refined residual at I u_h weighted by the refined adjoint there (ζ = c − z),
  // with the statuses carried over as they were (a node inside an old zone limit free). Measured
  // alternatives (docs/theory.md §7): z itself (its layer at the response's group refines there
  // for nothing); the zone limits decided first, as for the solve below, or the statuses the
  // refined solve converges to (the die lip's penalty residual then takes everything, the bulk
  // stays coarse and the force overshoots).
  if (!indicatorResponses.empty()) {
    const auto at = std::chrono::steady_clock::now();
    fine.startFrom(coarse, false);
    addIndicators(coarse, fine, indicatorResponses, false, estimate);
    estimate.timings["indicators"] = secondsSince(at);
  }
  const auto at = std::chrono::steady_clock::now();
  fine.startFrom(coarse);
  fineRun->run();
  estimate.timings["refined_run"] = secondsSince(at);
  estimate.seconds = secondsSince(start);
  if (fineRun->exitStatus() != 0) {
    estimate.failure = "the solve on the refined mesh (" + std::to_string(estimate.refinedDofs) +
                       " dofs) did not converge: " + fine.report().message;
    return estimate;
  }
  if (!fine.freeSurfaces().empty()) estimate.refinedSurfaceUpdates = fine.freeSurfaceReport().iterations;
  const ResponseDerivatives* sensitivities =
      fineRun->sensitivity().computed() ? &fineRun->sensitivity().responseDerivatives() : nullptr;
  const ResponseDerivatives* totalShape =
      fineRun->shapeDerivative().computed ? &fineRun->shapeDerivative().responses : nullptr;
  extrapolate(coarseRun, fineRun->functionals(), sensitivities, totalShape, estimate);
  estimate.estimated = true;
  estimate.seconds = secondsSince(start);
  return estimate;
}

}  // namespace flowform
