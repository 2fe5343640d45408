// Optimization and inverse problems on Trilinos ROL (docs/optimization.md): the case's
// Optimization sublist names the design parameters with their bounds and the objective (a
// response, or a least-squares misfit to measured values); ROL's bound-constrained trust region
// or line search moves the design, each of its evaluations one solve of the case with the DDM
// derivatives by the design (DesignRuns, warm-started); the final design is re-solved as the case
// asks (its sensitivities, check, estimate) and written as an ordinary run, with the
// optimization's record in summary.json under "optimization".
#pragma once

#include <string>

#include <Teuchos_ParameterList.hpp>

#include "flowform/estimation/CaseRun.hpp"

namespace flowform {

/// Runs the optimization of the validated case `caseParams`, writes the final design's results to
/// `outDir`; the exit status (0, or 3 with `message` when the optimizer or a solve did not
/// converge). InputError for a bad Optimization sublist (before any solve).
int runOptimization(const Teuchos::ParameterList& caseParams, const CaseRunFactory& factory,
                    const std::string& outDir, std::string* message);

}  // namespace flowform
