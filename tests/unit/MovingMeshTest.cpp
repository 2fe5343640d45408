// A mesh whose nodes move (Mesh::setCoordinates) and the pieces that cache geometry
// (BoundaryConditions: symmetry directions; ContactWall: normals, segment lengths, corners)
// refreshed: the residual must equal, to round-off, that of the same problem built from
// scratch on a mesh at the moved positions — plane and axisymmetric, triangles and
// quadrilaterals, with a symmetry line that turns, a frictional contact wall on a curved
// boundary and a traction. Same dof numbering and the same arithmetic on both sides, so
// the difference is expected to be exactly zero; 1e-14 relative allows for nothing more
// than a reordering of sums. A move that inverts a cell is an InputError and leaves the
// mesh as it was. On 1 and 2 ranks.
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>
#include <memory>

#include "StructuredMesh.hpp"
#include "flowform/assembly/Assembler.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/contact/ToolCorners.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/discretization/DofMap.hpp"

namespace {

using namespace flowform;
using Teuchos::ParameterList;

/// Node (i, j) of the undeformed 6 × 4 mesh on [0.2, 2.2] × [0, 1].
std::array<double, 2> reference(int i, int j) { return {0.2 + i / 3.0, j / 4.0}; }

/// The motion: a shear and a turn (the symmetry line "bottom" turns, stays straight), plus
/// a bump that vanishes on the bottom only (the top wall and the sides become curved).
std::array<double, 2> moved(const std::array<double, 2>& p) {
  const double x = p[0], y = p[1];
  const double bump = 0.04 * std::sin(M_PI * (x - 0.2) / 2.0) * y;
  return {1.0 * x + 0.15 * y + bump, 0.1 * x + 1.05 * y + bump};
}

ParameterList conditions() {
  ParameterList bc("Boundary Conditions");
  bc.sublist("bottom").set("Type", "Symmetry");
  bc.sublist("left").set("Type", "Velocity");
  bc.sublist("left").set("Velocity X", 1.0);
  bc.sublist("right").set("Type", "Traction");
  bc.sublist("right").set("Traction X", -0.3);
  ParameterList& wall = bc.sublist("top");
  wall.set("Type", "Contact Wall");
  wall.set("Friction Law", "Coulomb");
  wall.set("Friction Coefficient", 0.2);
  return bc;
}

/// A problem on `mesh` (kept by reference: it may move).
struct Problem {
  Mesh mesh;
  std::vector<ContactWall> walls;
  std::unique_ptr<DofMap> dofMap;
  std::unique_ptr<BoundaryConditions> bcs;
  std::unique_ptr<Assembler> assembler;

  Problem(Mesh m, Geometry geometry, const Teuchos::RCP<const Comm>& comm) : mesh(std::move(m)) {
    const ParameterList bc = conditions();
    walls = contactWallsFromCase(bc, mesh, geometry);
    dofMap = std::make_unique<DofMap>(mesh, comm, walls[0].couplings());
    bcs = std::make_unique<BoundaryConditions>(bc, mesh, *dofMap);
    assembler = std::make_unique<Assembler>(mesh, *dofMap, *bcs);
    FlowPhysics physics;
    physics.kernel.geometry = geometry;
    physics.kernel.beta = 0.1;
    physics.material = flowform::powerLaw(0.5, 1.0, 5.0, 1e-3);
    assembler->setPhysics(physics);
    assembler->setContactWalls(&walls);
  }
  void moveTo(const std::vector<std::array<double, 2>>& coords) {
    mesh.setCoordinates(coords);
    for (ContactWall& w : walls) w.refreshGeometry(mesh);
    markConvexToolCorners(walls);
    bcs->refreshGeometry(mesh);
  }
  /// F at a smooth state of the (current) node positions, and at the same dof values.
  Teuchos::RCP<Vector> residualAt(const Vector& x) const {
    auto f = Teuchos::rcp(new Vector(dofMap->ownedMap()));
    assembler->residual(x, *f);
    return f;
  }
  Teuchos::RCP<Vector> state() const {
    auto x = Teuchos::rcp(new Vector(dofMap->ownedMap()));
    auto v = x->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO n = 0; n < dofMap->numOwnedNodes(); ++n) {
      const auto& p = mesh.coords[dofMap->overlapNodes()[n]];
      v(dofMap->dof(n, kUx), 0) = 1.0 + 0.3 * p[1] * p[1];
      v(dofMap->dof(n, kUy), 0) = 0.2 * p[0] * p[1] - 0.1;  // into the top wall: active, compressed
      v(dofMap->dof(n, kP), 0) = 2.0 - p[0];
    }
    return x;
  }
};

TEUCHOS_UNIT_TEST(MovingMesh, ResidualEqualsAFreshMeshAtTheMovedNodes) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
      const Mesh original = test::structuredMesh(type, 6, 4, "moving mesh", reference);
      std::vector<std::array<double, 2>> target;
      for (const auto& p : original.coords) target.push_back(moved(p));
      const Mesh atTarget = test::structuredMesh(type, 6, 4, "moving mesh",
                                                 [](int i, int j) { return moved(reference(i, j)); });

      Problem movedProblem(original, geometry, comm), fresh(atTarget, geometry, comm);
      const auto x = fresh.state();  // the same dof values on both: same numbering
      const auto before = movedProblem.residualAt(*x);
      movedProblem.moveTo(target);
      const auto after = movedProblem.residualAt(*x);
      const auto expected = fresh.residualAt(*x);

      const double scale = expected->normInf();
      before->update(-1.0, *expected, 1.0);
      after->update(-1.0, *expected, 1.0);
      out << cellTypeName(type) << (geometry == Geometry::Axisymmetric ? " axisymmetric" : " plane")
          << ": |F| = " << scale << ", moved vs fresh " << after->normInf() << ", unmoved vs fresh "
          << before->normInf() << "\n";
      TEST_COMPARE(scale, >, 0.0);
      TEST_COMPARE(after->normInf(), <=, 1e-14 * scale);
      TEST_COMPARE(before->normInf(), >, 1e-2 * scale);  // the motion matters: the check can fail
    }
}

TEUCHOS_UNIT_TEST(MovingMesh, InvertingMoveIsRefusedAndLeavesTheMesh) {
  Mesh mesh = test::structuredMesh(CellType::Quadrilateral4, 3, 2, "inverting move", reference);
  const auto coords = mesh.coords;
  auto bad = coords;
  bad[5][0] += 1.0;  // an interior node pushed past its neighbour: a cell turns inside out
  TEST_THROW(mesh.setCoordinates(bad), InputError);
  TEST_ASSERT(mesh.coords == coords);
}

}  // namespace
