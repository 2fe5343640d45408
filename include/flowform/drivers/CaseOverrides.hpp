// Command-line overrides of case parameters: --set "Path/To/Param=value".
#pragma once

#include <string>

#include <Teuchos_ParameterList.hpp>

namespace flowform {

/// Sets the parameter that `assignment` ("Sub/List/Name=value") names in `params`. The
/// value takes the type the entry already has in the case, else the type it has in
/// `valid`, else the narrowest of int, double, bool, string that parses. InputError for a
/// malformed assignment or a value that does not parse as the required type.
void applyOverride(Teuchos::ParameterList& params, const std::string& assignment,
                   const Teuchos::ParameterList& valid);

}  // namespace flowform
