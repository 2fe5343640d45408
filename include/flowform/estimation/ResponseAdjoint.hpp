// The adjoint of a response: K_tᵀ z = ∂φ/∂q, one transposed solve with the factors of the
// exact Jacobian at x. For the responses linear in the reactions (Boundary Force, Mean
// Pressure: φ = c·R_unc(q), so ∂φ/∂q = J_uncᵀ c); z is then the sensitivity of φ to a
// residual: φ(q + δq) − φ(q) ≈ −zᵀ R(q + δq) when K_t δq = −R. The two-level error estimate
// weights the refined mesh's residual with ζ = c − z to localize the estimate (docs/theory.md §7).
#pragma once

#include <string>

#include "flowform/responses/Responses.hpp"
#include "flowform/solvers/FlowModel.hpp"

namespace flowform {

/// ζ = c − z for the response `name` at x (owned map): z the adjoint, zero on the held velocity
/// components (the test space), and c the response's weights on its group's held components,
/// so ζ is the adjoint that carries the response's Dirichlet data and has no layer at the group.
/// With `factor` the Jacobian at x is factored exactly (the model's factors are then K_t(x));
/// without, the model's factors must already be those of the exact K_t(x). False, ζ untouched
/// and nothing factored, for a response not linear in the reactions.
bool responseAdjoint(FlowModel& model, const Vector& x, const Responses& responses, const std::string& name,
                     const Mesh& mesh, Vector& z, bool factor = true);

}  // namespace flowform
