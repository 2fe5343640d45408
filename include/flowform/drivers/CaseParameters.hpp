// The case parameter list: its valid form (names, types, defaults, allowed values, the
// help text of --help) and the validation that turns a bad case into an InputError naming
// the parameter and what is allowed (exit status 2, nothing written).
#pragma once

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include "flowform/physics/FlowPhysics.hpp"

namespace flowform {

/// Every parameter a case may set, with its default and documentation.
Teuchos::RCP<const Teuchos::ParameterList> validCaseParameters();

/// Checks `params` against validCaseParameters() and sets the defaults of its fixed
/// sublists: entry types first (Teuchos' own messages would not name the parameter), then
/// names, Mesh/File present, γ, n and e0 > 0, the output cell fields, and the Sensitivity
/// sublist when there is one. The free-form sublists (Boundary Conditions, Responses) are
/// checked by their owners. Throws InputError.
void validateCase(Teuchos::ParameterList& params);

/// The bulk physics (geometry, body force, β, the material law) of a validated case.
FlowPhysics physicsFromCase(const Teuchos::ParameterList& params);

/// Whether the case asks for the adaptive loop: an Adaptivity sublist whose Enabled is not false.
bool adaptivityRequested(const Teuchos::ParameterList& params);

}  // namespace flowform
