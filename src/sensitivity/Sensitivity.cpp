#include "flowform/sensitivity/Sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <nlohmann/json.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/core/Strings.hpp"
#include "flowform/core/ValidList.hpp"
#include "flowform/problem/Problem.hpp"

namespace flowform {

namespace {

/// fd_check's entries for the solution fields (beside the responses).
const char* const kFieldEntries[] = {"velocity_field", "pressure_field"};

}  // namespace

static void buildValidParameters(const ValidList& valid) {
  std::string materialNames;  // per registered law, its sensitivity parameters
  for (const MaterialLawInfo& law : materialLaws()) {
    std::string names;
    for (const MaterialParameterInfo& p : law.parameters)
      if (p.sensitivity) names += (names.empty() ? "" : ", ") + std::string(p.name);
    materialNames += (materialNames.empty() ? "" : "; ") + law.name + ": " + names;
  }
  valid->set("Parameters", Teuchos::Array<std::string>(),
             "parameters h to differentiate by: Friction Coefficient (every wall's ν), Friction Coefficient:<wall>, "
             "Friction Field:<wall>/<j> (station j of a wall's Friction Field), "
             "Shear Factor, Shear Factor:<wall>, the sensitivity parameters of the case's Material/Law (" +
                 materialNames + "), Geo Parameter:<name> (a Mesh/Geo Parameters entry), Boundary Value:<group>/<entry> "
                 "(a boundary condition's Velocity X/Y, Temperature, Heat Transfer Coefficient, Ambient or Tool "
                 "Temperature, Friction Heat Fraction), Thermal:<name> (Material/Thermal's Conductivity, Density, "
                 "Specific Heat, Heat Fraction); none: no sensitivity work");
  valid->set("Finite Difference Check", false,
             "recompute every sensitivity by central differences (two more nonlinear solves per parameter, from the "
             "converged state, each with its contact-status loop) and report the relative difference (fd_check)");
  valid->set("Finite Difference Step", 2e-4,
             "δ: absolute for ν and m (the paper's Δν = 2e-4), relative to |h| for σ0, γ, n",
             inRange(0.0, 1.0, true, false));
  Teuchos::setStringToIntegralParameter<int>(
      "Jacobian", "Converged",
      "factors for the DDM solves: Converged (K_t assembled and factored at the converged q, one factorization) or "
      "Last Newton Iterate (the factors NOX leaves, of the iterate before the converged one: none)",
      Teuchos::tuple<std::string>("Converged", "Last Newton Iterate"), valid.get());
  Teuchos::setStringToIntegralParameter<int>(
      "Finite Difference Scales", "Held",
      "contact penalty scales in the check's runs: Held (the base run's, as the DDM holds them: checks the DDM) or "
      "Recomputed (from the start state at h ± δ, as a fresh solve would: measures what holding them neglects)",
      Teuchos::tuple<std::string>("Held", "Recomputed"), valid.get());
  valid->set("Responses", Teuchos::Array<std::string>(),
             "the responses to differentiate (each a differentiable response of the case); empty: all of them. "
             "Method = Adjoint solves one adjoint per response named");
  Teuchos::setStringToIntegralParameter<int>(
      "Method", "Direct",
      "Direct (dq/dh for every parameter, one back-substitution each: the sensitivity fields, the total derivative "
      "through free surfaces) or Adjoint (one transposed back-substitution per response, dphi/dh = dphi/dh|_q - "
      "lambda.dR/dh: for many parameters and few responses; no fields, no free-surface total derivative, no Rigid "
      "Inflow)",
      Teuchos::tuple<std::string>("Direct", "Adjoint"), valid.get());
  Teuchos::setStringToIntegralParameter<int>(
      "Shape Derivative", "Total",
      "with free surfaces: Total (the derivatives through the moving surfaces as well, sensitivities_total_shape; "
      "two assemblies per surface node, docs/theory.md §3.5) or Frozen (the DDM on the converged shape only); "
      "no effect without free surfaces",
      Teuchos::tuple<std::string>("Total", "Frozen"), valid.get());
}

Teuchos::RCP<const Teuchos::ParameterList> Sensitivity::validParameters() {
  return validListOnce<buildValidParameters>("Sensitivity");
}

Sensitivity::Sensitivity(const Teuchos::ParameterList* list, const std::vector<ContactWall>& walls,
                         const Responses& responses, int materialLaw, const GeoParameterValues& geo,
                         const BoundaryValues& boundary, const FieldRegistry& fields) {
  if (!list) return;
  const bool temperatureField = fields.contains(kTemperatureField);
  std::set<std::string> seen;
  for (const std::string& given : list->get<Teuchos::Array<std::string>>("Parameters")) {
    const std::string name = trim(given);
    if (name.empty()) continue;
    if (!seen.insert(name).second) throw InputError("Sensitivity/Parameters: '" + name + "' is given twice");
    m_parameters.push_back(parseSensitivityParameter(name, walls, materialLaw, geo, boundary));
    if (!temperatureField && m_parameters.back().kind == ParameterKind::Thermal)
      throw InputError("Sensitivity/Parameters: '" + name + "' is a property of the temperature field, and the case "
                       "has none: add a Material/Thermal sublist");
    // With a Temperature field the law's own temperature is only Newton's start (the field gives
    // each cell its T): its derivative would be 0, whatever the physics.
    if (temperatureField && m_parameters.back().kind == ParameterKind::Material &&
        m_parameters.back().material == temperatureParameter(materialLaw))
      throw InputError("Sensitivity/Parameters: '" + name + "' is the law's uniform temperature, which a case with "
                       "Material/Thermal does not use (the Temperature field gives each cell its own); differentiate "
                       "by a boundary's temperature instead, e.g. 'Boundary Value:<inflow group>/Temperature'");
    // With a Strain field the law's own strain is likewise only the field's start.
    if (fields.contains(kStrainField) && m_parameters.back().kind == ParameterKind::Material &&
        m_parameters.back().material == strainParameter(materialLaw))
      throw InputError("Sensitivity/Parameters: '" + name + "' is the law's uniform strain, which a case with "
                       "Material/Strain Field does not use (the Strain field gives each cell its own); differentiate "
                       "by the inflow's strain instead, 'Boundary Value:<inflow group>/Strain'");
    // The Tresca bound m σ̄_k/√3 uses σ̄_k held from the start of the solve (ContactWall::
    // setScales), so its dependence on the material parameters (and on q) is not in ∂R/∂h
    // or K_t: refuse rather than report a derivative that misses a full-size term.
    if (m_parameters.back().kind == ParameterKind::Material)
      for (const ContactWall& wall : walls)
        if (wall.usesShearFactor())
          throw InputError("Sensitivity/Parameters: '" + name + "' is not available while wall '" + wall.name() +
                           "' uses Tresca or Orowan friction (its bound m σ̄/√3 holds σ̄ fixed; docs/sensitivity.md); "
                           "its friction parameters are");
  }
  m_check = list->get<bool>("Finite Difference Check");
  m_step = list->get<double>("Finite Difference Step");
  m_holdScales = list->get<std::string>("Finite Difference Scales") == "Held";
  m_lastNewtonJacobian = list->get<std::string>("Jacobian") == "Last Newton Iterate";
  m_totalShapeRequested = list->get<std::string>("Shape Derivative") == "Total";
  m_adjoint = list->get<std::string>("Method") == "Adjoint";
  const std::vector<std::string> differentiable = responses.differentiableNames();
  for (const std::string& given : list->get<Teuchos::Array<std::string>>("Responses")) {
    const std::string name = trim(given);
    if (name.empty()) continue;
    if (std::find(differentiable.begin(), differentiable.end(), name) == differentiable.end())
      throw InputError("Sensitivity/Responses: '" + name + "' is not a differentiable response of the case; they are: " +
                       join(differentiable, ", "));
    if (std::find(m_responseNames.begin(), m_responseNames.end(), name) == m_responseNames.end())
      m_responseNames.push_back(name);
  }
  if (m_responseNames.empty()) m_responseNames = differentiable;
  if (m_adjoint && m_lastNewtonJacobian)
    throw InputError("Sensitivity/Jacobian: 'Last Newton Iterate' is for Method = Direct; the adjoint needs the exact "
                     "K_t at the converged q (its transpose is solved): use Jacobian = Converged");
  if (m_check)
    for (const std::string& name : responses.names())
      for (const char* reserved : kFieldEntries)
        if (name == reserved)
          throw InputError("Responses/" + name + ": the name is taken by the finite-difference check's field entry; "
                           "rename the response");
}

void Sensitivity::compute(FlowModel& model, const Vector& x, const Responses& responses, const Mesh& mesh,
                          const DofMap& dofMap, const std::vector<ContactWall>& walls,
                          const RigidInflowLinearization* inflow, const GeoPartialsSource* geo) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: sensitivity"));
  const int factorizations0 = model.linearSolver().numFactorizations();
  const int solves0 = model.linearSolver().numSolves();
  m_computed = false;

  // A Geo Parameter's ∂R/∂h (and ∂φ/∂h, ∂F/∂h) from the mesh moved along its motion, before the
  // factors (a moved mesh drops them).
  std::map<std::string, MeshPartials> meshPartials;
  m_geoMotions.clear();
  for (const SensitivityParameter& h : m_parameters) {
    if (!h.partialsFromProblem()) continue;
    if (!geo) throw std::logic_error("Sensitivity::compute: a Geo Parameter or Boundary Value without its partials");
    MeshPartials partials = (*geo)(h, x);
    if (h.isGeo()) m_geoMotions[h.name] = std::move(partials.motion);
    meshPartials[h.name] = std::move(partials);
  }

  // The factors: of K_t at the converged q, or those NOX left (the previous iterate's).
  const auto point = model.jacobianPoint();
  if (m_lastNewtonJacobian && model.hasJacobian() && !point.is_null()) {
    Vector diff(x, Teuchos::Copy);
    diff.update(-1.0, *point, 1.0);
    m_jacobianOffset = diff.norm2() / std::max(x.norm2(), 1e-300);
    m_jacobianUsed = "last Newton iterate";
  } else {
    if (m_lastNewtonJacobian) log() << "sensitivity: no factorization left by Newton; factoring K_t at the converged q\n";
    m_jacobianOffset = 0.0;
    m_jacobianUsed = "converged";
    try {
      model.restartLinearization();  // K_t exact at the converged q
      model.computeJacobian(x);
    } catch (const std::exception& e) {  // a singular K_t: no sensitivities, exit 3
      log() << "sensitivity: " << e.what() << "\n";
      m_finite = false;
      m_factorizations = model.linearSolver().numFactorizations() - factorizations0;
      return;
    }
  }

  if (m_adjoint) {
    computeByAdjoint(model, x, responses, mesh, dofMap, walls, meshPartials);
    m_factorizations = model.linearSolver().numFactorizations() - factorizations0;
    m_solves = model.linearSolver().numSolves() - solves0;
    return;
  }

  // K_t dq/dh_j = −∂R/∂h_j: one MultiVector, one back-substitution per column.
  const size_t numParameters = m_parameters.size();
  MultiVector rhs(x.getMap(), numParameters);
  m_dqdh = Teuchos::rcp(new MultiVector(x.getMap(), numParameters));
  assembleParameterLoads(model, x, meshPartials, rhs);
  model.solve(rhs, *m_dqdh);
  m_rhsNorms.assign(numParameters, 0.0);
  m_solutionNorms.assign(numParameters, 0.0);
  rhs.norm2(Teuchos::ArrayView<double>(m_rhsNorms));
  m_dqdh->norm2(Teuchos::ArrayView<double>(m_solutionNorms));
  m_finite = true;
  for (double n : m_solutionNorms) m_finite = m_finite && std::isfinite(n);
  // A Rigid Inflow's speed U: K g = −∂f/∂U, then the bordered system's dq/dh (Sensitivity.hpp).
  m_inflow = inflow != nullptr;
  m_inflowSpeedDerivatives.clear();
  if (inflow && m_finite) {
    MultiVector g(x.getMap(), 1);
    model.solve(*inflow->minusDfDU, g);
    const Vector gU = *g.getVector(0);
    m_inflowForceSlope = inflow->dForce(gU, nullptr);
    log() << "sensitivity: rigid inflow: dF/dU = " << m_inflowForceSlope << "\n";
    for (size_t j = 0; j < numParameters; ++j) {
      auto column = m_dqdh->getVectorNonConst(j);
      const auto partials = meshPartials.find(m_parameters[j].name);
      const double dFdh = inflow->dForce(*column, &m_parameters[j]) +
                          (partials != meshPartials.end() ? partials->second.dInflowForce : 0.0);
      const double dUdh = -dFdh / m_inflowForceSlope;
      column->update(dUdh, gU, 1.0);
      m_inflowSpeedDerivatives[m_parameters[j].name] = dUdh;
      log() << "sensitivity: rigid inflow: dU/d" << m_parameters[j].name << " = " << dUdh << "\n";
    }
    m_dqdh->norm2(Teuchos::ArrayView<double>(m_solutionNorms));
    for (double n : m_solutionNorms) m_finite = m_finite && std::isfinite(n);
  }
  m_factorizations = model.linearSolver().numFactorizations() - factorizations0;
  m_solves = model.linearSolver().numSolves() - solves0;

  m_responseDerivatives.clear();
  for (size_t j = 0; j < numParameters; ++j) {
    log() << "sensitivity: " << m_parameters[j].name << ": |dR/dh| = " << m_rhsNorms[j]
          << ", |dq/dh| = " << m_solutionNorms[j] << "\n";
    if (!m_finite) continue;
    const auto d = responses.derivatives(x, *m_dqdh->getVector(j), m_parameters[j], mesh, dofMap, model.assembler(),
                                         walls);
    const auto partials = meshPartials.find(m_parameters[j].name);
    for (const auto& [name, value] : d) {
      if (std::find(m_responseNames.begin(), m_responseNames.end(), name) == m_responseNames.end()) continue;
      m_responseDerivatives[name][m_parameters[j].name] =
          value + (partials != meshPartials.end() ? partials->second.dPhidh.at(name) : 0.0);
      log() << "sensitivity:   d" << name << "/dh = " << m_responseDerivatives[name][m_parameters[j].name] << "\n";
    }
  }
  // A moving tool's partials were taken with the flow following it (GeoParameterMotion.hpp): the
  // responses' derivatives above are complete with the solved part; dq/dh itself gets the shift.
  for (size_t j = 0; j < numParameters && m_finite; ++j) {
    const auto partials = meshPartials.find(m_parameters[j].name);
    if (partials != meshPartials.end() && !partials->second.velocityShift.is_null())
      m_dqdh->getVectorNonConst(j)->update(1.0, *partials->second.velocityShift, 1.0);
  }
  m_computed = m_finite;
  if (!m_finite) {
    log() << "sensitivity: dq/dh is not finite (singular Jacobian?)\n";
    m_dqdh = Teuchos::null;  // no NaN fields are written
  }
}

void Sensitivity::assembleParameterLoads(FlowModel& model, const Vector& x,
                                         const std::map<std::string, MeshPartials>& partials, MultiVector& rhs) const {
  for (size_t j = 0; j < m_parameters.size(); ++j) {
    auto column = rhs.getVectorNonConst(j);
    const auto given = partials.find(m_parameters[j].name);
    if (given != partials.end()) {
      column->update(-1.0, *given->second.dRdh, 0.0);
      continue;
    }
    model.assembler().parameterDerivative(x, m_parameters[j], *column);
    column->scale(-1.0);
  }
}

void Sensitivity::computeByAdjoint(FlowModel& model, const Vector& x, const Responses& responses, const Mesh& mesh,
                                   const DofMap& dofMap, const std::vector<ContactWall>& walls,
                                   const std::map<std::string, MeshPartials>& partials) {
  // K_tᵀ λ_φ = (∂φ/∂q)ᵀ: one MultiVector, one transposed back-substitution per response.
  const size_t numResponses = m_responseNames.size(), numParameters = m_parameters.size();
  m_responseDerivatives.clear();
  m_rhsNorms.assign(numParameters, 0.0);
  m_solutionNorms.clear();
  m_finite = true;
  if (numResponses > 0) {
    MultiVector gradient(x.getMap(), numResponses), lambda(x.getMap(), numResponses);
    responses.gradients(x, m_responseNames, mesh, dofMap, model.assembler(), walls, gradient);
    model.solveTranspose(gradient, lambda);
    m_solutionNorms.assign(numResponses, 0.0);
    lambda.norm2(Teuchos::ArrayView<double>(m_solutionNorms));
    for (double n : m_solutionNorms) m_finite = m_finite && std::isfinite(n);
    if (!m_finite) {
      log() << "sensitivity: an adjoint is not finite (singular Jacobian?)\n";
      return;
    }
    // −∂R/∂h_j for every parameter, then dφ/dh_j = ∂φ/∂h_j + λ_φ·(−∂R/∂h_j).
    MultiVector loads(x.getMap(), numParameters);
    assembleParameterLoads(model, x, partials, loads);
    loads.norm2(Teuchos::ArrayView<double>(m_rhsNorms));
    for (size_t j = 0; j < numParameters; ++j) {
      const SensitivityParameter& h = m_parameters[j];
      const auto given = partials.find(h.name);
      const std::map<std::string, double> explicitPart = responses.partials(x, h, mesh, dofMap, model.assembler(), walls);
      log() << "sensitivity: " << h.name << ": |dR/dh| = " << m_rhsNorms[j] << " (adjoint)\n";
      for (size_t i = 0; i < numResponses; ++i) {
        const std::string& name = m_responseNames[i];
        const double value = explicitPart.at(name) + (given != partials.end() ? given->second.dPhidh.at(name) : 0.0) +
                             lambda.getVector(i)->dot(*loads.getVector(j));
        m_responseDerivatives[name][h.name] = value;
        log() << "sensitivity:   d" << name << "/dh = " << value << "\n";
      }
    }
  }
  m_computed = true;
}

void Sensitivity::checkMethod(bool rigidInflow, bool freeSurfaces) const {
  if (!m_adjoint || !requested()) return;
  if (rigidInflow)
    throw InputError("Sensitivity/Method: Adjoint does not handle a Rigid Inflow (its speed's bordered system needs "
                     "dq/dh); use Method = Direct");
  if (freeSurfaces && m_totalShapeRequested)
    throw InputError("Sensitivity/Method: Adjoint gives no dq/dh, which the total derivative through the free "
                     "surfaces needs; use Method = Direct, or Shape Derivative = Frozen");
}

void Sensitivity::report(nlohmann::json& summary) const {
  nlohmann::json& s = summary["sensitivities"];
  s = nlohmann::json::object();
  for (const auto& [response, byParameter] : m_responseDerivatives)
    for (const auto& [parameter, value] : byParameter) s[response][parameter] = value;

  nlohmann::json parameters = nlohmann::json::array();
  for (size_t j = 0; j < m_parameters.size(); ++j) {
    nlohmann::json p = {{"name", m_parameters[j].name}, {"symbol", m_parameters[j].symbol}};
    if (j < m_rhsNorms.size()) p["dR_dh_norm"] = m_rhsNorms[j];
    if (!m_adjoint && j < m_solutionNorms.size()) p["dq_dh_norm"] = m_solutionNorms[j];
    parameters.push_back(p);
  }
  summary["sensitivity"] = {{"parameters", parameters},
                            {"method", m_adjoint ? "adjoint" : "direct"},
                            {"factorizations", m_factorizations},
                            {"solves", m_solves},
                            {"jacobian", m_jacobianUsed.empty() ? nlohmann::json(nullptr) : nlohmann::json(m_jacobianUsed)},
                            {"jacobian_offset", m_jacobianOffset},
                            {"finite", m_finite}};
  if (m_adjoint) {
    nlohmann::json adjoints = nlohmann::json::object();
    for (size_t i = 0; i < m_responseNames.size() && i < m_solutionNorms.size(); ++i)
      adjoints[m_responseNames[i]] = m_solutionNorms[i];
    summary["sensitivity"]["adjoint_norms"] = adjoints;
  }
  if (m_inflow)
    summary["sensitivity"]["rigid_inflow"] = {{"force_slope", m_inflowForceSlope},
                                              {"speed_derivatives", m_inflowSpeedDerivatives}};
}

}  // namespace flowform
