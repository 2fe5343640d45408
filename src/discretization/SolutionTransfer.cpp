#include "flowform/discretization/SolutionTransfer.hpp"

#include "flowform/mesh/PointLocator.hpp"

namespace flowform {

std::vector<double> replicate(const Vector& x, const DofMap& dofMap) {
  const GO n = dofMap.numGlobalDofs();
  auto all = Tpetra::createLocalMapWithNode<LO, GO, Node>(n, dofMap.comm());  // every dof on every rank
  Vector local(all);
  local.doImport(x, Import(dofMap.ownedMap(), all), Tpetra::INSERT);
  const auto v = local.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> values(n);
  for (GO i = 0; i < n; ++i) values[i] = v(all->getLocalElement(i), 0);
  return values;
}

void interpolate(const Mesh& fromMesh, const DofMap& fromDofs, const std::vector<double>& fromValues,
                 const Mesh& toMesh, const DofMap& toDofs, Vector& toOwned) {
  const PointLocator locator(fromMesh);
  const int npc = nodesPerCell(fromMesh.cellType);
  auto out = toOwned.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO n = 0; n < toDofs.numOwnedNodes(); ++n) {
    const GO node = toDofs.overlapNodes()[n];
    const CellPoint at = locator.locate(toMesh.coords[node]);
    const GO* cell = fromMesh.cell(at.cell);
    for (int f = 0; f < toDofs.numFields(node); ++f) {
      double v = 0.0;
      for (int a = 0; a < npc; ++a) v += at.weights[a] * fromValues[fromDofs.globalDof(cell[a], f)];
      out(toDofs.dof(n, f), 0) = v;
    }
  }
}

std::vector<std::array<double, 2>> carryShape(const Mesh& fromMade, const Mesh& fromMoved, const Mesh& toMesh) {
  const PointLocator locator(fromMade);
  const int npc = nodesPerCell(fromMade.cellType);
  std::vector<std::array<double, 2>> moved(toMesh.coords.size());
  for (std::size_t n = 0; n < moved.size(); ++n) {
    const CellPoint at = locator.locate(toMesh.coords[n]);
    const GO* cell = fromMade.cell(at.cell);
    moved[n] = {0.0, 0.0};
    for (int a = 0; a < npc; ++a)
      for (int d = 0; d < 2; ++d) moved[n][d] += at.weights[a] * fromMoved.coords[cell[a]][d];
  }
  return moved;
}

}  // namespace flowform
