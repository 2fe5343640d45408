// Adaptive meshing to a requested accuracy (the case's Adaptivity sublist; docs/theory.md §7).
//
// Cycle k: solve on mesh k (cycle 0: the case's own mesh; later ones start from the previous
// cycle's solution and contact statuses, interpolated: no continuation), estimate every response's
// error (Error Estimation/Method, Coarser Mesh when None: EstimationMethods.hpp) with nodal
// indicators for the target responses, stop when every target has |η|/|φ| ≤ Target Relative Error,
// else size mesh k+1 from the indicators and let gmsh mesh the .geo anew with that size field
// (curves and physical groups exact). The case's Mesh/Uniform Refinements and Size Factor shape the
// first mesh only: later meshes take the field's sizes as they are (the summary's parameters, those
// of the last cycle, say so).
//
// Sizing (error equidistribution at the least node count). With e_a = Σ_targets (nodal share
// of |η_φ|)/(tol |φ|) at node a of mesh k (so Σ_a e_a ≈ Σ_targets |η_φ|/(tol |φ|)), h_a the mean
// length of the edges at a, and a node's share modelled as e_a' = e_a (h_a'/h_a)^s, the sizes
// that reach Σ_a e_a' = 1/2 (half the tolerance: the estimate's own uncertainty) with the fewest
// nodes N' = Σ_a (h_a/h_a')² are
//     h_a'/h_a = (λ/e_a)^(1/(s+2)),   λ^(s/(s+2)) = ½ / Σ_a e_a^(2/(s+2)),
// with s = 2 (a share falls like its area where the solution is smooth, more slowly at a
// singular corner, which the next cycles then refine further), clamped to [1/32, 3/2] per
// cycle. h_a' is capped by the largest size of the first mesh, the sizes gmsh meshes with are
// floored at 1/128 of its smallest (finer sizes made gmsh leave a zero-area cell at the die
// lip; the uniform refinements of the Coarser Mesh estimate's levels go below), and all are
// scaled up uniformly when the predicted dof count Σ_a 3 (h_a/h_a')² exceeds Maximum Dofs or
// 16 times the cycle's dofs. With the Coarser Mesh estimate the next mesh is the field's at
// 2^L times the sizes refined L = Coarser Levels times when the coarsest level keeps a quarter
// of the first mesh's dofs, else it is not nested (L = 0: the Newton Step estimate).
#pragma once

#include <string>

#include <Teuchos_ParameterList.hpp>

#include "flowform/estimation/CaseRun.hpp"

namespace flowform {

/// Runs the adaptive loop of the validated case (each cycle's run made by `makeRun`) and writes
/// the last cycle's results, with the list of cycles, into `outDir`. Returns the exit status: 0, or 3 when a solve did not
/// converge or the target was not met within Maximum Cycles / Maximum Dofs (or a target response is
/// zero to round-off, or the Solver/Time Limit budget is spent); `message` (optional) returns
/// summary.json's "message".
int runAdaptive(const Teuchos::ParameterList& caseParams, const CaseRunFactory& makeRun, const std::string& outDir,
                std::string* message = nullptr);

}  // namespace flowform
