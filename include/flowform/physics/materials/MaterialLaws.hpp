// The registry of material laws: the one list a new law is added to. Adding a law is one file
// beside this one (a struct like PowerLaw: name, description, its parameters with their
// ranges, defaults and whether they are sensitivity parameters, its templated flow stress,
// whether it is linear and the γ of its Newtonian predictor; optionally a static
// std::string inputError(const double* values) that checks its constants together, "" when
// they are fine) and one entry in
// RegisteredMaterialLaws below. The Material sublist's "Law" choices and parameters, the
// sensitivity parameters of the material and the dispatch all follow from the list.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/core/TypeList.hpp"
#include "flowform/physics/materials/HenselSpittel.hpp"
#include "flowform/physics/materials/PowerLaw.hpp"
#include "flowform/physics/materials/SellarsTegart.hpp"

namespace flowform {

template <typename... Laws>
using MaterialLawList = TypeList<Laws...>;

/// The first is the default of Material/Law.
using RegisteredMaterialLaws = MaterialLawList<PowerLaw, SellarsTegart, HenselSpittel>;

/// A law's static facts, by its index in RegisteredMaterialLaws.
struct MaterialLawInfo {
  std::string name, description;
  std::vector<MaterialParameterInfo> parameters;
  int exponent;  ///< the parameter the continuation in n moves
};
const std::vector<MaterialLawInfo>& materialLaws();
/// Index of the law called `name`, −1 when there is none.
int materialLawIndex(const std::string& name);
/// "'Power Law', 'Sellars-Tegart'"
std::string materialLawNames();

/// The Material sublist's valid parameters for law `law`: Law, the law's parameters,
/// Strain Rate Cutoff.
Teuchos::RCP<const Teuchos::ParameterList> validMaterialParameters(int law);
/// The law a Material sublist names (the default when it names none); InputError naming the
/// registered laws for an unknown name or a Law that is not a string, and naming the law's
/// parameters for an entry that is another law's parameter.
int materialLawOf(const Teuchos::ParameterList& material);
/// The parameters of a validated Material sublist.
MaterialParameters<double> materialFromParameters(const Teuchos::ParameterList& material);

/// True when the law is linear (μ independent of the strain rate).
bool isNewtonian(const MaterialParameters<double>& m);
/// The Newtonian predictor of any law: the power law with σ0 = 0, n = 1 and the law's γ.
MaterialParameters<double> newtonianPredictor(const MaterialParameters<double>& m);
/// The index of law `law`'s parameter called "Temperature" (Sellars-Tegart's T), −1 when the law
/// does not depend on the temperature. With a Temperature field that parameter is the field's
/// value in each cell (physics/Material.hpp atTemperature), and its own value the start of the
/// field's Newton iteration.
int temperatureParameter(int law);
/// The index of law `law`'s parameter called "Strain" (Hensel–Spittel's ε), −1 when the law does not
/// depend on the strain. With a Strain field (Material/Strain Field) that parameter is the field's
/// regularized value in each cell (physics/StrainField.hpp), and its own value the field's start.
int strainParameter(int law);
/// n, the parameter the continuation moves (NonlinearSolver).
double& rateExponent(MaterialParameters<double>& m);
double rateExponent(const MaterialParameters<double>& m);

namespace detail {
template <typename Law, typename... Laws>
constexpr int lawIndex(MaterialLawList<Laws...>) {
  int i = 0, found = -1;
  ((std::is_same_v<Law, Laws> ? found = i++ : i++), ...);
  return found;
}
}  // namespace detail

/// The index of law `Law` in RegisteredMaterialLaws.
template <typename Law>
inline constexpr int kMaterialLawIndex = detail::lawIndex<Law>(RegisteredMaterialLaws{});

/// σ̄(e_r) by the law of `m`.
template <typename Scalar, typename PScalar>
Scalar lawFlowStress(const Scalar& eReg, const MaterialParameters<PScalar>& m) {
  Scalar out(0.0);
  visitByIndex(RegisteredMaterialLaws{}, m.law, [&](auto tag) {
    using Law = typename decltype(tag)::type;
    out = Law::template flowStress<Scalar, PScalar>(eReg, m.values.data());
  });
  return out;
}

}  // namespace flowform
