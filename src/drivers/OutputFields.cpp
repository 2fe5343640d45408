#include "flowform/drivers/OutputFields.hpp"

namespace flowform {

namespace {

/// Columns of `dofs` (owned map) imported to rank 0 as whole mesh-numbered vectors.
Teuchos::RCP<MultiVector> toRoot(const MultiVector& dofs, const DofMap& dofMap, const Teuchos::RCP<const Map>& rootDofs) {
  auto all = Teuchos::rcp(new MultiVector(rootDofs, dofs.getNumVectors()));
  all->doImport(dofs, Import(dofMap.ownedMap(), rootDofs), Tpetra::INSERT);
  return all;
}

}  // namespace

const std::vector<std::string>& cellFieldNames() {
  static const std::vector<std::string> names = {"strain_rate", "equivalent_stress", "viscosity"};
  return names;
}

FieldSet gatherOutputFields(const Assembler& assembler, const Vector& solution, const std::vector<ContactWall>& walls,
                            const Sensitivity& sensitivity, const FiniteDifferenceCheck* fdCheck,
                            const Teuchos::Array<std::string>& cellFields) {
  const Mesh& mesh = assembler.mesh();
  const DofMap& dofMap = assembler.dofMap();
  const auto comm = dofMap.comm();
  const GO numNodes = mesh.numNodes(), numCells = mesh.numCells();
  const bool root = comm->getRank() == 0;

  // Nodal dofs to rank 0, in the global dof numbering.
  const GO numDofs = dofMap.numGlobalDofs();
  auto rootDofs = Teuchos::rcp(new Map(numDofs, root ? numDofs : 0, 0, comm));
  const auto allDofs = toRoot(solution, dofMap, rootDofs);
  // Sensitivity fields only when sensitivities were asked for and computed.
  Teuchos::RCP<MultiVector> sensitivityDofs, differenceDofs;
  if (sensitivity.hasSolutionDerivatives()) sensitivityDofs = toRoot(sensitivity.solutionDerivatives(), dofMap, rootDofs);
  if (fdCheck) differenceDofs = toRoot(fdCheck->solutionDifferences(), dofMap, rootDofs);

  // Cell values at the centroid, computed where the cell is assembled, then to rank 0:
  // e = sqrt(2/3 D:D), σ_eq = sqrt(3/2 s:s) = 3 μ e, μ(e_r).
  const std::vector<CellState> states = assembler.cellStates(solution);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto ownedCells = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(dofMap.cells()), 0, comm));
  auto rootCells = Teuchos::rcp(new Map(numCells, root ? numCells : 0, 0, comm));
  MultiVector cellValues(ownedCells, 3), allCells(rootCells, 3);
  {
    auto v = cellValues.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t k = 0; k < states.size(); ++k) {
      v(k, 0) = states[k].strainRate;
      v(k, 1) = 3.0 * states[k].viscosity * states[k].strainRate;
      v(k, 2) = states[k].viscosity;
    }
  }
  allCells.doImport(cellValues, Import(ownedCells, rootCells), Tpetra::INSERT);

  FieldSet fields;
  if (!root) return fields;
  // Component `field` of every node from column j of a rank-0 dof vector.
  auto nodal = [&](const MultiVector& dofs, size_t j, std::initializer_list<int> components, Field f) {
    auto d = dofs.getLocalViewHost(Tpetra::Access::ReadOnly);
    f.components = static_cast<int>(components.size());
    f.values.resize(f.components * numNodes);
    for (GO n = 0; n < numNodes; ++n) {
      int i = 0;
      for (int c : components) f.values[f.components * n + i++] = d(dofMap.globalDof(n, c), j);
    }
    return f;
  };
  fields.nodal = {nodal(*allDofs, 0, {kUx, kUy}, {"velocity", 2, {}}), nodal(*allDofs, 0, {kP}, {"pressure", 1, {}})};
  if (const int t = dofMap.fields().componentOf(kTemperatureField); t >= 0)
    fields.nodal.push_back(nodal(*allDofs, 0, {t}, {"temperature", 1, {}}));
  if (const int e = dofMap.fields().componentOf(kStrainField); e >= 0)
    fields.nodal.push_back(nodal(*allDofs, 0, {e}, {"strain", 1, {}}));
  if (!walls.empty()) {
    // 1 active, 0 free, -1 not on a contact wall
    Field status{"contact_status", 1, std::vector<double>(numNodes, -1.0)};
    for (const ContactWall& wall : walls)
      for (int k = 0; k < wall.numNodes(); ++k) status.values[wall.curve().nodes[k]] = wall.isActive(k) ? 1.0 : 0.0;
    fields.nodal.push_back(std::move(status));
  }
  // du/dh (also as du_t/dh, du_n/dh in the boundary CSVs) and dp/dh per parameter, by DDM
  // and, when the check ran, by central differences (suffix _fd).
  for (const auto& [dofs, suffix] : {std::make_pair(sensitivityDofs, ""), std::make_pair(differenceDofs, "_fd")}) {
    if (!dofs) continue;
    const auto& parameters = sensitivity.parameters();
    for (size_t j = 0; j < parameters.size(); ++j) {
      const std::string h = parameters[j].symbol + suffix;
      fields.nodal.push_back(nodal(*dofs, j, {kUx, kUy}, {"du_d" + h, 2, {}, "du_t_d" + h, "du_n_d" + h}));
      fields.nodal.push_back(nodal(*dofs, j, {kP}, {"dp_d" + h, 1, {}}));
    }
  }
  auto c = allCells.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& names = cellFieldNames();
  for (const auto& wanted : cellFields)
    for (size_t j = 0; j < names.size(); ++j)
      if (wanted == names[j]) {
        Field f{names[j], 1, std::vector<double>(numCells)};
        for (GO k = 0; k < numCells; ++k) f.values[k] = c(k, j);
        fields.cell.push_back(std::move(f));
      }
  return fields;
}

}  // namespace flowform
