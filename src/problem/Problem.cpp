#include "flowform/problem/Problem.hpp"

#include <algorithm>

#include "flowform/bc/FieldBoundaryValues.hpp"
#include "flowform/bc/ThermalBoundaryConditions.hpp"
#include "flowform/contact/ToolCorners.hpp"
#include "flowform/contact/WallStates.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/freesurface/ReferenceTopology.hpp"
#include "flowform/mesh/MeshReader.hpp"
#include "flowform/physics/kernels/FlowKernel.hpp"
#include "flowform/physics/kernels/CoupledFlowKernel.hpp"
#include "flowform/solvers/LinearSolverRegistry.hpp"

namespace flowform {

using Teuchos::ParameterList;

namespace {

/// A scalar field's Newton start (component `component` of x): the law's parameter `lawParameter`
/// where the law has it (−1: none), else the mean of the prescribed values; the prescribed values at
/// their nodes.
void startScalarField(Vector& x, const DofMap& dofMap, int component, int lawParameter,
                      const MaterialParameters<double>& material, const std::vector<NodeValue>& prescribed) {
  double start = 0.0;
  if (lawParameter >= 0) {
    start = material.values[lawParameter];
  } else if (!prescribed.empty()) {
    for (const auto& [node, value] : prescribed) start += value;
    start /= static_cast<double>(prescribed.size());
  }
  auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (LO n = 0; n < dofMap.numOwnedNodes(); ++n) xv(dofMap.dof(n, component), 0) = start;
  for (const auto& [node, value] : prescribed) {
    const LO n = dofMap.overlapIndex(node);
    if (dofMap.ownsNode(n)) xv(dofMap.dof(n, component), 0) = value;
  }
}

}  // namespace

Problem::Problem(const ParameterList& caseParams, const FlowPhysics& physics, const std::string& baseDir,
                 const Teuchos::RCP<const Comm>& comm, const SizeField* sizeField)
    : m_params(caseParams), m_comm(comm), m_baseDir(baseDir), m_physics(physics) {
  if (sizeField) m_sizeField = *sizeField;

  m_mesh = readMeshOnReference(m_params.sublist("Mesh"), baseDir, *comm, sizeField);
  m_madeCoords = m_mesh.coords;
  if (m_physics.kernel.geometry == Geometry::Axisymmetric)
    for (const auto& xy : m_mesh.coords)
      if (xy[0] < -1e-12)
        throw InputError("Problem/Geometry is Axisymmetric but mesh '" + m_mesh.source +
                         "' has nodes at x = r < 0; the axis is x = 0 and the section must lie in x >= 0");

  // Contact walls first: the friction law couples wall neighbours, which the DofMap must know.
  const ParameterList& bcList = m_params.sublist("Boundary Conditions");
  m_walls = contactWallsFromCase(bcList, m_mesh, m_physics.kernel.geometry);
  std::vector<std::array<GO, 2>> couplings;
  for (const ContactWall& wall : m_walls) {
    const auto pairs = wall.couplings();
    couplings.insert(couplings.end(), pairs.begin(), pairs.end());
  }
  m_responses = std::make_unique<Responses>(m_params.sublist("Responses"), m_mesh);
  m_responses->checkWalls(m_walls);

  // A case with Material/Thermal has a Temperature field, after the flow's (docs/theory.md §10); one
  // with Material/Strain Field a Strain field after that (§1.1).
  const ParameterList& material = m_params.sublist("Material");
  const bool thermal = material.isSublist("Thermal");
  const bool strain = material.isSublist("Strain Field");
  FieldRegistry fields = FieldRegistry::flow();
  if (thermal) {
    fields.add({kTemperatureField, 1});
  } else if (const std::string group = ThermalBoundaryConditions::firstThermalGroup(bcList); !group.empty()) {
    throw InputError("Boundary Conditions/" + group +
                     " gives a thermal condition, but the case has no temperature field: add a Material/Thermal "
                     "sublist (Conductivity, Density, Specific Heat, Heat Fraction) or drop the entry");
  }
  if (strain) {
    fields.add({kStrainField, 1});
    m_physics.strainField = StrainFieldSettings::fromParameters(material.sublist("Strain Field"));
    m_strainInflow = prescribedGroupValues(bcList, m_mesh, "Strain", "strains");
    if (m_strainInflow.empty())
      throw InputError("Material/Strain Field: no boundary group gives the strain the material enters with; add "
                       "'Strain' (e.g. 0) to the inflow's group (the ram, the entry) in Boundary Conditions");
  } else if (const std::string group = firstGroupWith(bcList, "Strain"); !group.empty()) {
    throw InputError("Boundary Conditions/" + group +
                     "/Strain is given, but the case has no strain field: add a Material/Strain Field sublist or "
                     "drop the entry");
  }
  m_responses->checkFields(fields);
  m_dofMap = std::make_unique<DofMap>(m_mesh, comm, couplings, fields);
  m_bcs = std::make_unique<BoundaryConditions>(bcList, m_mesh, *m_dofMap);
  markHeldNormals();
  m_assembler = std::make_unique<Assembler>(m_mesh, *m_dofMap, *m_bcs);
  if (thermal) m_physics.thermal = ThermalProperties::fromParameters(material.sublist("Thermal"));
  m_assembler->setPhysics(m_physics);
  // The flow and the fields it carries in one kernel (the law at each cell's field values).
  if (thermal && strain)
    m_assembler->setKernels({makeCellKernel(CoupledFlowKernel<true, true>{}, fields)});
  else if (thermal)
    m_assembler->setKernels({makeCellKernel(CoupledFlowKernel<true, false>{}, fields)});
  else if (strain)
    m_assembler->setKernels({makeCellKernel(CoupledFlowKernel<false, true>{}, fields)});
  std::optional<ThermalBoundaryConditions> thermalConditions;
  if (thermal)
    thermalConditions.emplace(applyThermalConditions());
  else if (strain)
    m_assembler->setPrescribedValues(prescribedStrains());
  if (!m_walls.empty()) m_assembler->setContactWalls(&m_walls);
  m_model = std::make_unique<FlowModel>(
      *m_assembler, createLinearSolver(m_params.sublist("Solver").sublist("Linear Solver"), *comm));
  makeStatusLoop();
  m_freeSurfaces = std::make_unique<FreeSurfaces>(bcList, m_mesh, m_walls);
  if (m_freeSurfaces->empty() && !m_bcs->heldGroups().empty())
    throw InputError("Boundary Conditions/" + m_bcs->heldGroups().front() +
                     ": 'Release After Free Surfaces' needs free surfaces, and the case has none");
  m_solution = Teuchos::rcp(new Vector(m_dofMap->ownedMap()));
  m_bcs->imposeOnSolution(*m_solution);
  if (thermalConditions) startTemperature(*thermalConditions);
  if (strain) startStrain();
}

std::vector<Assembler::PrescribedValue> Problem::prescribedStrains() const {
  std::vector<Assembler::PrescribedValue> values;
  if (m_strainInflow.empty()) return values;
  const int component = m_dofMap->fields().component(kStrainField);
  for (const auto& [node, value] : m_strainInflow) values.push_back({node, component, value});
  return values;
}

void Problem::startStrain() {
  // Newton's start for ε: the law's own Strain (the uniform strain it would be read at), else the
  // mean inflow strain.
  startScalarField(*m_solution, *m_dofMap, m_dofMap->fields().component(kStrainField),
                   strainParameter(m_physics.material.law), m_physics.material, m_strainInflow);
}

ThermalBoundaryConditions Problem::applyThermalConditions() {
  const int temperature = m_dofMap->fields().component(kTemperatureField);
  ThermalBoundaryConditions conditions(m_params.sublist("Boundary Conditions"), m_mesh);
  std::vector<Assembler::PrescribedValue> values;
  for (const auto& [node, value] : conditions.prescribed()) values.push_back({node, temperature, value});
  for (const Assembler::PrescribedValue& v : prescribedStrains()) values.push_back(v);
  m_assembler->setPrescribedValues(values);
  m_assembler->setHeatTransfer(conditions.transferEdges(m_mesh, *m_dofMap), temperature);
  std::vector<double> frictionHeat;  // β per wall, in the walls' order; empty when no wall heats
  for (const ContactWall& wall : m_walls) frictionHeat.push_back(conditions.frictionHeatFraction(wall.name()));
  if (std::all_of(frictionHeat.begin(), frictionHeat.end(), [](double beta) { return beta == 0.0; }))
    frictionHeat.clear();
  m_assembler->setFrictionHeat(frictionHeat, temperature);
  return conditions;
}

void Problem::shiftBoundaryValue(const std::string& group, const std::string& entry, double delta) {
  ParameterList& list = m_params.sublist("Boundary Conditions").sublist(group);
  const double value = list.get<double>(entry) + delta;
  list.set(entry, value);
  m_bcs->setGroupValue(m_mesh, group, entry, value);
  if (m_dofMap->fields().contains(kStrainField))
    m_strainInflow = prescribedGroupValues(m_params.sublist("Boundary Conditions"), m_mesh, "Strain", "strains");
  if (m_dofMap->fields().contains(kTemperatureField))
    applyThermalConditions();
  else if (m_dofMap->fields().contains(kStrainField))
    m_assembler->setPrescribedValues(prescribedStrains());
  m_model->invalidateJacobian();
}

void Problem::startTemperature(const ThermalBoundaryConditions& conditions) {
  // Newton's start for T: the law's own Temperature (Sellars–Tegart: its reference, which also
  // sets the Newtonian predictor's γ), else the mean of the prescribed temperatures. A law at T = 0
  // would have exp(Q/RT) = ∞.
  startScalarField(*m_solution, *m_dofMap, m_dofMap->fields().component(kTemperatureField),
                   temperatureParameter(m_physics.material.law), m_physics.material, conditions.prescribed());
}

Problem::~Problem() = default;

NonlinearSolver Problem::newtonSolver(bool refreshScales) {
  NonlinearSolver solver(*m_model, m_params.sublist("Solver"));
  if (refreshScales && !m_walls.empty()) solver.setBeforeNewton([this](const Vector& x) { updateWallScales(x); });
  return solver;
}

void Problem::startFrom(const Problem& other, bool decideZoneLimits, bool carryShapes) {
  if (!m_warmStart) {  // this problem's own start, for the solve from scratch should this one fail
    ColdStart cold;
    cold.solution = Teuchos::rcp(new Vector(*m_solution, Teuchos::Copy));
    for (const ContactWall& wall : m_walls) cold.walls.push_back(wall.state());
    cold.rigidInflowSpeed = m_bcs->rigidInflow().speed;
    m_coldStart = std::move(cold);
  }
  // The other mesh's free surfaces moved: this mesh, as made, takes their shape first (carryShape),
  // and the groups it released after its first loop are released here from the start.
  if (carryShapes && other.m_mesh.coords != other.m_madeCoords) {
    moveNodes(carryShape(other.meshAsMade(), other.mesh(), meshAsMade()));
  } else if (other.m_mesh.coords != other.m_madeCoords && other.m_mesh.cellNodes == m_mesh.cellNodes) {
    // Another shape on this topology (a design of the optimizer): the free surfaces' displacement
    // node by node, unless it inverts a cell here (then they start as made).
    std::vector<std::array<double, 2>> coords = m_madeCoords;
    for (std::size_t n = 0; n < coords.size(); ++n)
      for (int d = 0; d < 2; ++d) coords[n][d] += other.m_mesh.coords[n][d] - other.m_madeCoords[n][d];
    try {
      moveNodes(coords);
    } catch (const InputError&) {
      moveNodes(m_madeCoords);
    }
  }
  if (!other.m_bcs->releasedGroups().empty()) releaseHeldConditions();
  // A rigid inflow starts at the speed the other mesh found.
  if (!m_bcs->rigidInflow().group.empty()) m_bcs->setRigidInflowSpeed(m_mesh, other.m_bcs->rigidInflow().speed);
  interpolate(other.mesh(), other.dofMap(), replicate(other.solution(), other.dofMap()), m_mesh, *m_dofMap,
              *m_solution);
  m_bcs->imposeOnSolution(*m_solution);
  // Statuses carried over; a node inside an old zone limit is decided by whether it penetrates.
  const double penetrationTolerance = m_params.sublist("Contact").get<double>("Penetration Tolerance");
  std::vector<double> p;
  std::vector<std::array<double, 2>> u;
  for (ContactWall& wall : m_walls)
    for (const ContactWall& from : other.contactWalls())
      if (from.name() == wall.name()) {
        if (decideZoneLimits) wallValues(wall, *m_dofMap, *m_solution, p, u);  // collective
        wall.takeStatusesFrom(from, decideZoneLimits ? &u : nullptr, penetrationTolerance);
      }
  if (!m_walls.empty()) updateWallScales(*m_solution);
  m_warmStart = true;
}

void Problem::makeStatusLoop() {
  m_statusLoop = std::make_unique<ContactStatusLoop>(m_params.sublist("Contact"), m_mesh, *m_dofMap);
  // A wall whose released nodes are a free surface: its separation point may cycle until the
  // surface has settled; a node that still cycles then decides by itself (ContactWall), and the
  // free-surface loop does not converge while any other cycles.
  for (const ContactWall& wall : m_walls) if (wall.releasedFreeSurface()) m_statusLoop->tolerateCycling(true);
}

void Problem::restoreColdStart() {
  const ColdStart& cold = *m_coldStart;
  Tpetra::deep_copy(*m_solution, *cold.solution);
  for (size_t w = 0; w < m_walls.size(); ++w) {
    m_walls[w].leaveComplementarity();
    m_walls[w].restore(cold.walls[w]);
  }
  if (!m_bcs->rigidInflow().group.empty()) m_bcs->setRigidInflowSpeed(m_mesh, cold.rigidInflowSpeed);
  m_bcs->imposeOnSolution(*m_solution);
  makeStatusLoop();
  m_model->invalidateJacobian();
  m_warmStart = false;
}

void Problem::moveNodes(const std::vector<std::array<double, 2>>& coords) {
  m_mesh.setCoordinates(coords);
  for (ContactWall& wall : m_walls) wall.refreshGeometry(m_mesh);
  markConvexToolCorners(m_walls);
  m_bcs->refreshGeometry(m_mesh);
  markHeldNormals();
  m_bcs->imposeOnSolution(*m_solution);  // symmetry directions may have turned
  m_model->invalidateJacobian();
}

void Problem::markHeldNormals() {
  // A single velocity condition along the wall's normal (|a·n| = 1: a Parallel To the wall, or a
  // prescribed component normal to it) holds the node's normal velocity (ContactWall::setNormalHeld).
  const std::vector<NodeConstraint>& constraints = m_bcs->constraints();
  for (ContactWall& wall : m_walls)
    for (int k = 0; k < wall.numNodes(); ++k) {
      const LO n = m_dofMap->overlapIndex(wall.curve().nodes[k]);
      if (n < 0) continue;
      const NodeConstraint& c = constraints[n];
      const auto& normal = wall.curve().normals[k];
      wall.setNormalHeld(k, c.kind == NodeConstraint::Kind::Single &&
                                std::abs(c.a[0] * normal[0] + c.a[1] * normal[1]) > 1.0 - 1e-9);
    }
}

bool Problem::releaseHeldConditions() {
  if (!m_bcs->releaseHeld(m_mesh)) return false;
  markHeldNormals();
  return true;
}

void Problem::moveShape(const std::vector<std::array<double, 2>>& madeCoords,
                        const std::vector<std::array<double, 2>>& coords) {
  Mesh made = m_mesh;
  made.coords = madeCoords;
  for (ContactWall& wall : m_walls) wall.setTool(made);
  m_bcs->setToolShape(made);
  moveNodes(coords);
}

SurfaceLinearizationState Problem::linearizationState(bool withInflow) {
  SurfaceLinearizationState state{m_mesh,  *m_dofMap, m_physics.kernel.geometry, *m_freeSurfaces, m_walls, *m_model,
                                  *m_responses, *m_solution,
                                  [this](const std::vector<std::array<double, 2>>& coords) { moveNodes(coords); }};
  if (!withInflow || m_bcs->rigidInflow().group.empty()) return state;
  state.inflowForce = [this](const Vector& reactions) { return rigidInflowForceFrom(reactions); };
  state.minusDfDU = rigidInflowSpeedLoad(*m_solution);
  state.inflowForceTangent = [this](const Vector& dq) { return rigidInflowForceTangent(*m_solution, dq, nullptr); };
  return state;
}

void Problem::updateWallScales(const Vector& x) {
  std::vector<double> mu, sigma;
  m_assembler->nodalCellMaxima(x, mu, sigma);
  for (ContactWall& wall : m_walls) {
    std::vector<double> wallMu(wall.numNodes(), 0.0), wallSigma(wall.numNodes(), 0.0);
    for (int k = 0; k < wall.numNodes(); ++k) {
      const LO n = m_dofMap->overlapIndex(wall.curve().nodes[k]);
      if (n < 0) continue;  // neither this rank's node nor a neighbour of one: not used here
      const double fixed = wall.settings().penaltyViscosity;
      wallMu[k] = fixed > 0.0 ? fixed : mu[n];
      wallSigma[k] = sigma[n];
    }
    wall.setScales(std::move(wallMu), std::move(wallSigma));
  }
  m_model->invalidateJacobian();
}

}  // namespace flowform
