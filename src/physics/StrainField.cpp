#include "flowform/physics/StrainField.hpp"

#include <string>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

static void buildValidParameters(const ValidList& valid) {
  valid->set("Minimum Strain", 0.05,
             "eps_min > 0: a law with a Strain parameter reads sqrt(eps^2 + eps_min^2) (the smallest strain its "
             "constants were fitted at; docs/theory.md §1.1)",
             positive());
  valid->set("Maximum Strain", 5.0,
             "eps_max > eps_min: the law reads the strain held smoothly below eps_max (the largest strain its "
             "constants were fitted at; beyond it the law is held constant; docs/theory.md §1.1)",
             positive());
}

Teuchos::RCP<const Teuchos::ParameterList> StrainFieldSettings::validParameters() {
  return validListOnce<buildValidParameters>("Strain Field");
}

StrainFieldSettings StrainFieldSettings::fromParameters(const Teuchos::ParameterList& list) {
  StrainFieldSettings s;
  s.minimumStrain = list.get<double>("Minimum Strain");
  s.maximumStrain = list.get<double>("Maximum Strain");
  if (s.maximumStrain <= s.minimumStrain)
    throw InputError("Material/Strain Field/Maximum Strain = " + std::to_string(s.maximumStrain) +
                     " must be larger than Minimum Strain = " + std::to_string(s.minimumStrain));
  return s;
}

}  // namespace flowform
