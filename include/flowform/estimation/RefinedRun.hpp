// What the estimates on the uniformly refined mesh share (docs/theory.md §7): the refined run
// (the case on the mesh refined once more), the nodal indicators from the refined residual and
// adjoint at I u_h, and the extrapolation of refined values, η = (φ_f − φ_h) / (1 − 2^(−p)).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "flowform/estimation/CaseRun.hpp"
#include "flowform/estimation/ErrorEstimate.hpp"

namespace flowform {

/// The case of `run` on the mesh its size field makes, refined `refinements` times (Mesh/Uniform
/// Refinements), without estimate, adaptivity or finite-difference check, made by `makeRun`:
/// a level of the estimates.
std::unique_ptr<CaseRun> makeLevelRun(const Problem& run, int refinements, const CaseRunFactory& makeRun);

/// The case of `coarse` on its mesh refined once more (Mesh/Uniform Refinements + 1, the coarse
/// size field), without estimate, adaptivity or finite-difference check, made by `makeRun`.
std::unique_ptr<CaseRun> makeRefinedRun(const Problem& coarse, const CaseRunFactory& makeRun);

/// Nodal shares of the localized estimate on the coarse mesh (TwoLevelEstimate.hpp):
/// e_i = |Σ_fields R_f,i (ζ_f − I_h ζ_f)_i| at each refined node i, spread over the coarse
/// cell that holds node i by its shape functions there. Replicated on every rank.
std::vector<double> coarseIndicator(const Problem& coarse, const Problem& fine, const Vector& residual,
                                    const Vector& zeta);

/// The indicators of `indicatorResponses` into `estimate`: the refined residual at the refined
/// problem's current state (I u_h) weighted by ζ_f = c − z_f (ResponseAdjoint). `factored`: the
/// model's factors are already those of the exact K_f at that state (no factorization here).
void addIndicators(const Problem& coarse, Problem& fine, const std::vector<std::string>& indicatorResponses,
                   bool factored, ErrorEstimate& estimate);

/// Response → parameter → value.
using ResponseDerivatives = std::map<std::string, std::map<std::string, double>>;

/// η of every response of `run` (and of its sensitivities and total shape derivatives, when
/// both levels have them) from another level's values: η = factor (φ_other − φ_run). The other
/// level's values are kept in the estimate. A null derivative map: none on the other level.
void estimateFromOtherLevel(const CaseRun& run, const std::map<std::string, double>& other,
                            const ResponseDerivatives* otherSensitivities, const ResponseDerivatives* otherTotalShape,
                            double factor, ErrorEstimate& estimate);

/// From the refined level: η = (φ_f − φ_h) / (1 − 2^(−estimate.order)).
void extrapolate(const CaseRun& coarseRun, const std::map<std::string, double>& refined,
                 const ResponseDerivatives* refinedSensitivities, const ResponseDerivatives* refinedTotalShape,
                 ErrorEstimate& estimate);

}  // namespace flowform
