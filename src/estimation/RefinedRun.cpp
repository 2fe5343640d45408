#include "flowform/estimation/RefinedRun.hpp"

#include <cmath>

#include <Teuchos_CommHelpers.hpp>

#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/estimation/ResponseAdjoint.hpp"
#include "flowform/mesh/PointLocator.hpp"

namespace flowform {

std::unique_ptr<CaseRun> makeLevelRun(const Problem& run, int refinements, const CaseRunFactory& makeRun) {
  Teuchos::ParameterList params = run.parameters();
  params.sublist("Mesh").set("Uniform Refinements", refinements);
  params.sublist("Error Estimation").set("Method", "None");
  if (params.isSublist("Adaptivity")) params.remove("Adaptivity");
  if (params.isSublist("Sensitivity")) params.sublist("Sensitivity").set("Finite Difference Check", false);
  return makeRun(params, &run.sizeField());
}

std::unique_ptr<CaseRun> makeRefinedRun(const Problem& coarse, const CaseRunFactory& makeRun) {
  return makeLevelRun(coarse, coarse.parameters().sublist("Mesh").get<int>("Uniform Refinements") + 1, makeRun);
}

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

void addIndicators(const Problem& coarse, Problem& fine, const std::vector<std::string>& indicatorResponses,
                   bool factored, ErrorEstimate& estimate) {
  if (indicatorResponses.empty()) return;
  Vector residual(fine.dofMap().ownedMap()), zeta(fine.dofMap().ownedMap());
  fine.model().residual(fine.solution(), residual);
  for (const std::string& name : indicatorResponses) {
    if (responseAdjoint(fine.model(), fine.solution(), fine.responses(), name, fine.mesh(), zeta, !factored))
      estimate.indicators[name] = coarseIndicator(coarse, fine, residual, zeta);
    factored = true;  // the first adjoint factored K_f at I u_h
  }
}

void estimateFromOtherLevel(const CaseRun& run, const std::map<std::string, double>& other,
                            const ResponseDerivatives* otherSensitivities, const ResponseDerivatives* otherTotalShape,
                            double factor, ErrorEstimate& estimate) {
  estimate.refinedFunctionals = other;
  for (const auto& [name, value] : run.functionals()) {
    auto it = other.find(name);
    if (it != other.end()) estimate.functionals[name] = factor * (it->second - value);
  }
  // η of each derivative (response → parameter), from this level's and the other's values.
  auto estimateDerivatives = [&](const ResponseDerivatives& values, ResponseDerivatives& kept, ResponseDerivatives& eta) {
    for (const auto& [name, byParameter] : values)
      for (const auto& [parameter, value] : byParameter) eta[name][parameter] = factor * (kept[name][parameter] - value);
  };
  if (otherTotalShape && run.shapeDerivative().computed) {
    estimate.refinedSensitivitiesTotalShape = *otherTotalShape;
    estimateDerivatives(run.shapeDerivative().responses, estimate.refinedSensitivitiesTotalShape,
                        estimate.sensitivitiesTotalShape);
  }
  if (otherSensitivities && run.sensitivity().computed()) {
    estimate.refinedSensitivities = *otherSensitivities;
    estimateDerivatives(run.sensitivity().responseDerivatives(), estimate.refinedSensitivities, estimate.sensitivities);
  }
}

void extrapolate(const CaseRun& coarseRun, const std::map<std::string, double>& refined,
                 const ResponseDerivatives* refinedSensitivities, const ResponseDerivatives* refinedTotalShape,
                 ErrorEstimate& estimate) {
  estimateFromOtherLevel(coarseRun, refined, refinedSensitivities, refinedTotalShape,
                         1.0 / (1.0 - std::pow(2.0, -estimate.order)), estimate);
}

}  // namespace flowform
