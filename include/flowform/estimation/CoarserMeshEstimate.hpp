// The nested estimate of every response (Error Estimation/Method = Coarser Mesh; docs/theory.md
// §7): the run's mesh is a mesh refined once uniformly (Mesh/Uniform Refinements ≥ 1), and the
// same case is solved on the mesh one refinement coarser, started from the run's solution
// (injected: the coarser nodes are nodes of the run's mesh) and contact statuses. With an error
// that falls like h^p under uniform refinement, φ − φ_2h ≈ 2^p (φ − φ_h), so
//
//     φ(u) − φ(u_h) ≈ η_φ = (φ_h − φ_2h) / (2^p − 1),
//
// the same two levels as the two-level estimate, the answer taken on the finer one. What the
// estimate costs is a solve with a quarter of the run's dofs from a start next to its answer
// (a few Newton steps) instead of Newton steps on four times the dofs: the adaptive loop, which
// meshes its cycles this way with this method, gets the refined level's accuracy for the
// estimate's price. The sensitivities get η = (dφ_h/dh − dφ_2h/dh) / (2^p − 1) (DDM on both).
//
// The indicators are the two-level estimate's with the levels shifted by one: the run's
// residual at the interpolated coarser solution I u_2h, weighted by ζ_h = c − z_h, the adjoint
// of the exact K_h at I u_2h (one factorization at the run's level), localized as
// Σ_i R_h,i (ζ_h − I_2h ζ_h)_i over the run's nodes and spread to the coarser mesh's nodes
// (estimation/RefinedRun coarseIndicator); ErrorEstimate::indicatorMesh is that mesh. As in the
// two-level estimate, that linearization has the coarser level's statuses carried as they are
// (no zone limit decided, no complementarity: with the run's converged ones the die lip's
// penalty residual took the indicators and the loop coarsened the bulk cycle after cycle); the
// run's statuses are put back afterwards.
//
// Nested iteration (Error Estimation/Nested Start, the default): the levels are solved before
// the run, coarsest first, each from the one below (on nested meshes the coarser solution
// interpolates exactly), and the run starts from the finest of them: its Newton begins next to its
// answer instead of at the last adaptive cycle's state or from scratch. The levels then start
// further from theirs (7–10 Newton iterations instead of 5–8): on the extrusion the trade is about
// even (docs/BENCHMARKS.md §17); where a run from scratch is costly — free surfaces converged from
// the .geo's shape — the coarsest level does that work on a fraction of the dofs (the cutting
// scene: 28 updates there, 10 on the run's mesh instead of 29 to 41; 3.6× faster, §13).
//
// With free surfaces each level converges its own surfaces (nested: the coarsest from the mesh as
// made, each finer one from the shape below; after the run: each from the run's shape, a few
// updates; Problem::startFrom carries it) and the responses, frozen-shape and total
// derivatives compare level to level as on a fixed domain (the die swell: effectivity 0.90–1.05,
// docs/verification.md §11). Falls back to the Newton Step estimate on a mesh that is not refined
// (Uniform Refinements 0: the adaptive loop's first cycle), and to the two-level one where a case
// with free surfaces asks for indicators (the coarser level's surface is off the run's, where the
// indicators are interpolated); error_estimation.details.coarser_mesh_fallback = 1 says so.
#pragma once

#include <string>
#include <vector>

#include "flowform/estimation/CaseRun.hpp"
#include "flowform/estimation/ErrorEstimate.hpp"

namespace flowform {

struct CoarserMeshEstimate {
  static constexpr const char* kName = "Coarser Mesh";
  static constexpr const char* kDescription =
      "the case solved again on the mesh one uniform refinement coarser than the run's (Mesh/Uniform Refinements >= "
      "1), from the run's solution: eta = (phi - phi_coarser) / (2^Order - 1), a quarter of the dofs; the adaptive "
      "loop then meshes every cycle after the first refined once; on an unrefined mesh the Newton Step estimate, "
      "with free surfaces and adaptivity indicators the two-level one";
  /// The estimate of `run`'s converged responses (and sensitivities, when computed), with
  /// indicators for `indicatorResponses` on the coarser mesh. `run`'s model is refactored for
  /// the indicators (its solution and statuses are kept). When the coarser solve does not
  /// converge there is no estimate (`failure` says why). Collective.
  /// The indicators are made after the estimate, only when `wanted` (empty: always) says so.
  /// Levels the run solved before itself (CaseRun::coarserLevels) are taken as they are.
  static ErrorEstimate estimate(CaseRun& run, const CaseRunFactory& makeRun,
                                const std::vector<std::string>& indicatorResponses,
                                const IndicatorsWanted& wanted = {});

  /// How many coarser levels the estimate of `run` solves: Coarser Levels, at most its mesh's
  /// Uniform Refinements; 0 where the method falls back to another (an unrefined mesh, free
  /// surfaces with indicators wanted).
  static int levelsOf(const Problem& run, bool indicatorsWanted);

  /// Nested iteration: the case on the meshes `levels` … 1 refinements coarser than `run`'s,
  /// solved coarsest first, each from the one below (the coarsest from `run`'s carried start when
  /// it has one, Problem::startFrom, else from scratch); returned the finer first, with
  /// `seconds` their time. Empty, with `failure` saying why, when a level does not converge.
  /// Collective.
  static std::vector<std::unique_ptr<CaseRun>> solveLevels(const Problem& run, int levels,
                                                           const CaseRunFactory& makeRun, std::string& failure,
                                                           double& seconds);
};

}  // namespace flowform
