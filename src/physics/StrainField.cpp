#include "flowform/physics/StrainField.hpp"

#include "flowform/core/NumberRange.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

static void buildValidParameters(const ValidList& valid) {
  valid->set("Minimum Strain", 0.05,
             "eps_min > 0: a law with a Strain parameter reads sqrt(eps^2 + eps_min^2) (the smallest strain its "
             "constants were fitted at; docs/theory.md §1.1)",
             positive());
}

Teuchos::RCP<const Teuchos::ParameterList> StrainFieldSettings::validParameters() {
  return validListOnce<buildValidParameters>("Strain Field");
}

StrainFieldSettings StrainFieldSettings::fromParameters(const Teuchos::ParameterList& list) {
  StrainFieldSettings s;
  s.minimumStrain = list.get<double>("Minimum Strain");
  return s;
}

}  // namespace flowform
