// A boundary value as a sensitivity parameter ("Boundary Value:<group>/<entry>",
// assembly/SensitivityParameter.hpp): a ram speed, a billet's or a tool's temperature, a heat
// transfer coefficient. The constrained residual is affine in each — a prescribed velocity or
// temperature enters its constraint rows u − v, T − T_b (and the constraint of a node two groups
// share is solved linearly from theirs), a heat transfer term ∫ N_a h (T − T_a) is linear in h and
// in T_a — so
//
//   ∂R/∂h = R(x; h + 1) − R(x; h)        exactly, at the converged x,
//
// two assemblies with the condition rebuilt in between. The responses read x (and the
// unconstrained residual, which has no constraint rows and no heat transfer): ∂φ/∂h = 0, and a
// Rigid Inflow's force (a reaction) has no partial either.
#pragma once

#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/sensitivity/GeoParameterMotion.hpp"

namespace flowform {

class Problem;

/// The entries of the case's Boundary Conditions that "Boundary Value:<group>/<entry>" may name:
/// Velocity X, Velocity Y (not of a Rigid Inflow group, whose speed is an unknown), Temperature,
/// Heat Transfer Coefficient, Ambient Temperature, Tool Temperature, Friction Heat Fraction, as numbers
/// the case gives (the residual is affine in each).
BoundaryValues givenBoundaryValues(const Teuchos::ParameterList& caseParams);

/// ∂R/∂h and ∂φ/∂h at x by two assemblies and response evaluations, at h and h + Δ (the condition
/// put back after): exact, the residual being affine in h.
MeshPartials boundaryValuePartials(Problem& problem, const SensitivityParameter& h, const Vector& x);

}  // namespace flowform
