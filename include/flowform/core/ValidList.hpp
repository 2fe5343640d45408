// The valid-parameter list of a class (its validParameters()), built once on first use and
// shared: the validators in it are shared by every list validated against it.
//   void buildFooParameters(const ValidList& valid) { valid->set(...); }
//   Teuchos::RCP<const Teuchos::ParameterList> Foo::validParameters() {
//     return validListOnce<buildFooParameters>("Foo");
//   }
#pragma once

#include <Teuchos_ParameterList.hpp>

namespace flowform {

using ValidList = Teuchos::RCP<Teuchos::ParameterList>;

/// The list `Build` fills, made the first time it is asked for (one per Build function).
template <void (*Build)(const ValidList&)>
ValidList validListOnce(const char* name) {
  static const ValidList valid = [name] {
    ValidList list = Teuchos::rcp(new Teuchos::ParameterList(name));
    Build(list);
    return list;
  }();
  return valid;
}

}  // namespace flowform
