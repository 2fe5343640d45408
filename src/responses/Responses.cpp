#include "flowform/responses/Responses.hpp"

#include <algorithm>
#include <type_traits>

#include "flowform/assembly/EvaluationTypes.hpp"
#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/responses/ResponseRegistry.hpp"

namespace flowform {

Teuchos::RCP<const Teuchos::ParameterList> Responses::validParameters() { return validResponseParameters(); }

Responses::Responses(const Teuchos::ParameterList& list, const Mesh& mesh) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    if (!list.isSublist(name)) throw InputError("Responses/" + name + " must be a sublist (one per response)");
    Teuchos::ParameterList r = list.sublist(name);
    try {
      r.validateParametersAndSetDefaults(*validParameters());
    } catch (const std::exception& e) {
      throw InputError("Responses/" + name + ": " + e.what());
    }
    const int type = responseTypeIndex(r.get<std::string>("Type"));
    const std::string boundary = r.get<std::string>("Boundary");
    if (responseTypes()[type].needsBoundary && !mesh.hasBoundary(boundary))
      throw InputError("Responses/" + name + "/Boundary: mesh '" + mesh.source + "' has no boundary group '" +
                       boundary + "'; it has: " + mesh.boundaryNames());
    auto function = makeResponse(type, r);
    try {
      function->checkMesh(mesh);
    } catch (const InputError& e) {
      throw InputError("Responses/" + name + "/" + e.what());
    }
    m_responses.push_back({name, boundary, type, function});
  }
}

void Responses::checkWalls(const std::vector<ContactWall>& walls) const {
  for (const Response& r : m_responses) {
    if (!responseTypes()[r.type].needsWall) continue;
    const auto wall = std::find_if(walls.begin(), walls.end(), [&](const ContactWall& w) { return w.name() == r.boundary; });
    if (wall == walls.end())
      throw InputError("Responses/" + r.name + "/Boundary: '" + r.boundary + "' is not a Contact Wall (a " +
                       responseTypes()[r.type].name + " measures one)");
    const std::string& typeName = responseTypes()[r.type].name;
    if ((typeName == NeutralAngle::kName || typeName == ForwardSlip::kName) &&
        wall->motion().kind != ToolMotion::Kind::Rotation)
      throw InputError("Responses/" + r.name + "/Boundary: a " + typeName + " measures a rotating wall (a roll), and '" +
                       r.boundary + "' has no 'Tool Motion' = Rotation");
  }
}

void Responses::checkTemperatureField(bool temperatureField) const {
  if (temperatureField) return;
  for (const Response& r : m_responses)
    if (r.function->readsTemperature())
      throw InputError("Responses/" + r.name + ": a " + responseTypes()[r.type].name +
                       " response needs a temperature field: add a Material/Thermal sublist");
}

bool Responses::reactionWeights(const std::string& name, const Mesh& mesh, const DofMap& dofMap, Geometry geometry,
                                Vector& c) const {
  for (const Response& r : m_responses)
    if (r.name == name && r.function->reactionWeights(mesh, dofMap, geometry, c)) return true;
  return false;
}

template <typename Scalar>
std::map<std::string, Scalar> Responses::evaluateAs(const Vector& xOwned, const Vector* dxOwned,
                                                    const SensitivityParameter* h, const Mesh& mesh,
                                                    const DofMap& dofMap, const Assembler& assembler,
                                                    const std::vector<ContactWall>& walls,
                                                    const Vector* givenReactions) const {
  std::map<std::string, Scalar> values;
  if (m_responses.empty()) return values;
  constexpr bool tangent = !std::is_same_v<Scalar, double>;

  // The reactions (unconstrained residual) and, for the tangent, their derivative.
  Vector reactions(dofMap.ownedMap()), dReactions(dofMap.ownedMap());
  Vector xOverlap(dofMap.overlapMap()), dxOverlap(dofMap.overlapMap());
  if (!givenReactions) assembler.residual(xOwned, reactions, false);
  if (tangent) assembler.tangent(xOwned, dxOwned, h, dReactions, false);
  xOverlap.doImport(xOwned, *dofMap.importer(), Tpetra::INSERT);
  if (dxOwned) dxOverlap.doImport(*dxOwned, *dofMap.importer(), Tpetra::INSERT);
  const Workset R = vectorReader(givenReactions ? *givenReactions : reactions, tangent ? &dReactions : nullptr);  // owned dofs: the overlap's first ones
  const Workset x = vectorReader(xOverlap, dxOwned ? &dxOverlap : nullptr);
  const MaterialParameters<Scalar> material = materialFor<Scalar>(assembler.physics().material, h);
  const ResponseContext<Scalar> context{x, R, mesh, dofMap, assembler.physics(), material, walls, h};

  for (const Response& r : m_responses) {
    if constexpr (tangent) {
      if (responseTypes()[r.type].differentiable) values[r.name] = r.function->derivative(context);
    } else {
      values[r.name] = r.function->value(context);
    }
  }
  return values;
}

std::map<std::string, double> Responses::evaluate(const Vector& xOwned, const Mesh& mesh, const DofMap& dofMap,
                                                  const Assembler& assembler, const std::vector<ContactWall>& walls,
                                                  const Vector* reactions) const {
  return evaluateAs<double>(xOwned, nullptr, nullptr, mesh, dofMap, assembler, walls, reactions);
}

std::map<std::string, double> Responses::derivatives(const Vector& xOwned, const Vector& dxOwned,
                                                     const SensitivityParameter& h, const Mesh& mesh,
                                                     const DofMap& dofMap, const Assembler& assembler,
                                                     const std::vector<ContactWall>& walls) const {
  std::map<std::string, double> d;
  for (const auto& [name, value] : evaluateAs<TangentFad>(xOwned, &dxOwned, &h, mesh, dofMap, assembler, walls))
    d[name] = value.dx(0);
  return d;
}

}  // namespace flowform
