#include "flowform/physics/materials/MaterialLaws.hpp"

#include <type_traits>
#include <utility>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"

namespace flowform {

namespace {

template <typename Law>
MaterialLawInfo infoOf() {
  static_assert(Law::kNumParameters <= kMaxMaterialParameters, "raise kMaxMaterialParameters");
  return {Law::kName, Law::kDescription,
          std::vector<MaterialParameterInfo>(Law::kParameters, Law::kParameters + Law::kNumParameters),
          Law::kExponent};
}

template <typename... Laws>
std::vector<MaterialLawInfo> collect(MaterialLawList<Laws...>) {
  return {infoOf<Laws>()...};
}

Teuchos::RCP<const Teuchos::ParameterEntryValidator> validatorOf(MaterialParameterInfo::Range range) {
  switch (range) {
    case MaterialParameterInfo::Range::Positive: return positive();
    case MaterialParameterInfo::Range::NonNegative: return nonNegative();
    case MaterialParameterInfo::Range::Finite: return finiteNumber();
  }
  return finiteNumber();
}

/// InputError for an entry of `material` that is a parameter of another law than `law` (the
/// validation would call it unknown and list the valid names, without saying why).
void checkOwnParameters(const Teuchos::ParameterList& material, int law) {
  const auto& laws = materialLaws();
  auto declares = [&](int l, const std::string& name) {
    for (const MaterialParameterInfo& p : laws[l].parameters)
      if (name == p.name) return true;
    return false;
  };
  for (auto it = material.begin(); it != material.end(); ++it) {
    const std::string& name = material.name(it);
    if (declares(law, name)) continue;
    for (size_t other = 0; other < laws.size(); ++other)
      if (declares(static_cast<int>(other), name)) {
        throw InputError("Material/" + name + " is a parameter of material law '" + laws[other].name +
                         "', but the case's Material/Law is '" + laws[law].name + "'; its parameters: 'Law', " +
                         quotedNames(laws[law].parameters) + ", 'Strain Rate Cutoff'");
      }
  }
}

/// Whether a law has the optional static std::string inputError(const double* values).
template <typename Law, typename = void>
struct HasInputError : std::false_type {};
template <typename Law>
struct HasInputError<Law, std::void_t<decltype(Law::inputError(std::declval<const double*>()))>> : std::true_type {};

}  // namespace

const std::vector<MaterialLawInfo>& materialLaws() {
  static const std::vector<MaterialLawInfo> laws = collect(RegisteredMaterialLaws{});
  return laws;
}

int materialLawIndex(const std::string& name) { return indexByName(materialLaws(), name); }

std::string materialLawNames() { return quotedNames(materialLaws()); }

Teuchos::RCP<const Teuchos::ParameterList> validMaterialParameters(int law) {
  // One list per law, built once (as validListOnce does for a class's single list).
  static const std::vector<Teuchos::RCP<const Teuchos::ParameterList>> lists = [] {
    std::vector<Teuchos::RCP<const Teuchos::ParameterList>> made;
    std::string doc = "the material law:";
    Teuchos::Array<std::string> names;
    for (const MaterialLawInfo& info : materialLaws()) {
      doc += " " + info.name + " (" + info.description + ");";
      names.push_back(info.name);
    }
    doc.back() = '.';
    const auto lawValidator = Teuchos::rcp(new Teuchos::StringValidator(names));
    for (const MaterialLawInfo& info : materialLaws()) {
      auto valid = Teuchos::rcp(new Teuchos::ParameterList("Material"));
      valid->set("Law", materialLaws().front().name, doc, lawValidator);
      for (const MaterialParameterInfo& p : info.parameters)
        valid->set(p.name, p.defaultValue, p.doc, validatorOf(p.range));
      valid->set("Strain Rate Cutoff", 1e-3, "e0 > 0: e_r = sqrt(e² + e0²) [1/time]", positive());
      made.push_back(valid);
    }
    return made;
  }();
  return lists.at(law);
}

int materialLawOf(const Teuchos::ParameterList& material) {
  if (!material.isParameter("Law")) {
    checkOwnParameters(material, 0);
    return 0;
  }
  if (!material.isType<std::string>("Law"))
    throw InputError("Material/Law must be of type string, one of " + materialLawNames());
  const std::string name = material.get<std::string>("Law");
  const int law = materialLawIndex(name);
  if (law < 0) throw InputError("Material/Law: '" + name + "' is not a material law; allowed: " + materialLawNames());
  checkOwnParameters(material, law);
  return law;
}

MaterialParameters<double> materialFromParameters(const Teuchos::ParameterList& material) {
  MaterialParameters<double> m;
  m.law = materialLawOf(material);
  const MaterialLawInfo& info = materialLaws()[m.law];
  for (size_t i = 0; i < info.parameters.size(); ++i) m.values[i] = material.get<double>(info.parameters[i].name);
  m.cutoff = material.get<double>("Strain Rate Cutoff");
  // A law's own check of its constants together (a law's optional inputError(values)).
  visitByIndex(RegisteredMaterialLaws{}, m.law, [&](auto tag) {
    using Law = typename decltype(tag)::type;
    if constexpr (HasInputError<Law>::value) {
      const std::string error = Law::inputError(m.values.data());
      if (!error.empty()) throw InputError("Material (" + info.name + "): " + error);
    }
  });
  return m;
}

bool isNewtonian(const MaterialParameters<double>& m) {
  bool out = false;
  visitByIndex(RegisteredMaterialLaws{}, m.law,
               [&](auto tag) { out = decltype(tag)::type::isNewtonian(m.values.data()); });
  return out;
}

MaterialParameters<double> newtonianPredictor(const MaterialParameters<double>& m) {
  MaterialParameters<double> p;
  p.law = kMaterialLawIndex<PowerLaw>;
  p.values[PowerLaw::kYieldStress] = 0.0;
  double gamma = 1.0;
  visitByIndex(RegisteredMaterialLaws{}, m.law,
               [&](auto tag) { gamma = decltype(tag)::type::newtonianRateConstant(m.values.data()); });
  p.values[PowerLaw::kRateConstant] = gamma;
  p.values[PowerLaw::kRateExponent] = 1.0;
  p.cutoff = m.cutoff;
  return p;
}

namespace {
/// The index of each law's parameter called `name` (−1 where a law has none).
std::vector<int> parameterIndices(const char* name) {
  std::vector<int> made;
  for (const MaterialLawInfo& info : materialLaws()) {
    int found = -1;
    for (size_t i = 0; i < info.parameters.size(); ++i)
      if (std::string(info.parameters[i].name) == name) found = static_cast<int>(i);
    made.push_back(found);
  }
  return made;
}
}  // namespace

int temperatureParameter(int law) {
  static const std::vector<int> index = parameterIndices("Temperature");
  return index.at(law);
}

int strainParameter(int law) {
  static const std::vector<int> index = parameterIndices("Strain");
  return index.at(law);
}

double& rateExponent(MaterialParameters<double>& m) { return m.values[materialLaws()[m.law].exponent]; }
double rateExponent(const MaterialParameters<double>& m) { return m.values[materialLaws()[m.law].exponent]; }

}  // namespace flowform
