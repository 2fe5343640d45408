// Mesh input (MeshReader), boundary curves and the cell partition. Runs on 1 and 2 ranks:
// on 2 ranks every rank must get the same mesh, and every rank must throw the same
// InputError when rank 0 fails to read (no rank left waiting in a broadcast).
//
// tests/data/unit_square_*.msh: the unit square, 3 x 3 nodes (gmsh tags 1-4 corners,
// 5-8 midsides of bottom/right/top/left, 9 the centre, 10 an unused geometry point at
// (2,2)); reader ids are tag - 1. Physical curves bottom/right/top/left (bottom's edges
// listed out of order and against the curve), physical surface "body". Cell tags from 101.
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <algorithm>
#include <cmath>
#include <string>

#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/mesh/MeshReader.hpp"
#include "flowform/mesh/Partition.hpp"

namespace {

using flowform::BoundaryCurve;
using flowform::BoundaryGroup;
using flowform::CellType;
using flowform::GO;
using flowform::InputError;
using flowform::Mesh;

Teuchos::ParameterList meshList(const std::string& file, const std::string& type = "Triangle",
                                int refinements = 0) {
  Teuchos::ParameterList p("Mesh");
  p.set("File", file);
  p.set("Element Type", type);
  p.set("Uniform Refinements", refinements);
  return p;
}

Mesh readData(const std::string& file, const std::string& type = "Triangle", int refinements = 0) {
  return flowform::readMesh(meshList(file, type, refinements), FLOWFORM_TEST_DATA,
                            *Teuchos::DefaultComm<int>::getComm());
}

Mesh readChannel(const std::string& type, int refinements, double n = 0) {
  Teuchos::ParameterList p = meshList("channel.geo", type, refinements);
  if (n > 0) p.sublist("Geo Parameters").set("N", n);
  return flowform::readMesh(p, FLOWFORM_MESH_DIR, *Teuchos::DefaultComm<int>::getComm());
}

/// The InputError message `f` throws, or a marker that none was thrown.
template <class F>
std::string inputError(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no InputError thrown>";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

double signedArea(const Mesh& mesh, GO c) {
  const int npc = flowform::nodesPerCell(mesh.cellType);
  double twice = 0;
  for (int i = 0; i < npc; ++i) {
    const auto& a = mesh.coords[mesh.cell(c)[i]];
    const auto& b = mesh.coords[mesh.cell(c)[(i + 1) % npc]];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * twice;
}

bool allCounterClockwise(const Mesh& mesh) {
  for (GO c = 0; c < mesh.numCells(); ++c)
    if (!(signedArea(mesh, c) > 0)) return false;
  return true;
}

double totalArea(const Mesh& mesh) {
  double sum = 0;
  for (GO c = 0; c < mesh.numCells(); ++c) sum += signedArea(mesh, c);
  return sum;
}

// ------------------------------------------------------------------------------------------

TEUCHOS_UNIT_TEST(MeshReader, ReadsTinyMsh) {
  const Mesh mesh = readData("unit_square_tri.msh");
  TEST_ASSERT(mesh.cellType == CellType::Triangle3);
  TEST_EQUALITY(mesh.numNodes(), 9);  // node 10 belongs to no cell and is dropped
  TEST_EQUALITY(mesh.numCells(), 8);
  TEST_ASSERT(contains(mesh.source, "unit_square_tri.msh"));
  TEST_EQUALITY(mesh.coords[8][0], 0.5);  // gmsh node 9, the centre
  TEST_EQUALITY(mesh.coords[8][1], 0.5);
  const GO cell0[3] = {0, 4, 8};  // gmsh element 101: nodes 1 5 9
  TEST_COMPARE_ARRAYS(Teuchos::arrayView(mesh.cell(0), 3), Teuchos::arrayView(cell0, 3));
  TEST_EQUALITY(mesh.boundaryNames(), "bottom, right, top, left");
  TEST_ASSERT(mesh.hasBoundary("top"));
  TEST_ASSERT(!mesh.hasBoundary("body"));
  const BoundaryGroup& bottom = mesh.boundary("bottom");
  TEST_EQUALITY(bottom.edges.size(), 2u);
  TEST_ASSERT((bottom.edges[0] == std::array<GO, 2>{1, 4}));  // as in the file: 2 5, 1 5
  TEST_ASSERT((bottom.edges[1] == std::array<GO, 2>{0, 4}));
  TEST_EQUALITY(mesh.regions.size(), 1u);
  TEST_EQUALITY(mesh.regions[0].name, "body");
  TEST_EQUALITY(mesh.regions[0].cells.size(), 8u);
  TEST_ASSERT(allCounterClockwise(mesh));
}

TEUCHOS_UNIT_TEST(MeshReader, ClockwiseSurfaceIsTurnedRound) {
  const Mesh mesh = readData("unit_square_cw.msh");  // every triangle listed clockwise
  TEST_EQUALITY(mesh.numCells(), 8);
  TEST_ASSERT(allCounterClockwise(mesh));
  const GO cell0[3] = {0, 4, 8};  // file: 1 9 5
  TEST_COMPARE_ARRAYS(Teuchos::arrayView(mesh.cell(0), 3), Teuchos::arrayView(cell0, 3));
}

TEUCHOS_UNIT_TEST(MeshReader, ReadsQuadsAndRefines) {
  const Mesh mesh = readData("unit_square_quad.msh", "Quadrilateral");
  TEST_ASSERT(mesh.cellType == CellType::Quadrilateral4);
  TEST_EQUALITY(mesh.numNodes(), 9);
  TEST_EQUALITY(mesh.numCells(), 4);
  TEST_ASSERT(allCounterClockwise(mesh));
  const Mesh fine = readData("unit_square_quad.msh", "Quadrilateral", 1);
  TEST_EQUALITY(fine.numCells(), 16);
  TEST_EQUALITY(fine.numNodes(), 25);
  TEST_EQUALITY(fine.boundary("bottom").edges.size(), 4u);
  TEST_ASSERT(allCounterClockwise(fine));
  TEST_FLOATING_EQUALITY(totalArea(fine), 1.0, 1e-12);
}

TEUCHOS_UNIT_TEST(MeshReader, ChannelGeoBothTypes) {
  // N = 4 cells across the height, 8 along: squares of side 1/2; a refinement halves them.
  const Mesh tri0 = readChannel("Triangle", 0);
  TEST_EQUALITY(tri0.numCells(), 64);
  TEST_EQUALITY(tri0.numNodes(), 45);
  const Mesh tri1 = readChannel("Triangle", 1);
  TEST_EQUALITY(tri1.numCells(), 256);
  TEST_EQUALITY(tri1.numNodes(), 153);
  TEST_EQUALITY(tri1.boundary("inlet").edges.size(), 8u);
  const Mesh quad0 = readChannel("Quadrilateral", 0);
  TEST_ASSERT(quad0.cellType == CellType::Quadrilateral4);
  TEST_EQUALITY(quad0.numCells(), 32);
  TEST_EQUALITY(quad0.numNodes(), 45);
  // gmsh places transfinite nodes to ~1e-12 only
  for (GO c = 0; c < quad0.numCells(); ++c)
    TEST_FLOATING_EQUALITY(signedArea(quad0, c), 0.25, 1e-10);
  const Mesh quad1 = readChannel("Quadrilateral", 1);
  TEST_EQUALITY(quad1.numCells(), 128);
  TEST_EQUALITY(quad1.numNodes(), 153);
  for (const Mesh* m : {&tri0, &tri1, &quad0, &quad1}) {
    TEST_ASSERT(allCounterClockwise(*m));
    TEST_FLOATING_EQUALITY(totalArea(*m), 8.0, 1e-10);
    TEST_EQUALITY(m->boundaryNames(), "inlet, outlet, bottom, top");
    TEST_EQUALITY(m->regions.at(0).name, "channel");
  }
}

TEUCHOS_UNIT_TEST(MeshReader, GeoParameterReachesDefineConstant) {
  const Mesh mesh = readChannel("Triangle", 0, 2.0);  // N = 2: 4 x 2 squares
  TEST_EQUALITY(mesh.numCells(), 16);
  TEST_EQUALITY(mesh.boundary("outlet").edges.size(), 2u);
  TEST_EQUALITY(readChannel("Triangle", 0).numCells(), 64);  // N does not leak into the next read
  Teuchos::ParameterList p = meshList("channel.geo");
  p.sublist("Geo Parameters").set("Bogus", 3.0);
  const std::string msg = inputError(
      [&] { flowform::readMesh(p, FLOWFORM_MESH_DIR, *Teuchos::DefaultComm<int>::getComm()); });
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "Geo Parameters/Bogus") && contains(msg, "it defines: N"));
}

TEUCHOS_UNIT_TEST(MeshReader, ValidParametersAcceptAnyGeoParameterName) {
  // As the driver embeds it: Geo Parameters' names belong to the .geo, not to flowform.
  Teuchos::ParameterList valid("Case"), user("Case");
  valid.set("Mesh", *flowform::validMeshParameters());
  user.sublist("Mesh").set("File", std::string("channel.geo"));
  user.sublist("Mesh").sublist("Geo Parameters").set("N", 8.0);
  TEST_NOTHROW(user.validateParametersAndSetDefaults(valid));
  TEST_EQUALITY(user.sublist("Mesh").get<int>("Uniform Refinements"), 0);
  user.sublist("Mesh").set("Uniform Refinement", 1);  // misspelt
  TEST_THROW(user.validateParametersAndSetDefaults(valid), std::exception);
}

TEUCHOS_UNIT_TEST(MeshReader, InputErrorsNameTheCulprit) {
  struct Case {
    std::string file, type, expect1, expect2;
  };
  const Case cases[] = {
      {"no_such_mesh.msh", "Triangle", "no_such_mesh.msh' (Mesh/File) does not exist", "data"},
      {"unit_square_flipped.msh", "Triangle", "inverted cell 3 (gmsh element 104", "7 of the 8"},
      {"unit_square_bowtie.msh", "Quadrilateral", "inverted cell 1 (gmsh element 102", "bow-tie"},
      {"unit_square_degenerate.msh", "Triangle", "degenerate cell 2 (gmsh element 103",
       "unit_square_degenerate.msh"},
      {"unit_square_mixed.msh", "Triangle", "mixes cell types", "unit_square_mixed.msh"},
      {"unit_square_tri.msh", "Quadrilateral", "Element Type is 'Quadrilateral'", "8 x Triangle 3"},
      {"broken.geo", "Triangle", "broken.geo", "syntax error"},
      {"unit_square_tri.msh", "Hexahedron", "Element Type", "Quadrilateral"},
      {"unit_square_tri.vtk", "Triangle", "unknown extension", ".geo"},
  };
  for (const Case& c : cases) {
    const std::string msg = inputError([&] { readData(c.file, c.type); });
    out << c.file << ": " << msg << "\n";
    TEST_ASSERT(contains(msg, c.expect1) && contains(msg, c.expect2));
  }
  const Mesh mesh = readData("unit_square_tri.msh");
  const std::string msg = inputError([&] { mesh.boundary("wall"); });
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "'wall'") && contains(msg, "unit_square_tri.msh") &&
              contains(msg, "bottom, right, top, left"));
}

// ------------------------------------------------------------------------------------------

TEUCHOS_UNIT_TEST(BoundaryCurve, StraightSideIsOrderedWithOutwardNormal) {
  const Mesh mesh = readData("unit_square_tri.msh");
  const BoundaryCurve bottom = flowform::buildBoundaryCurve(mesh, mesh.boundary("bottom"));
  const GO nodes[3] = {0, 4, 1};  // (0,0) -> (0.5,0) -> (1,0): material on the left
  TEST_COMPARE_ARRAYS(bottom.nodes, Teuchos::arrayView(nodes, 3));
  const double s[3] = {0.0, 0.5, 1.0};
  TEST_COMPARE_FLOATING_ARRAYS(bottom.arcLength, Teuchos::arrayView(s, 3), 1e-14);
  TEST_ASSERT(!bottom.closed);
  TEST_EQUALITY(bottom.segmentLength.size(), 2u);
  for (const auto& n : bottom.normals) {
    TEST_ASSERT(std::abs(n[0]) < 1e-14);
    TEST_FLOATING_EQUALITY(n[1], -1.0, 1e-14);
  }
  TEST_ASSERT(bottom.isStraight());
  const Mesh quads = readData("unit_square_quad.msh", "Quadrilateral");
  const BoundaryCurve top = flowform::buildBoundaryCurve(quads, quads.boundary("top"));
  TEST_EQUALITY(top.nodes.front(), 2);  // (1,1) -> (0,1)
  TEST_EQUALITY(top.nodes.back(), 3);
  TEST_FLOATING_EQUALITY(top.normals[1][1], 1.0, 1e-14);
}

TEUCHOS_UNIT_TEST(BoundaryCurve, CornerAndClosedLoop) {
  const Mesh mesh = readData("unit_square_tri.msh");
  BoundaryGroup corner{"corner", mesh.boundary("right").edges};
  for (const auto& e : mesh.boundary("bottom").edges) corner.edges.push_back(e);
  const BoundaryCurve c = flowform::buildBoundaryCurve(mesh, corner);
  TEST_EQUALITY(c.nodes.size(), 5u);
  TEST_EQUALITY(c.nodes[2], 1);  // the corner (1,0)
  TEST_FLOATING_EQUALITY(c.normals[2][0], std::sqrt(0.5), 1e-14);
  TEST_FLOATING_EQUALITY(c.normals[2][1], -std::sqrt(0.5), 1e-14);
  TEST_FLOATING_EQUALITY(c.arcLength.back(), 2.0, 1e-14);
  TEST_ASSERT(!c.isStraight());

  BoundaryGroup loop{"loop", {}};
  for (const BoundaryGroup& g : mesh.boundaries)
    loop.edges.insert(loop.edges.end(), g.edges.begin(), g.edges.end());
  const BoundaryCurve l = flowform::buildBoundaryCurve(mesh, loop);
  TEST_ASSERT(l.closed);
  TEST_EQUALITY(l.nodes.size(), 8u);
  TEST_EQUALITY(l.segmentLength.size(), 8u);
  TEST_EQUALITY(l.nodes[0], 0);  // closed: starts at the lowest node id
  TEST_EQUALITY(l.nodes[1], 4);  // and runs counter-clockwise
  TEST_FLOATING_EQUALITY(l.arcLength.back(), 3.5, 1e-14);
  TEST_FLOATING_EQUALITY(l.normals[0][0], -std::sqrt(0.5), 1e-14);
  TEST_FLOATING_EQUALITY(l.normals[0][1], -std::sqrt(0.5), 1e-14);
}

TEUCHOS_UNIT_TEST(BoundaryCurve, BadGroups) {
  const Mesh mesh = readData("unit_square_tri.msh");
  auto curveError = [&](const BoundaryGroup& g) {
    return inputError([&] { flowform::buildBoundaryCurve(mesh, g); });
  };
  BoundaryGroup twoPieces{"pieces", mesh.boundary("bottom").edges};
  for (const auto& e : mesh.boundary("top").edges) twoPieces.edges.push_back(e);
  std::string msg = curveError(twoPieces);
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "'pieces'") && contains(msg, "separate pieces"));
  msg = curveError({"inside", {{4, 8}}});  // midside (0.5,0) to the centre
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "'inside'") && contains(msg, "not on the mesh boundary"));
  msg = curveError({"empty", {}});
  TEST_ASSERT(contains(msg, "'empty'") && contains(msg, "no edges"));

  // Hand-made meshes (no reader checks): a zero-length edge, and two triangles that touch
  // at one node, where the boundary branches.
  Mesh zero;
  zero.source = "zero";
  zero.coords = {{0, 0}, {1, 0}, {1, 0}, {0, 1}};
  zero.cellNodes = {0, 1, 3, 1, 2, 3};
  msg = inputError([&] { flowform::buildBoundaryCurve(zero, {"z", {{0, 1}, {1, 2}}}); });
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "'z'") && contains(msg, "zero-length"));
  Mesh touch;
  touch.source = "touch";
  touch.coords = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}};
  touch.cellNodes = {0, 1, 2, 2, 3, 4};
  msg = inputError([&] {
    flowform::buildBoundaryCurve(touch, {"t", {{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 4}, {4, 2}}});
  });
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "'t'") && contains(msg, "branches at node 2"));
}

// ------------------------------------------------------------------------------------------

TEUCHOS_UNIT_TEST(Partition, TwoPartsCoverTheMesh) {
  const Mesh mesh = readChannel("Triangle", 0);
  const std::vector<int> serial = flowform::partitionCells(mesh, 1);
  TEST_COMPARE_ARRAYS(serial, std::vector<int>(mesh.numCells(), 0));

  const std::vector<int> part = flowform::partitionCells(mesh, 2);
  TEST_EQUALITY(static_cast<GO>(part.size()), mesh.numCells());
  int count[2] = {0, 0};
  for (int p : part) {
    TEST_ASSERT(p == 0 || p == 1);
    if (p == 0 || p == 1) ++count[p];
  }
  out << "cells per part: " << count[0] << " " << count[1] << "\n";
  TEST_ASSERT(count[0] > 0 && count[1] > 0);
  TEST_COMPARE_ARRAYS(flowform::partitionCells(mesh, 2), part);  // deterministic

  // Every rank computes the same partition without talking: compare with rank 0's.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<int> root(part);
  Teuchos::broadcast<int, int>(*comm, 0, static_cast<int>(root.size()), root.data());
  TEST_COMPARE_ARRAYS(root, part);

  const std::vector<int> owner = flowform::nodeOwners(mesh, part);
  std::vector<int> lowest(mesh.numNodes(), 2);
  for (GO c = 0; c < mesh.numCells(); ++c)
    for (int i = 0; i < 3; ++i)
      lowest[mesh.cell(c)[i]] = std::min(lowest[mesh.cell(c)[i]], part[c]);
  TEST_COMPARE_ARRAYS(owner, lowest);

  const Mesh quads = readChannel("Quadrilateral", 0);
  const std::vector<int> quadPart = flowform::partitionCells(quads, 2);
  TEST_ASSERT(std::count(quadPart.begin(), quadPart.end(), 0) > 0 &&
              std::count(quadPart.begin(), quadPart.end(), 1) > 0);
}

}  // namespace
