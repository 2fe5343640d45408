// One run of the finite-difference check (sensitivity/FiniteDifferenceCheck): the problem
// solved again at h + δ from its converged state, with its contact-status loop, and, with free
// surfaces, once more with the surfaces re-converged (the total derivative's difference).
#pragma once

#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/sensitivity/FiniteDifferenceCheck.hpp"

namespace flowform {

class Problem;

/// The free-surface tolerances of a finite-difference run relative to the case's.
constexpr double kFiniteDifferenceSurfaceTolerance = 1e-4;

/// The solve at h + delta from `problem`'s converged state, with its contact loop; the
/// problem's physics, its walls' state, its mesh and the model are restored afterwards.
/// `holdScales` (Sensitivity::holdScalesInCheck): the walls keep the base run's penalty scales
/// (the problem the DDM differentiates), else they take them from the start state at h + δ.
PerturbedRun solvePerturbed(Problem& problem, const SensitivityParameter& h, double delta, bool holdScales);

}  // namespace flowform
