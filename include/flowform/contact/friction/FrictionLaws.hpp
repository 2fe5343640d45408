// The registry of friction laws: the one list a new law is added to. Adding a law is one
// file beside this one (a struct like CoulombFriction: name, description, which of ν and m
// it uses, and its templated force) and one entry in RegisteredFrictionLaws below. The
// "Friction Law" choices of a Contact Wall, the dispatch and which sensitivity parameters
// enter a wall all follow from the list.
#pragma once

#include <string>
#include <vector>

#include "flowform/contact/friction/Coulomb.hpp"
#include "flowform/contact/friction/NoFriction.hpp"
#include "flowform/contact/friction/Norton.hpp"
#include "flowform/contact/friction/Orowan.hpp"
#include "flowform/contact/friction/Tresca.hpp"
#include "flowform/core/TypeList.hpp"

namespace flowform {

template <typename... Laws>
using FrictionLawList = TypeList<Laws...>;

/// The first is the default of "Friction Law".
using RegisteredFrictionLaws = FrictionLawList<CoulombFriction, TrescaFriction, OrowanFriction, NortonFriction, NoFriction>;

/// A law's static facts, by its index in RegisteredFrictionLaws.
struct FrictionLawInfo {
  std::string name, description;
  bool usesFrictionCoefficient, usesShearFactor, needsTributary;
};
const std::vector<FrictionLawInfo>& frictionLaws();
/// Index of the law called `name`, −1 when there is none.
int frictionLawIndex(const std::string& name);

/// g_k and its branch by law `law` (an index of frictionLaws()).
template <typename Scalar, typename PScalar>
FrictionForce<Scalar> frictionForce(int law, const FrictionNodeData<Scalar>& d, const FrictionParameters<PScalar>& fp,
                                    const FrictionSettings& s) {
  FrictionForce<Scalar> out{Scalar(0.0), FrictionBranch::NoFriction};
  visitByIndex(RegisteredFrictionLaws{}, law, [&](auto tag) {
    using Law = typename decltype(tag)::type;
    out = Law::template force<Scalar, PScalar>(d, fp, s);
  });
  return out;
}

}  // namespace flowform
