// Carrying a state from one mesh to another (mesh/PointLocator, discretization/SolutionTransfer,
// ContactWall::takeStatusesFrom), what the two-level error estimate and the adaptive loop
// start their solves from:
// - a linear field is reproduced exactly (to round-off, 1e-12) at any point inside a distorted
//   mesh, by P1 triangles and by Q1 quadrilaterals (both contain the linear functions);
// - a point just outside the mesh is clamped to the nearest cell and flagged;
// - a P1/Q1 field of arbitrary nodal values on a coarse mesh, interpolated onto the uniformly
//   refined mesh, keeps its values at the coarse nodes and takes the edge averages at the
//   midpoints (nested spaces: exact), on 1 and 2 ranks (replicate is collective);
// - the moved shape of a coarse mesh carried to its refinement as made (carryShape): the refined
//   nodes land on the moved coarse nodes and the midpoints of the moved edges;
// - wall statuses carried to a refined wall: coarse nodes keep theirs, a midpoint is active
//   only between two active nodes, or, given the velocities, inside a zone limit when it
//   penetrates.
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>

#include "StructuredMesh.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/discretization/SolutionTransfer.hpp"
#include "flowform/mesh/PointLocator.hpp"

namespace {

using namespace flowform;

/// A smooth distortion of [0, 2] × [0, 1] that keeps the boundary lines straight.
std::array<double, 2> distort(double x, double y) {
  return {x + 0.05 * std::sin(M_PI * x) * std::sin(M_PI * y), y + 0.04 * std::sin(M_PI * x / 2) * std::sin(M_PI * y)};
}

Mesh distorted(CellType type, int nx, int ny) {
  return test::structuredMesh(type, nx, ny, "distorted", [&](int i, int j) {
    return distort(2.0 * i / nx, 1.0 * j / ny);
  });
}

double linear(const std::array<double, 2>& p) { return 1.0 + 2.0 * p[0] - 3.0 * p[1]; }

/// A nodal value with no pattern (not a polynomial).
double scrambled(GO node, int field) { return std::sin(1.7 * node + 0.3 * field) + 0.1 * field; }

TEUCHOS_UNIT_TEST(Transfer, LinearFieldsAreReproducedInsideAndClampedOutside) {
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    const Mesh mesh = distorted(type, 7, 5);
    const PointLocator locator(mesh);
    const int npc = nodesPerCell(type);
    for (int k = 0; k < 200; ++k) {
      // Points spread over the (straight-sided) domain [0, 2] × [0, 1].
      const std::array<double, 2> p{2.0 * std::fmod(0.618034 * k + 0.05, 1.0), std::fmod(0.414214 * k + 0.02, 1.0)};
      const CellPoint at = locator.locate(p);
      TEST_ASSERT(at.inside);
      double v = 0.0, sum = 0.0;
      for (int a = 0; a < npc; ++a) {
        v += at.weights[a] * linear(mesh.coords[mesh.cell(at.cell)[a]]);
        sum += at.weights[a];
      }
      TEST_FLOATING_EQUALITY(sum, 1.0, 1e-12);
      TEST_FLOATING_EQUALITY(v, linear(p), 1e-12);
    }
    const CellPoint outside = locator.locate({-1e-3, 0.5});
    TEST_ASSERT(!outside.inside);
    TEST_ASSERT(outside.cell >= 0);
    for (int a = 0; a < npc; ++a) TEST_ASSERT(outside.weights[a] >= 0.0 && outside.weights[a] <= 1.0);
  }
}

TEUCHOS_UNIT_TEST(Transfer, NestedRefinementCarriesAFieldExactly) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    // The refined structured mesh is nested in the coarse one: fine node (2i, 2j) is coarse
    // node (i, j); straight cells are split at their edge midpoints (same diagonals for
    // triangles: fine cell (2i.., 2j..) has the coarse cell's diagonal when (i + j) and
    // (2i + 2j) have the same parity, which holds for the diagonal's own pair of fine cells).
    const int nx = 4, ny = 2;
    const Mesh coarse = test::structuredMesh(type, nx, ny, "coarse", [&](int i, int j) {
      return std::array<double, 2>{0.5 * i, 0.5 * j};
    });
    const Mesh fine = test::structuredMesh(type, 2 * nx, 2 * ny, "fine", [&](int i, int j) {
      return std::array<double, 2>{0.25 * i, 0.25 * j};
    });
    const DofMap coarseDofs(coarse, comm, {}), fineDofs(fine, comm, {});
    Vector x(coarseDofs.ownedMap()), y(fineDofs.ownedMap());
    {
      auto v = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (LO n = 0; n < coarseDofs.numOwnedNodes(); ++n)
        for (int f = 0; f < 3; ++f) v(coarseDofs.dof(n, f), 0) = scrambled(coarseDofs.overlapNodes()[n], f);
    }
    const std::vector<double> all = replicate(x, coarseDofs);
    TEST_EQUALITY(static_cast<GO>(all.size()), coarseDofs.numGlobalDofs());
    interpolate(coarse, coarseDofs, all, fine, fineDofs, y);
    const auto v = y.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO n = 0; n < fineDofs.numOwnedNodes(); ++n) {
      const GO node = fineDofs.overlapNodes()[n];
      const int i = static_cast<int>(node % (2 * nx + 1)), j = static_cast<int>(node / (2 * nx + 1));
      auto coarseNode = [&](int ci, int cj) { return static_cast<GO>(cj * (nx + 1) + ci); };
      for (int f = 0; f < 3; ++f) {
        double expected;
        if (i % 2 == 0 && j % 2 == 0)
          expected = scrambled(coarseNode(i / 2, j / 2), f);
        else if (j % 2 == 0)
          expected = 0.5 * (scrambled(coarseNode(i / 2, j / 2), f) + scrambled(coarseNode(i / 2 + 1, j / 2), f));
        else if (i % 2 == 0)
          expected = 0.5 * (scrambled(coarseNode(i / 2, j / 2), f) + scrambled(coarseNode(i / 2, j / 2 + 1), f));
        else if (type == CellType::Quadrilateral4)  // the cell centre: the mean of the four corners
          expected = 0.25 * (scrambled(coarseNode(i / 2, j / 2), f) + scrambled(coarseNode(i / 2 + 1, j / 2), f) +
                             scrambled(coarseNode(i / 2 + 1, j / 2 + 1), f) + scrambled(coarseNode(i / 2, j / 2 + 1), f));
        else {  // the midpoint of the coarse cell's diagonal
          const bool rising = (i / 2 + j / 2) % 2 == 0;  // diagonal a–c, else b–d (StructuredMesh.hpp)
          expected = rising ? 0.5 * (scrambled(coarseNode(i / 2, j / 2), f) + scrambled(coarseNode(i / 2 + 1, j / 2 + 1), f))
                            : 0.5 * (scrambled(coarseNode(i / 2 + 1, j / 2), f) + scrambled(coarseNode(i / 2, j / 2 + 1), f));
        }
        TEST_FLOATING_EQUALITY(v(fineDofs.dof(n, f), 0), expected, 1e-12);
      }
    }
  }
}

TEUCHOS_UNIT_TEST(Transfer, ARefinedMeshTakesTheMovedShape) {
  // The coarse mesh as made, the same mesh after a free-surface loop moved its nodes (a smooth
  // non-affine map), and the refined mesh as made: carryShape puts the refined nodes at the
  // moved coarse nodes and at the midpoints of the moved coarse edges, so the refined free
  // surfaces lie on the moved ones.
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    const int nx = 4, ny = 2;
    auto grid = [](int i, int j, double size) { return std::array<double, 2>{size * i, size * j}; };
    const Mesh made = test::structuredMesh(type, nx, ny, "made", [&](int i, int j) { return grid(i, j, 0.5); });
    Mesh moved = made;
    for (auto& xy : moved.coords) xy = {xy[0] + 0.1 * xy[1] * xy[1], 1.3 * xy[1] + 0.05 * std::sin(xy[0])};
    const Mesh fine = test::structuredMesh(type, 2 * nx, 2 * ny, "fine", [&](int i, int j) { return grid(i, j, 0.25); });
    const std::vector<std::array<double, 2>> carried = carryShape(made, moved, fine);
    TEST_EQUALITY(carried.size(), fine.coords.size());
    auto coarse = [&](int ci, int cj) { return moved.coords[cj * (nx + 1) + ci]; };
    for (int j = 0; j <= 2 * ny; ++j)
      for (int i = 0; i <= 2 * nx; ++i) {
        if (i % 2 == 1 && j % 2 == 1) continue;  // cell interiors: the diagonal's or the centre's
        const std::array<double, 2> a = coarse(i / 2, j / 2);
        const std::array<double, 2> b = coarse((i + 1) / 2, (j + 1) / 2);
        for (int d = 0; d < 2; ++d)
          TEST_FLOATING_EQUALITY(carried[j * (2 * nx + 1) + i][d] + 1.0, 0.5 * (a[d] + b[d]) + 1.0, 1e-12);
      }
  }
}

TEUCHOS_UNIT_TEST(Transfer, WallStatusesCarryToARefinedWall) {
  const Mesh coarse = test::structuredMesh(CellType::Triangle3, 4, 2, "coarse", [](int i, int j) {
    return std::array<double, 2>{0.5 * i, 0.5 * j};
  });
  const Mesh fine = test::structuredMesh(CellType::Triangle3, 8, 4, "fine", [](int i, int j) {
    return std::array<double, 2>{0.25 * i, 0.25 * j};
  });
  Teuchos::ParameterList params;
  params.set("Friction Law", "Coulomb");
  params.set("Friction Coefficient", 0.1);
  ContactWall from("top", params, coarse, Geometry::PlaneStrain);
  ContactWall to("top", params, fine, Geometry::PlaneStrain);
  // The top curve runs from x = 2 to x = 0 (material on its left).
  TEST_EQUALITY(from.numNodes(), 5);
  const bool statuses[5] = {true, true, false, false, true};
  for (int k = 0; k < 5; ++k)
    if (from.isActive(k) != statuses[k]) from.setActive(k, statuses[k]);
  to.takeStatusesFrom(from);
  TEST_EQUALITY(to.numNodes(), 9);
  for (int k = 0; k < 9; ++k) {
    const bool expected = k % 2 == 0 ? statuses[k / 2] : statuses[k / 2] && statuses[k / 2 + 1];
    TEST_EQUALITY(to.isActive(k), expected);
    TEST_EQUALITY(to.changes(k), 0);
  }
  // With the carried-over velocities, a node inside a zone limit (k = 3: between active and
  // free; k = 7: between free and active) is active iff it moves into the tool (u·n > 1e-4,
  // n = +y on the top wall); k = 5 lies between two free nodes and stays free however it moves.
  std::vector<std::array<double, 2>> u(9, {0.0, 0.0});
  u[3] = {0.3, 1e-3};
  u[5] = {0.0, 1.0};
  u[7] = {0.0, -1.0};
  to.takeStatusesFrom(from, &u, 1e-4);
  for (int k = 0; k < 9; ++k) {
    const bool expected = k == 3 ? true : k == 7 ? false : k % 2 == 0 ? statuses[k / 2] : statuses[k / 2] && statuses[k / 2 + 1];
    TEST_EQUALITY(to.isActive(k), expected);
  }
  u[3] = {0.3, 1e-5};  // below the tolerance: free
  to.takeStatusesFrom(from, &u, 1e-4);
  TEST_ASSERT(!to.isActive(3));
}

}  // namespace
