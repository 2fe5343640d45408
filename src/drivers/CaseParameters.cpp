#include "flowform/drivers/CaseParameters.hpp"
#include "flowform/optimization/OptimizationSettings.hpp"

#include <algorithm>
#include <optional>
#include <tuple>
#include <sstream>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/estimation/EstimationMethods.hpp"
#include "flowform/freesurface/FreeSurfaceLoop.hpp"
#include "flowform/drivers/OutputFields.hpp"
#include "flowform/mesh/MeshReader.hpp"
#include "flowform/physics/StrainField.hpp"
#include "flowform/physics/ThermalProperties.hpp"
#include "flowform/physics/materials/MaterialLaws.hpp"
#include "flowform/solvers/NonlinearSolver.hpp"
#include "flowform/responses/ResponseRegistry.hpp"
#include "flowform/responses/Responses.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/freesurface/FreeSurface.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

namespace {

/// "Boundary Force or Mean Pressure": the response types the adaptive loop can target.
std::string adaptivityTargets() { return responseTypeNames(&ResponseTypeInfo::adaptivityTarget, " or "); }

using Teuchos::ParameterList;

/// The entries of `list` whose type differs from the valid one's. Checked before Teuchos'
/// validation, whose number validators would try to convert a string ("stod") and report
/// neither the parameter nor the value.
void checkTypes(const ParameterList& list, const ParameterList& valid, const std::string& prefix = "") {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const std::string path = prefix.empty() ? name : prefix + "/" + name;
    const Teuchos::ParameterEntry* expected = valid.getEntryPtr(name);
    if (!expected) continue;  // unknown names are Teuchos' to report, with the valid list
    const Teuchos::ParameterEntry& given = list.entry(it);
    if (expected->isList() && given.isList()) {
      checkTypes(list.sublist(name), valid.sublist(name), path);
    } else if (given.getAny().type() != expected->getAny().type()) {
      throw InputError(path + " must be of type " + expected->getAny().typeName() + ", but the case gives " +
                       given.getAny().typeName() + " '" + Teuchos::toString(given.getAny()) + "'");
    }
  }
}

/// Teuchos' message without its bookkeeping lines ("Throw number = 1", blank runs).
std::string cleanTeuchosMessage(const std::string& what) {
  std::istringstream in(what);
  std::string line, out;
  while (std::getline(in, line))
    if (!line.empty() && line.rfind("Throw number", 0) != 0) out += line + "\n";
  if (!out.empty()) out.pop_back();
  return out;
}

/// Validates `list` against `valid` (setting defaults), naming the sublist on failure.
void validateSublist(ParameterList& list, const ParameterList& valid, const std::string& where, int depth = 1000) {
  try {
    list.validateParametersAndSetDefaults(valid, depth);
  } catch (const std::exception& e) {
    throw InputError("in " + where + ": " + cleanTeuchosMessage(e.what()));
  }
}

/// "a, b, c"
std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

static void buildValidCaseParameters(const ValidList& valid) {

  ParameterList& problem = valid->sublist("Problem", false, "kind of model");
  Teuchos::setStringToIntegralParameter<int>("Geometry", "Plane Strain",
                                             "Plane Strain (per unit depth) or Axisymmetric (x = r, y = z)",
                                             Teuchos::tuple<std::string>("Plane Strain", "Axisymmetric"), &problem);
  problem.set("Body Force X", 0.0, "f_x, force per unit volume", finiteNumber());
  problem.set("Body Force Y", 0.0, "f_y, force per unit volume", finiteNumber());

  // The default law's list; validateCase validates against the case's law's (physics/materials/).
  valid->set("Material", *validMaterialParameters(0), "rigid-viscoplastic law (docs/theory.md §1)");
  // Documented here (--help, --set); validated on its own, and only when the case gives it.
  valid->sublist("Material").set("Thermal", *ThermalProperties::validParameters(),
                                 "the workpiece's thermal properties: given, the case has a Temperature field coupled "
                                 "to the flow (docs/theory.md §10); absent, the case is isothermal");
  valid->sublist("Material").set("Strain Field", *StrainFieldSettings::validParameters(),
                                 "given, the case has a Strain field (the equivalent strain carried along the "
                                 "streamlines, u.grad eps = e) that a law with a Strain parameter reads, its inflow "
                                 "value a group's 'Strain' entry (docs/theory.md §1.1); absent, no strain field");

  ParameterList& stab = valid->sublist("Stabilization", false, "pressure stabilization");
  stab.set("Beta", 0.1, "β in τ_K = β h_K² / (2 μ_K); h_K = cell diameter (docs/verification.md)", nonNegative());

  valid->set("Mesh", *validMeshParameters(), "the mesh (gmsh .msh or .geo)");
  // Free-form: one sublist per group. The template documents the entries (--help) and gives
  // --set the types of entries the case does not have yet.
  ParameterList& bcTemplate = valid->sublist("Boundary Conditions", false, "one sublist per boundary group name")
                                  .sublist("<group name>", false, "the condition on one gmsh physical group");
  bcTemplate.setParameters(*BoundaryConditions::validGroupParameters());
  for (auto it = ContactWall::validParameters()->begin(); it != ContactWall::validParameters()->end(); ++it)
    if (ContactWall::validParameters()->name(it) != "Type")
      bcTemplate.setEntry(ContactWall::validParameters()->name(it), ContactWall::validParameters()->entry(it));
  // A Free Surface group's own entries (its Start Group has the contact wall's name and type).
  for (auto it = validFreeSurfaceParameters()->begin(); it != validFreeSurfaceParameters()->end(); ++it)
    if (!bcTemplate.isParameter(validFreeSurfaceParameters()->name(it)))
      bcTemplate.setEntry(validFreeSurfaceParameters()->name(it), validFreeSurfaceParameters()->entry(it));
  valid->set("Solver", *NonlinearSolver::validParameters(), "Newton and continuation");

  ParameterList& output = valid->sublist("Output", false, "what is written");
  output.set("Write Solution", true, "solution.h5 + solution.xdmf");
  output.set("Boundary CSV", true, "one CSV per named boundary group");
  const std::vector<std::string>& cellFields = cellFieldNames();
  output.set("Cell Fields", Teuchos::Array<std::string>(cellFields.begin(), cellFields.end()),
             "cell fields to write: any of " + joined(cellFields));
  valid->sublist("Responses", false, "functionals by name (include/flowform/responses/Responses.hpp)")
      .sublist("<response name>", false, "one functional")
      .setParameters(*Responses::validParameters());
  ParameterList& estimation =
      valid->sublist("Error Estimation", false, "a posteriori error estimates of the responses (docs/theory.md §7)");
  {
    // The choices and their description from the registry (estimation/EstimationMethods.hpp).
    Teuchos::Array<std::string> names(1, "None");
    std::string doc =
        "None, or a method by which every response (and sensitivity) gets an estimate of its discretization "
        "error from the uniformly refined mesh, eta = (phi_refined - phi) / (1 - 2^-Order), written to "
        "summary.json functionals_error_estimate, sensitivities_error_estimate and "
        "sensitivities_total_shape_error_estimate (docs/theory.md §7); the adaptive loop uses the case's method, " +
        estimationMethods().front().name + " when None:";
    for (const EstimationMethodInfo& method : estimationMethods()) {
      names.push_back(method.name);
      doc += " " + method.name + ": " + method.description + ";";
    }
    doc.back() = '.';
    Teuchos::setStringToIntegralParameter<int>("Method", "None", doc, names(), &estimation);
  }
  estimation.set("Newton Steps", 8,
                 "Method = Newton Step: at most this many Newton steps (assemblies and factorizations) on the refined "
                 "mesh",
                 intInRange(1, 50));
  estimation.set("Step Tolerance", 0.1,
                 "Method = Newton Step: the steps stop when a chord step moves every differentiable response by at "
                 "most this fraction of its distance from the coarse value (of its estimate)",
                 inRange(0.0, 1.0));
  estimation.set("Order", 1.0,
                 "p, the order in h at which the responses' error falls under uniform refinement: 1 where a singular "
                 "corner dominates (the extrusion's die lip), 2 for a smooth solution; the estimate is "
                 "(phi_refined - phi) / (1 - 2^-p)",
                 inRange(0.1, 10.0));
  estimation.set("Coarser Levels", 2,
                 "Method = Coarser Mesh: how many meshes coarser than the run's are solved (at most Mesh/Uniform "
                 "Refinements): 1 gives eta = (phi - phi_2h) / (2^Order - 1); 2 fits the two-term error "
                 "A h^Order + B h^(Second Order) to the three levels (the extrusion's die lip and bulk, of opposite "
                 "signs, which two levels cannot tell apart); the adaptive loop meshes its cycles refined this often",
                 intInRange(1, 2));
  estimation.set("Nested Start", true,
                 "Method = Coarser Mesh: the coarser levels are solved first, coarsest to finest, each from the one "
                 "below, and the run starts from the finest of them (nested iteration: the run's Newton starts next to "
                 "its answer, a free surface from the coarser level's shape); the estimate reads those levels. false: the run first, then each level from the next finer one");
  estimation.set("Second Order", 2.0,
                 "Method = Coarser Mesh with 2 Coarser Levels: the order of the error's second term (the smooth bulk: "
                 "2), larger than Order",
                 inRange(0.1, 10.0));
  ParameterList& adaptivity = valid->sublist(
      "Adaptivity", false,
      "adaptive meshing to a requested accuracy (docs/theory.md §7): solve, estimate (Error Estimation/Method; Coarser Mesh when None), size the next "
      "mesh from the indicators, remesh the .geo through gmsh, carry the solution and contact statuses over, "
      "solve again. No sublist: none of this runs");
  adaptivity.set("Enabled", true,
                 "false: the sublist is kept but not used (the case's own mesh, solved once), e.g. "
                 "--set Adaptivity/Enabled=false on a scene that adapts by default");
  adaptivity.set("Responses", Teuchos::Array<std::string>(),
                 "names of the responses (" + adaptivityTargets() + ") whose relative error is to be met");
  adaptivity.set("Sensitivities", Teuchos::Array<std::string>(),
                 "derivatives dphi/dh whose relative error is to be met too, each 'response/parameter': a response "
                 "of the kinds Responses takes and a Sensitivity/Parameters entry (e.g. 'ram_force/Friction "
                 "Coefficient'); the mesh is sized by the response's indicators scaled to the derivative's estimate");
  adaptivity.set("Target Relative Error", 5e-3,
                 "|estimated error| / |value| to reach for every named response and sensitivity",
                 inRange(1e-8, 1.0));
  adaptivity.set("Safety Factor", 1.5,
                 "the loop stops when this times the estimated relative error meets the target: the estimate's "
                 "effectivity is >= 0.7 where measured (docs/theory.md §7), so 1.5 makes the true error meet it",
                 inRange(1.0, 100.0));
  adaptivity.set("Maximum Cycles", 8, "solve-estimate-remesh cycles at most (the first mesh is cycle 0)",
                 intInRange(1, 100));
  adaptivity.set("Maximum Dofs", 400000, "no mesh is made with more dofs than this (predicted from the size field)",
                 intInRange(100, 100000000));
  ParameterList& contact = valid->sublist("Contact", false, "the contact-status loop (docs/theory.md §2)");
  Teuchos::setStringToIntegralParameter<int>(
      "Status Update", "Complementarity",
      "Complementarity: after the first solve, every wall node that may change its status decides its contact "
      "inside Newton (normal force alpha_n max(u.n, 0), friction up to the interpolated limit of the contact zone; "
      "docs/contact.md); the nodes at open convex tool corners and on walls whose released nodes are a free surface "
      "keep statuses, decided as Certain Iterate does; Certain Iterate: after a change, Newton iterates one step at a time and the next change is read from the "
      "first iterate on which it is certain (the same decision for every state within the last step of it; "
      "docs/contact.md); Converged State: the paper's loop, every change read from a re-solved state",
      Teuchos::tuple<std::string>("Complementarity", "Certain Iterate", "Converged State"), &contact);
  contact.set("Re-solve Tolerance", 0.0,
              "relative residual ||F|| / ||F_0|| at which a re-solve after a status change stops when the next "
              "change is read from it; the state that needs no change is then converged to the Solver tolerances "
              "and checked again. 0: every re-solve to the Solver tolerances",
              inRange(0.0, 1.0));
  contact.set("Max Status Changes", 500, "give up (not converged) after this many changes",
              intInRange(0, 1000000));
  contact.set("Max Changes Per Node", 4,
              "a node that changed this often keeps its status (no cycling); if it still violates its "
              "criterion the run is reported not converged",
              intInRange(1, 1000));
  contact.set("Pressure Tolerance", 1e-3, "an active node is released when p < -this [stress]", nonNegative());
  contact.set("Penetration Tolerance", 1e-4, "a free node is activated when u·n > this [velocity]", nonNegative());
  valid->set("Free Surface", *FreeSurfaceLoop::validParameters(),
             "the loop that makes free surfaces streamlines (docs/theory.md §3); used only when a boundary group is "
             "a Free Surface or a Contact Wall's Released Nodes are Free Surface");
  valid->set("Sensitivity", *Sensitivity::validParameters(),
             "sensitivities by direct differentiation and their finite-difference check (docs/theory.md §4)");
  valid->set("Optimization", *OptimizationSettings::validParameters(),
             "design and inverse problems on Trilinos ROL (docs/optimization.md): design parameters with bounds, "
             "a response to minimize or maximize or a misfit to measured values; no sublist: nothing of this runs");
  valid->sublist("Regression", false, "expected values for a regression checker");
  valid->set("Base Case", "",
             "a case file (relative to this one) that this case changes: it is read first and this file's entries "
             "laid over it, sublist by sublist (io/CaseFile.hpp); relative paths count from this file's folder");
}

Teuchos::RCP<const ParameterList> validCaseParameters() {
  return validListOnce<buildValidCaseParameters>("flowform");
}

void validateCase(ParameterList& params) {
  const ParameterList& valid = *validCaseParameters();
  checkTypes(params, valid);
  // The root is only checked (names, no defaults): taking defaults there would copy the
  // "<group name>" templates of the free-form sublists into the case.
  try {
    params.validateParameters(valid, 0);
  } catch (const std::exception& e) {
    throw InputError("in the case parameter list: " + cleanTeuchosMessage(e.what()));
  }
  // Material/Thermal and Material/Strain Field are validated by themselves and kept only when
  // given: their presence is what gives a case its Temperature and Strain fields (a default would
  // give every case them).
  ParameterList& material = params.sublist("Material");
  const std::pair<const char*, Teuchos::RCP<const ParameterList>> fieldLists[] = {
      {"Thermal", ThermalProperties::validParameters()}, {"Strain Field", StrainFieldSettings::validParameters()}};
  std::vector<std::tuple<std::string, ParameterList, const ParameterList*>> given;
  for (const auto& [name, validList] : fieldLists)
    if (material.isSublist(name)) {
      given.emplace_back(name, material.sublist(name), validList.get());
      material.remove(name);
    }
  const ParameterList& validMaterial = *validMaterialParameters(materialLawOf(material));
  checkTypes(material, validMaterial, "Material");
  validateSublist(material, validMaterial, "Material");
  for (auto& [name, list, validList] : given) {
    checkTypes(list, *validList, "Material/" + name);
    validateSublist(list, *validList, "Material/" + name);
    material.set(name, list);
  }
  for (const char* name : {"Problem", "Stabilization", "Solver", "Output", "Contact", "Error Estimation",
                           "Free Surface"})
    validateSublist(params.sublist(name), valid.sublist(name), name);
  if (!params.isSublist("Mesh") || !params.sublist("Mesh").isParameter("File"))
    throw InputError("the case has no Mesh/File: name a .msh or .geo file");
  validateSublist(params.sublist("Mesh"), valid.sublist("Mesh"), "Mesh", 0);

  // The two-term fit of the Coarser Mesh estimate (the adaptive loop's when Method is None).
  const ParameterList& estimation = params.sublist("Error Estimation");
  const std::string method = estimation.get<std::string>("Method");
  const bool fits = (method == CoarserMeshEstimate::kName || (method == "None" && adaptivityRequested(params))) &&
                    estimation.get<int>("Coarser Levels") == 2;
  if (fits && estimation.get<double>("Second Order") <= estimation.get<double>("Order"))
    throw InputError("Error Estimation/Second Order = " + std::to_string(estimation.get<double>("Second Order")) +
                     " must be larger than Error Estimation/Order = " + std::to_string(estimation.get<double>("Order")) +
                     " (the two terms of the error the Coarser Mesh estimate fits)");

  for (const auto& name : params.sublist("Output").get<Teuchos::Array<std::string>>("Cell Fields"))
    if (std::find(cellFieldNames().begin(), cellFieldNames().end(), name) == cellFieldNames().end())
      throw InputError("Output/Cell Fields: unknown field '" + name + "'; allowed: " + joined(cellFieldNames()));

  // Only a case with a Sensitivity sublist gets one (with defaults): none means no work.
  if (params.isSublist("Sensitivity"))
    validateSublist(params.sublist("Sensitivity"), valid.sublist("Sensitivity"), "Sensitivity");
  if (params.isSublist("Adaptivity"))
    validateSublist(params.sublist("Adaptivity"), valid.sublist("Adaptivity"), "Adaptivity");
  if (optimizationRequested(params)) {
    validateSublist(params.sublist("Optimization"), valid.sublist("Optimization"), "Optimization");
    if (adaptivityRequested(params))
      throw InputError("Optimization with Adaptivity: each design is solved on the case's own mesh; set "
                       "Adaptivity/Enabled=false (or remove the Adaptivity sublist)");
  }
  if (adaptivityRequested(params)) {
    auto targets = params.sublist("Adaptivity").get<Teuchos::Array<std::string>>("Responses");
    const auto derivatives = params.sublist("Adaptivity").get<Teuchos::Array<std::string>>("Sensitivities");
    if (targets.empty() && derivatives.empty())
      throw InputError("Adaptivity/Responses: name at least one response (" + adaptivityTargets() +
                       ") to adapt the mesh to");
    // A derivative target 'response/parameter': the parameter one the case differentiates by,
    // the response a target itself (its indicators size the mesh).
    const auto parameters = params.isSublist("Sensitivity")
                                ? params.sublist("Sensitivity").get<Teuchos::Array<std::string>>("Parameters")
                                : Teuchos::Array<std::string>();
    for (const std::string& entry : derivatives) {
      const std::size_t slash = entry.find('/');
      const std::string parameter = slash == std::string::npos ? "" : entry.substr(slash + 1);
      if (slash == std::string::npos || std::find(parameters.begin(), parameters.end(), parameter) == parameters.end())
        throw InputError("Adaptivity/Sensitivities: '" + entry + "' must be 'response/parameter' with a parameter of "
                         "Sensitivity/Parameters (the case gives: " + joined(parameters.toVector()) + ")");
      targets.push_back(entry.substr(0, slash));
    }
    // Only the responses linear in the reactions have an adjoint, hence indicators.
    const ParameterList& responses = params.sublist("Responses");
    for (const std::string& name : targets) {
      if (!responses.isSublist(name))
        throw InputError("Adaptivity/Responses: '" + name + "' is not one of the case's Responses");
      const ParameterList& response = responses.sublist(name);
      const std::string type =
          response.isParameter("Type") ? response.get<std::string>("Type") : responseTypes().front().name;
      const int index = responseTypeIndex(type);
      if (index < 0 || !responseTypes()[index].adaptivityTarget)
        throw InputError("Adaptivity/Responses: '" + name + "' is a " + type + " response; the adaptive loop needs " +
                         adaptivityTargets() + " responses (their adjoint gives the indicators)");
    }
    const std::string file = params.sublist("Mesh").get<std::string>("File");
    if (file.size() < 4 || file.substr(file.size() - 4) != ".geo")
      throw InputError("Mesh/File '" + file + "' is not a .geo, and the case asks for adaptivity (the Adaptivity "
                       "sublist, Enabled by default): the adaptive loop makes each new mesh by remeshing the .geo "
                       "geometry through gmsh with a size field, which a fixed .msh cannot give. Either solve this "
                       "mesh once with --set \"Adaptivity/Enabled=false\" (add \"Error Estimation/Method=Newton Step\" "
                       "for an error estimate), or refine it uniformly with \"Mesh/Uniform Refinements=N\" and "
                       "Adaptivity/Enabled=false, or give the .geo");
  }
}

bool adaptivityRequested(const ParameterList& params) {
  if (!params.isSublist("Adaptivity")) return false;
  const ParameterList& adaptivity = params.sublist("Adaptivity");
  // A mistyped Enabled counts as asked for: validateCase then names the type error.
  return !adaptivity.isParameter("Enabled") || !adaptivity.isType<bool>("Enabled") || adaptivity.get<bool>("Enabled");
}

FlowPhysics physicsFromCase(const ParameterList& params) {
  FlowPhysics physics;
  const ParameterList& mat = params.sublist("Material");
  physics.material = materialFromParameters(mat);
  const ParameterList& problem = params.sublist("Problem");
  physics.kernel.geometry =
      problem.get<std::string>("Geometry") == "Axisymmetric" ? Geometry::Axisymmetric : Geometry::PlaneStrain;
  physics.kernel.bodyForce[0] = problem.get<double>("Body Force X");
  physics.kernel.bodyForce[1] = problem.get<double>("Body Force Y");
  physics.kernel.beta = params.sublist("Stabilization").get<double>("Beta");
  return physics;
}

}  // namespace flowform
