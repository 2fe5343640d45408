#include "flowform/responses/Responses.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

#include <Teuchos_CommHelpers.hpp>

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

void Responses::checkFields(const FieldRegistry& fields) const {
  for (const Response& r : m_responses) {
    const std::string field = r.function->fieldRead();
    if (field.empty() || fields.contains(field)) continue;
    const bool temperature = field == kTemperatureField;
    throw InputError("Responses/" + r.name + ": a " + responseTypes()[r.type].name + " response needs a " +
                     (temperature ? "temperature" : "strain") + " field: add a " +
                     (temperature ? "Material/Thermal" : "Material/Strain Field") + " sublist");
  }
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

std::map<std::string, double> Responses::partials(const Vector& xOwned, const SensitivityParameter& h,
                                                  const Mesh& mesh, const DofMap& dofMap, const Assembler& assembler,
                                                  const std::vector<ContactWall>& walls) const {
  std::map<std::string, double> d;
  for (const auto& [name, value] : evaluateAs<TangentFad>(xOwned, nullptr, &h, mesh, dofMap, assembler, walls))
    d[name] = value.dx(0);
  return d;
}

std::vector<std::string> Responses::differentiableNames() const {
  std::vector<std::string> names;
  for (const Response& r : m_responses)
    if (responseTypes()[r.type].differentiable) names.push_back(r.name);
  return names;
}

void Responses::gradients(const Vector& xOwned, const std::vector<std::string>& names, const Mesh& mesh,
                          const DofMap& dofMap, const Assembler& assembler, const std::vector<ContactWall>& walls,
                          MultiVector& gradient) const {
  gradient.putScalar(0.0);
  if (names.empty()) return;
  Vector reactions(dofMap.ownedMap()), xOverlap(dofMap.overlapMap());
  assembler.residual(xOwned, reactions, false);
  xOverlap.doImport(xOwned, *dofMap.importer(), Tpetra::INSERT);
  // Variables: the overlap dofs of x, then the owned dofs of the reactions.
  const int numOverlap = static_cast<int>(xOverlap.getLocalLength());
  const int numOwned = static_cast<int>(reactions.getLocalLength());
  Workset x = vectorReader(xOverlap), R = vectorReader(reactions);
  x.gradientSize = R.gradientSize = numOverlap + numOwned;
  R.gradientOffset = numOverlap;
  const MaterialParameters<GradientFad> material = materialFor<GradientFad>(assembler.physics().material, nullptr);
  const ResponseContext<GradientFad> context{x, R, mesh, dofMap, assembler.physics(), material, walls, nullptr};

  MultiVector byX(dofMap.overlapMap(), names.size()), byReactions(dofMap.ownedMap(), names.size());
  bool readsReactions = false;
  {
    auto gx = byX.getLocalViewHost(Tpetra::Access::OverwriteAll);
    auto gR = byReactions.getLocalViewHost(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(gx, 0.0);
    Kokkos::deep_copy(gR, 0.0);
    for (size_t i = 0; i < names.size(); ++i) {
      const auto r = std::find_if(m_responses.begin(), m_responses.end(), [&](const Response& q) { return q.name == names[i]; });
      if (r == m_responses.end() || !responseTypes()[r->type].differentiable)
        throw std::logic_error("Responses::gradients: '" + names[i] + "' is not a differentiable response");
      const GradientFad phi = r->function->gradient(context);
      if (phi.size() == 0) continue;  // independent of q
      for (int d = 0; d < numOverlap; ++d) gx(d, i) = phi.dx(d);
      for (int d = 0; d < numOwned; ++d) {
        gR(d, i) = phi.dx(numOverlap + d);
        readsReactions = readsReactions || gR(d, i) != 0.0;
      }
    }
  }
  // A rank's derivatives by its ghost dofs belong to their owners.
  gradient.doExport(byX, *dofMap.exporter(), Tpetra::ADD);
  int anyReactions = readsReactions, globalReactions = 0;
  Teuchos::reduceAll(*dofMap.comm(), Teuchos::REDUCE_MAX, anyReactions, Teuchos::outArg(globalReactions));
  if (globalReactions) {
    auto unconstrained = assembler.createJacobian();
    assembler.unconstrainedJacobian(xOwned, *unconstrained);
    unconstrained->apply(byReactions, gradient, Teuchos::TRANS, 1.0, 1.0);
  }
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
