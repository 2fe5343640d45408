#include "flowform/responses/ResponseRegistry.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/core/ValidList.hpp"

namespace flowform {

namespace {

/// T::kField where a type declares it (the field besides the flow's that it reads), else "".
template <typename T, typename = void>
struct FieldOf {
  static constexpr const char* value = "";
};
template <typename T>
struct FieldOf<T, std::void_t<decltype(T::kField)>> {
  static constexpr const char* value = T::kField;
};

/// Whether T has the optional instance members fieldRead() and checkMesh(mesh).
template <typename T, typename = void>
struct HasFieldRead : std::false_type {};
template <typename T>
struct HasFieldRead<T, std::void_t<decltype(std::declval<const T&>().fieldRead())>> : std::true_type {};
template <typename T, typename = void>
struct HasCheckMesh : std::false_type {};
template <typename T>
struct HasCheckMesh<T, std::void_t<decltype(std::declval<const T&>().checkMesh(std::declval<const Mesh&>()))>>
    : std::true_type {};

template <typename T>
class RegisteredResponse final : public ResponseFunction {
 public:
  explicit RegisteredResponse(const Teuchos::ParameterList& p) : m_response(p) {}
  double value(const ResponseContext<double>& c) const override { return m_response.evaluate(c); }
  TangentFad derivative(const ResponseContext<TangentFad>& c) const override {
    if constexpr (T::kDifferentiable) return m_response.evaluate(c);
    else throw std::logic_error(std::string(T::kName) + " has no derivative");
  }
  GradientFad gradient(const ResponseContext<GradientFad>& c) const override {
    if constexpr (T::kDifferentiable) return m_response.evaluate(c);
    else throw std::logic_error(std::string(T::kName) + " has no gradient");
  }
  bool reactionWeights(const Mesh& mesh, const DofMap& dofMap, Geometry geometry, Vector& c) const override {
    if constexpr (T::kAdaptivityTarget) {
      c.putScalar(0.0);
      auto view = c.getLocalViewHost(Tpetra::Access::ReadWrite);
      m_response.reactionWeights(mesh, dofMap, geometry, view);
      return true;
    } else {
      return false;
    }
  }
  std::string fieldRead() const override {
    if constexpr (HasFieldRead<T>::value) return m_response.fieldRead();
    else return FieldOf<T>::value;
  }
  void checkMesh(const Mesh& mesh) const override {
    if constexpr (HasCheckMesh<T>::value) m_response.checkMesh(mesh);
  }

 private:
  T m_response;
};

template <typename... Types>
std::vector<ResponseTypeInfo> collect(ResponseList<Types...>) {
  return {ResponseTypeInfo{Types::kName, Types::kDescription, Types::kNeedsBoundary, Types::kNeedsWall,
                           Types::kReactionBased, Types::kAdaptivityTarget, Types::kDifferentiable,
                           FieldOf<Types>::value}...};
}

}  // namespace

const std::vector<ResponseTypeInfo>& responseTypes() {
  static const std::vector<ResponseTypeInfo> types = collect(RegisteredResponses{});
  return types;
}

int responseTypeIndex(const std::string& name) { return indexByName(responseTypes(), name); }

std::string responseTypeNames(bool ResponseTypeInfo::*trait, const std::string& separator) {
  std::string names;
  for (const ResponseTypeInfo& t : responseTypes())
    if (t.*trait) names += (names.empty() ? "" : separator) + t.name;
  return names;
}

namespace {

void buildValidResponseParameters(const ValidList& list) {
  Teuchos::ParameterList& valid = *list;
  const auto& types = responseTypes();
  Teuchos::Array<std::string> names, docs;
  Teuchos::Array<int> indices;
  for (const ResponseTypeInfo& t : types) {
    indices.push_back(static_cast<int>(names.size()));
    names.push_back(t.name);
    docs.push_back(t.description);
  }
  Teuchos::setStringToIntegralParameter<int>(
      "Type", types.front().name, "what to compute (include/flowform/responses/, one file per type)", names(),
      docs(), indices(), &valid);
  // The union of the types' entries, in the order first declared; each entry's doc says
  // which types read it and how ("Boundary Force, Mean Pressure: the group the tool acts on; ...").
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> uses;  // entry -> (doc, types)
  for (size_t i = 0; i < types.size(); ++i) {
    Teuchos::ParameterList own;
    declareResponseParameters(static_cast<int>(i), own);
    for (auto it = own.begin(); it != own.end(); ++it) {
      const std::string& name = own.name(it);
      if (!valid.isParameter(name)) valid.setEntry(name, own.entry(it));
      auto& docs = uses[name];
      const std::string& doc = own.entry(it).docString();
      const auto same = std::find_if(docs.begin(), docs.end(), [&](const auto& d) { return d.first == doc; });
      if (same == docs.end()) docs.push_back({doc, types[i].name});
      else same->second += ", " + types[i].name;
    }
  }
  for (const auto& [name, docs] : uses) {
    std::string text;
    for (const auto& [doc, users] : docs) text += (text.empty() ? "" : "; ") + users + ": " + doc;
    valid.getEntryRCP(name)->setDocString(text);
  }
}

}  // namespace

Teuchos::RCP<const Teuchos::ParameterList> validResponseParameters() {
  return validListOnce<buildValidResponseParameters>("Response");
}

void declareResponseParameters(int type, Teuchos::ParameterList& list) {
  if (!visitByIndex(RegisteredResponses{}, type, [&](auto tag) { decltype(tag)::type::declareParameters(list); }))
    throw std::out_of_range("declareResponseParameters: no response type " + std::to_string(type));
}

std::shared_ptr<const ResponseFunction> makeResponse(int type, const Teuchos::ParameterList& validated) {
  std::shared_ptr<const ResponseFunction> response;
  if (!visitByIndex(RegisteredResponses{}, type, [&](auto tag) {
        response = std::make_shared<RegisteredResponse<typename decltype(tag)::type>>(validated);
      }))
    throw std::out_of_range("makeResponse: no response type " + std::to_string(type));
  return response;
}

}  // namespace flowform
