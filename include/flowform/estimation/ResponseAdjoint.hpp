// The adjoint of a response: K_tᵀ z = ∂φ/∂q, one transposed solve with the factors of the
// exact Jacobian at x. For the responses linear in the reactions (Boundary Force, Mean
// Pressure: φ = c·R_unc(q), so ∂φ/∂q = J_uncᵀ c); z is then the sensitivity of φ to a
// residual: φ(q + δq) − φ(q) ≈ −zᵀ R(q + δq) when K_t δq = −R. The two-level error estimate
// weights the refined mesh's residual with it to localize the estimate (docs/theory.md §7).
#pragma once

#include <string>

#include "flowform/assembly/Responses.hpp"
#include "flowform/solvers/FlowModel.hpp"

namespace flowform {

/// z for the response `name` at x (owned map), with the Jacobian at x factored exactly (the
/// model's factors are then K_t(x)); z is zero on the held velocity components (the test
/// space). False, z untouched and nothing factored, for a response not linear in the reactions.
bool responseAdjoint(FlowModel& model, const Vector& x, const Responses& responses, const std::string& name,
                     const Mesh& mesh, Vector& z);

}  // namespace flowform
