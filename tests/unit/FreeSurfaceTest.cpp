// The pieces of the free-surface update (docs/theory.md §3), without a flow solve:
// - the mesh motion reproduces an affine boundary displacement exactly inside a uniform mesh
//   (the harmonic extension of an affine field is that field, and with equal cell areas the
//   1/|K| stiffening is a constant factor), triangles and quadrilaterals; nodes of boundary
//   groups that are not moved stay;
// - the spine update at a uniform velocity u = (1, s) makes a flat surface the straight line of
//   slope s from its fixed start in one step (every segment parallel to u), reports the flow
//   angle of the flat surface (s / √(1 + s²)), drags the group at the surface's end in proportion
//   to its arc length, and at the next step finds the flow angle and the move zero;
// - the arc-length update at a uniform velocity makes the surface the straight line along u with
//   its segment lengths kept in one step, and the group at its end follows the end's move in
//   proportion to its arc length;
// - a group dragged by two surfaces' ends (a chip's outlet) moves each of its nodes by the sum of
//   the two drags, and each end keeps its own move (each end is in the other's drag list, with
//   fraction 0);
// - a Start Group that shares no end of the surface is an input error naming it;
// - the loop halves a move that would invert a cell and goes on;
// - a second loop's report (a released chip outlet) takes in the first's: counts and seconds
//   add, the history is both loops', each entry tagged with its loop.
// Round-off bounds: 1e-12 (direct solve of a 100-node system, coordinates of order 1).
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>
#include <limits>

#include "StructuredMesh.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/freesurface/FreeSurfaceLoop.hpp"
#include "flowform/freesurface/FreeSurface.hpp"
#include "flowform/freesurface/MeshMotion.hpp"

namespace {

using namespace flowform;

Mesh unitMesh(CellType type, int nx, int ny) {
  return test::structuredMesh(type, nx, ny, "structured", [&](int i, int j) {
    return std::array<double, 2>{2.0 * i / nx, 1.0 * j / ny};
  });
}

std::array<double, 2> affine(const std::array<double, 2>& x) {
  return {0.05 * x[0] - 0.03 * x[1] + 0.01, 0.02 * x[0] + 0.07 * x[1] - 0.02};
}

TEUCHOS_UNIT_TEST(FreeSurface, MeshMotionReproducesAffineDisplacement) {
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    const Mesh mesh = unitMesh(type, 8, 6);
    std::vector<std::array<double, 2>> d(mesh.numNodes(), {0.0, 0.0});
    std::vector<char> prescribed(mesh.numNodes(), 0);
    for (const BoundaryGroup& g : mesh.boundaries)
      for (const auto& e : g.edges)
        for (GO n : e) {
          d[n] = affine(mesh.coords[n]);
          prescribed[n] = 1;
        }
    const auto moved = extendBoundaryDisplacement(mesh, d, prescribed);
    double worst = 0.0;
    for (GO n = 0; n < mesh.numNodes(); ++n) {
      const auto expected = affine(mesh.coords[n]);
      for (int c = 0; c < 2; ++c) worst = std::max(worst, std::abs(moved[n][c] - mesh.coords[n][c] - expected[c]));
    }
    TEST_COMPARE(worst, <, 1e-12);
  }
}

TEUCHOS_UNIT_TEST(FreeSurface, UnmovedBoundaryStaysAndInteriorFollows) {
  const Mesh mesh = unitMesh(CellType::Triangle3, 8, 6);
  std::vector<std::array<double, 2>> d(mesh.numNodes(), {0.0, 0.0});
  std::vector<char> prescribed(mesh.numNodes(), 0);
  for (const auto& e : mesh.boundary("top").edges)
    for (GO n : e) {
      d[n] = {0.0, 0.1};
      prescribed[n] = 1;
    }
  const auto moved = extendBoundaryDisplacement(mesh, d, prescribed);
  for (const char* name : {"bottom", "left", "right"})
    for (const auto& e : mesh.boundary(name).edges)
      for (GO n : e)
        if (!prescribed[n]) TEST_COMPARE(std::hypot(moved[n][0] - mesh.coords[n][0], moved[n][1] - mesh.coords[n][1]), ==, 0.0);
  // An interior node half-way up moves up, by less than the top.
  const GO middle = 3 * 9 + 4;
  TEST_COMPARE(moved[middle][1] - mesh.coords[middle][1], >, 0.0);
  TEST_COMPARE(moved[middle][1] - mesh.coords[middle][1], <, 0.1);
}

/// A "Free Surface" on top from its end at "left"; the replicated dof vector of u = (1, s), p = 0.
struct SpineCase {
  Mesh mesh = unitMesh(CellType::Triangle3, 8, 4);
  Teuchos::ParameterList bc;
  std::unique_ptr<DofMap> dofMap;
  std::vector<double> u;
  explicit SpineCase(double slope) {
    bc.sublist("top").set("Type", "Free Surface");
    bc.sublist("top").set("Start Group", "left");
    dofMap = std::make_unique<DofMap>(mesh, Teuchos::DefaultComm<int>::getComm());
    u.assign(dofMap->numGlobalDofs(), 0.0);
    for (GO n = 0; n < mesh.numNodes(); ++n) {
      u[dofMap->globalDof(n, kUx)] = 1.0;
      u[dofMap->globalDof(n, kUy)] = slope;
    }
  }
};

/// Moved as `step` says, the next update finds the surface a streamline: nothing to move.
bool streamlineAfter(const FreeSurfaces& surfaces, const SpineCase& c, const FreeSurfaceStep& step) {
  Mesh moved = c.mesh;
  moved.setCoordinates(extendBoundaryDisplacement(c.mesh, step.displacement, step.prescribed));
  const FreeSurfaceStep next = surfaces.step(moved, *c.dofMap, c.u, {}, Geometry::PlaneStrain, 1e-9);
  return next.maxFlowAngle < 1e-12 && next.maxMove < 1e-12;
}

TEUCHOS_UNIT_TEST(FreeSurface, SpineUpdateFollowsUniformFlow) {
  const double slope = 0.1;
  SpineCase c(slope);
  const FreeSurfaces surfaces(c.bc, c.mesh, {});
  TEST_EQUALITY(surfaces.surfaces().size(), 1u);
  const FreeSurfaceStep step = surfaces.step(c.mesh, *c.dofMap, c.u, {}, Geometry::PlaneStrain, 1e-9);
  TEST_ASSERT(step.failure.empty());
  TEST_FLOATING_EQUALITY(step.maxFlowAngle, slope / std::sqrt(1.0 + slope * slope), 1e-12);
  // The surface's nodes (top, y = 1) go to y = 1 + slope x; the right side's nodes in proportion.
  for (const auto& e : c.mesh.boundary("top").edges)
    for (GO n : e) TEST_FLOATING_EQUALITY(step.displacement[n][1] + 1.0, 1.0 + slope * c.mesh.coords[n][0], 1e-12);
  for (const auto& e : c.mesh.boundary("right").edges)
    for (GO n : e) TEST_FLOATING_EQUALITY(step.displacement[n][1] + 1.0, 1.0 + 2.0 * slope * c.mesh.coords[n][1], 1e-12);
  TEST_FLOATING_EQUALITY(step.maxMove, 2.0 * slope, 1e-12);

  TEST_ASSERT(streamlineAfter(surfaces, c, step));
}

TEUCHOS_UNIT_TEST(FreeSurface, ArcLengthUpdateTurnsWithUniformFlow) {
  // Arc length: the flat top (from x = 0) becomes the straight line along u = (1, s), every
  // segment's length scaled by the one factor λ = √(1 + s²) that keeps its end on the line of the
  // right side (x = 2, as made); the right side, dragged from its fixed bottom end, follows the end.
  const double slope = 0.5;
  SpineCase c(slope);
  c.bc.sublist("top").set("Update", "Arc Length");
  const FreeSurfaces surfaces(c.bc, c.mesh, {});
  const FreeSurfaceStep step = surfaces.step(c.mesh, *c.dofMap, c.u, {}, Geometry::PlaneStrain, 1e-9);
  TEST_ASSERT(step.failure.empty());
  for (const auto& e : c.mesh.boundary("top").edges)
    for (GO n : e) {
      const double s0 = c.mesh.coords[n][0];  // arc length from the start (0, 1) as made
      TEST_FLOATING_EQUALITY(c.mesh.coords[n][0] + step.displacement[n][0] + 1.0, s0 + 1.0, 1e-12);
      TEST_FLOATING_EQUALITY(c.mesh.coords[n][1] + step.displacement[n][1], 1.0 + slope * s0, 1e-12);
    }
  const GO end = 4 * 9 + 8;  // (2, 1)
  for (const auto& e : c.mesh.boundary("right").edges)
    for (GO n : e) {
      const double f = c.mesh.coords[n][1];
      TEST_FLOATING_EQUALITY(step.displacement[n][0] + 1.0, f * step.displacement[end][0] + 1.0, 1e-12);
      TEST_FLOATING_EQUALITY(step.displacement[n][1] + 1.0, f * step.displacement[end][1] + 1.0, 1e-12);
    }
  TEST_ASSERT(streamlineAfter(surfaces, c, step));
}

TEUCHOS_UNIT_TEST(FreeSurface, TwoEndsDragOneGroupAndKeepTheirMoves) {
  // Nodes 0 and 1 end two surfaces; node 2 lies on the group between them at a quarter of its
  // length from node 0. Surface 0's drags (its end: move 0) list node 2 (fraction 3/4) and node 1
  // (fraction 0); surface 1's list node 2 (1/4) and node 0 (0).
  FreeSurfaceStep step;
  step.displacement.assign(3, {0.0, 0.0});
  step.prescribed.assign(3, 0);
  step.moves.push_back({0, {0.0, 1.0}, {0.3, -0.1}, std::numeric_limits<double>::infinity(), true, true});
  step.moves.push_back({1, {0.0, 1.0}, {-0.2, 0.4}, std::numeric_limits<double>::infinity(), true, true});
  step.drags = {{2, 0.75, 0}, {1, 0.0, 0}, {2, 0.25, 1}, {0, 0.0, 1}};
  step.relax(1.0);
  TEST_FLOATING_EQUALITY(step.displacement[0][0], 0.3, 1e-14);
  TEST_FLOATING_EQUALITY(step.displacement[0][1], -0.1, 1e-14);
  TEST_FLOATING_EQUALITY(step.displacement[1][0], -0.2, 1e-14);
  TEST_FLOATING_EQUALITY(step.displacement[1][1], 0.4, 1e-14);
  TEST_FLOATING_EQUALITY(step.displacement[2][0], 0.75 * 0.3 + 0.25 * -0.2, 1e-14);
  TEST_FLOATING_EQUALITY(step.displacement[2][1], 0.75 * -0.1 + 0.25 * 0.4, 1e-14);
  TEST_ASSERT(step.prescribed[0] && step.prescribed[1] && step.prescribed[2]);
}

TEUCHOS_UNIT_TEST(FreeSurface, StartGroupMustShareAnEnd) {
  SpineCase c(0.0);
  c.bc.sublist("top").set("Start Group", "bottom");
  TEST_THROW(FreeSurfaces(c.bc, c.mesh, {}), InputError);
  c.bc.sublist("top").set("Start Group", "nowhere");
  TEST_THROW(FreeSurfaces(c.bc, c.mesh, {}), InputError);
}

}  // namespace

namespace {

using namespace flowform;

/// The loop on the structured case with a uniform velocity whose streamline from the top-left
/// corner leaves through the bottom: the plain update would invert cells.
FreeSurfaceReport loopAt(double slope, int maxIterations) {
  SpineCase c(slope);
  const FreeSurfaces surfaces(c.bc, c.mesh, {});
  Teuchos::ParameterList settings = *FreeSurfaceLoop::validParameters();
  settings.set("Maximum Iterations", maxIterations);
  settings.set("Relaxation", "None");
  FreeSurfaceLoop::Hooks hooks;
  hooks.velocities = [&] { return c.u; };
  hooks.moveNodes = [&](const std::vector<std::array<double, 2>>& x) { c.mesh.setCoordinates(x); };
  hooks.resolve = [](int&, int&, std::string&) { return true; };
  hooks.release = [](int, int) {};
  return FreeSurfaceLoop(surfaces, settings).run(c.mesh, *c.dofMap, {}, Geometry::PlaneStrain, hooks);
}

}  // namespace

// A move that would invert a cell is halved until it does not (the top at slope −0.75 would cross
// the bottom at x = 2: a quarter of it fits), and the loop goes on; one that cannot be made valid
// in kMaxHalvings halvings ends the loop with the reason. Either way the mesh stays valid.
TEUCHOS_UNIT_TEST(FreeSurface, LoopHalvesMovesThatInvert) {
  const FreeSurfaceReport halved = loopAt(-0.75, 1);
  TEST_ASSERT(!halved.converged);
  TEST_EQUALITY(halved.iterations, 1);
  TEST_ASSERT(halved.message.find("did not converge") != std::string::npos);
  // Slope −100: even 2⁻⁶ of the move (the top's end 3.1 lower) crosses the bottom.
  const FreeSurfaceReport impossible = loopAt(-100.0, 5);
  TEST_ASSERT(!impossible.converged);
  TEST_EQUALITY(impossible.iterations, 0);
  TEST_ASSERT(impossible.message.find("invert") != std::string::npos);
}

// Two loops of one run (the first ends when the surfaces converge with the outlet held, the
// second after its release): the report of the second takes in the first's.
TEUCHOS_UNIT_TEST(FreeSurface, SecondLoopReportTakesInTheFirst) {
  FreeSurfaceReport first = loopAt(0.1, 3), second = loopAt(0.2, 2);
  TEST_EQUALITY(first.history.size(), static_cast<size_t>(first.iterations));
  const int iterations = first.iterations + second.iterations;
  const double seconds = first.seconds + second.seconds;
  const bool secondConverged = second.converged;
  const double secondAngle = second.flowAngle;
  first.newtonIterations = 7;
  first.contactChanges = 2;
  second.newtonIterations = 5;
  second.contactChanges = 1;
  second.continueFrom(first);
  TEST_EQUALITY(second.iterations, iterations);
  TEST_EQUALITY(second.newtonIterations, 12);
  TEST_EQUALITY(second.contactChanges, 3);
  TEST_FLOATING_EQUALITY(second.seconds, seconds, 1e-14);
  TEST_EQUALITY(second.converged, secondConverged);
  TEST_EQUALITY(second.flowAngle, secondAngle);
  TEST_EQUALITY(second.history.size(), static_cast<size_t>(iterations));
  for (size_t k = 0; k < second.history.size(); ++k)
    TEST_EQUALITY(second.history[k]["loop"].get<int>(), k < first.history.size() ? 0 : 1);
  // A third loop continues the numbering.
  FreeSurfaceReport third = loopAt(0.3, 1);
  third.continueFrom(second);
  TEST_EQUALITY(third.history.back()["loop"].get<int>(), 2);
  TEST_EQUALITY(third.history.front()["loop"].get<int>(), 0);
}
