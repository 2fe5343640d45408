// Shared by the assembly tests (AssemblyTest, AssemblyParallelTest): a small assembled
// problem on a generated mesh, boundary-condition lists, fields to interpolate.
#pragma once

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/solvers/FlowModel.hpp"
#include "flowform/solvers/LinearSolverRegistry.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/drivers/Simulation.hpp"
#include "StructuredMesh.hpp"

namespace {

using namespace flowform;
using Teuchos::ParameterList;
using Teuchos::RCP;
using Field = std::function<std::array<double, 3>(double, double)>;  // (x, y) -> (u_x, u_y, p)

const MaterialParameters<double> kNewtonian = flowform::powerLaw(0.0, 1.0, 1.0, 1e-3);
const MaterialParameters<double> kNonlinear = flowform::powerLaw(0.5, 1.0, 5.0, 1e-2);

inline RCP<const Comm> worldComm() {
  setLogEnabled(false);
  return Teuchos::DefaultComm<int>::getComm();
}

inline double globalMax(const Comm& comm, double local) {
  double global = local;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

/// Deterministic value in [−1, 1] for grid point (i, j).
inline double hash(int i, int j, double salt) {
  const double s = std::sin(12.9898 * i + 78.233 * j + salt) * 43758.5453;
  return 2.0 * (s - std::floor(s)) - 1.0;
}

/// Every cell has positive Jacobian determinants at its quadrature points.
inline bool meshIsValid(const Mesh& mesh) {
  const int npc = nodesPerCell(mesh.cellType);
  for (GO c = 0; c < mesh.numCells(); ++c) {
    std::array<double, 2> xy[kMaxNodesPerCell];
    for (int a = 0; a < npc; ++a) xy[a] = mesh.coords[mesh.cell(c)[a]];
    CellQuadrature cq;
    if (!computeCellQuadrature(mesh.cellType, xy, 2, cq)) return false;
  }
  return true;
}

/// A structured nx × ny mesh of [x0, x0+Lx] × [y0, y0 + Ly(1 + slope ξ)] (ξ = (x−x0)/Lx:
/// with a slope the top side is straight but inclined), interior nodes moved by up to
/// `distortion` of a cell in each direction. Triangles split the cells along alternating
/// diagonals. Boundary groups bottom, right, top, left.
inline Mesh makeMesh(CellType type, int nx, int ny, double x0, double y0, double Lx, double Ly, double distortion,
              double slope = 0.0) {
  Mesh mesh = test::structuredMesh(type, nx, ny, "AssemblyTest mesh", [&](int i, int j) {
    double xi = double(i) / nx, eta = double(j) / ny;
    if (i > 0 && i < nx && j > 0 && j < ny) {
      xi += distortion / nx * hash(i, j, 0.1);
      eta += distortion / ny * hash(i, j, 0.7);
    }
    return std::array<double, 2>{x0 + xi * Lx, y0 + eta * Ly * (1.0 + slope * xi)};
  });
  if (!meshIsValid(mesh)) throw std::logic_error("AssemblyTest: the generated mesh has an inverted cell");
  return mesh;
}

/// Mesh, maps, conditions, assembler and model for one case (members refer to each other,
/// so a Problem is never moved).
struct Problem {
  Mesh mesh;
  std::unique_ptr<DofMap> dofMap;
  std::unique_ptr<BoundaryConditions> bcs;
  std::unique_ptr<Assembler> assembler;
  std::unique_ptr<FlowModel> model;

  Problem(Mesh m, const ParameterList& bcList, const FlowPhysics& physics, const RCP<const Comm>& comm)
      : mesh(std::move(m)) {
    dofMap = std::make_unique<DofMap>(mesh, comm);
    bcs = std::make_unique<BoundaryConditions>(bcList, mesh, *dofMap);
    assembler = std::make_unique<Assembler>(mesh, *dofMap, *bcs);
    assembler->setPhysics(physics);
    Teuchos::ParameterList linear("Linear Solver");
    linear.validateParametersAndSetDefaults(*validLinearSolverParameters());
    model = std::make_unique<FlowModel>(*assembler, createLinearSolver(linear, *comm));
  }
  RCP<Vector> vector() const { return Teuchos::rcp(new Vector(dofMap->ownedMap())); }
};

/// J v and its central difference (F(x + δv) − F(x − δv)) / (2δ) for the assembler's residual at
/// x, into `jv` and `fd` (owned vectors of x's map).
inline void jacobianAndDifference(const Assembler& assembler, const Vector& x, const Vector& v, double delta,
                                  Vector& jv, Vector& fd) {
  auto J = assembler.createJacobian();
  assembler.jacobian(x, *J);
  J->apply(v, jv);
  Vector xp(x.getMap()), xm(x.getMap()), fm(x.getMap());
  xp.update(1.0, x, delta, v, 0.0);
  xm.update(1.0, x, -delta, v, 0.0);
  assembler.residual(xp, fd);
  assembler.residual(xm, fm);
  fd.update(-1.0 / (2 * delta), fm, 1.0 / (2 * delta));
}

inline FlowPhysics makePhysics(Geometry geometry, const MaterialParameters<double>& material, double beta, double fx,
                        double fy) {
  FlowPhysics p;
  p.kernel.geometry = geometry;
  p.kernel.beta = beta;
  p.kernel.bodyForce[0] = fx;
  p.kernel.bodyForce[1] = fy;
  p.material = material;
  return p;
}

/// One group of a "Boundary Conditions" list; only the entries given are set.
struct Group {
  std::string name, type;
  std::map<std::string, double> values;
};
inline ParameterList bcList(const std::vector<Group>& groups) {
  ParameterList list("Boundary Conditions");
  for (const auto& g : groups) {
    ParameterList& s = list.sublist(g.name);
    s.set("Type", g.type);
    for (const auto& [k, v] : g.values) s.set(k, v);
  }
  return list;
}

/// x ← the nodal values of `field` (owned dofs; node and field of a dof from the DofMap).
inline void interpolate(const Mesh& mesh, const DofMap& dofMap, const Field& field, Vector& x) {
  auto v = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const Map& map = *x.getMap();
  for (size_t i = 0; i < x.getLocalLength(); ++i) {
    const GO g = map.getGlobalElement(static_cast<LO>(i));
    const auto& xy = mesh.coords[dofMap.nodeOfGlobalDof(g)];
    v(i, 0) = field(xy[0], xy[1])[dofMap.fieldOfGlobalDof(g)];
  }
}

/// x ← the flow `field` and a one-component field after the flow's ← `scalar` at the nodes
/// (owned dofs): a case with a second field (FieldKernelTest, CoupledFlowKernelTest).
inline void interpolate(const Mesh& mesh, const DofMap& dofMap, const Field& field,
                        const std::function<double(double, double)>& scalar, Vector& x) {
  auto v = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const Map& map = *x.getMap();
  for (size_t i = 0; i < x.getLocalLength(); ++i) {
    const GO g = map.getGlobalElement(static_cast<LO>(i));
    const auto& xy = mesh.coords[dofMap.nodeOfGlobalDof(g)];
    const int c = dofMap.fieldOfGlobalDof(g);
    v(i, 0) = c < kNumFlowComponents ? field(xy[0], xy[1])[c] : scalar(xy[0], xy[1]);
  }
}

inline std::set<GO> boundaryNodes(const Mesh& mesh) {
  std::set<GO> nodes;
  for (const auto& b : mesh.boundaries)
    for (const auto& e : b.edges) nodes.insert(e.begin(), e.end());
  return nodes;
}

inline std::string caseName(CellType type, Geometry geometry, const MaterialParameters<double>& m) {
  return std::string(cellTypeName(type)) + (geometry == Geometry::PlaneStrain ? ", plane strain" : ", axisymmetric") +
         (isNewtonian(m) ? ", Newtonian" : ", nonlinear");
}

/// μ(D:D) of the law, written out (pow form) for the tractions of the exact solutions.
inline double viscosityOf(double ddot, const MaterialParameters<double>& m) {
  const double er = std::sqrt(2.0 / 3.0 * ddot + m.cutoff * m.cutoff);
  const auto& v = m.values;  // the power law: σ0, γ, n
  return (v[0] + std::pow(er / v[1], 1.0 / v[2])) / (3.0 * er);
}

/// The conditions of the general test case on makeMesh's groups: symmetry on the inclined
/// top (a Single constraint mixing both components), a moving wall, a mixed velocity /
/// traction inlet and a loaded outlet.
inline ParameterList generalConditions() {
  return bcList({{"top", "Symmetry", {}},
                 {"bottom", "Velocity", {{"Velocity X", 0.3}, {"Velocity Y", 0.0}}},
                 {"left", "Velocity", {{"Velocity Y", 0.0}, {"Traction X", 2.0}}},
                 {"right", "Traction", {{"Traction X", -0.4}, {"Traction Y", 0.25}}}});
}

/// A smooth state with strain rates ~1 (≫ e0) and pressure ~1, constraints imposed.
const Field kSmooth = [](double x, double y) {
  return std::array<double, 3>{0.8 * x + 0.3 * std::sin(1.7 * y + 0.4 * x),
                               -0.8 * y + 0.3 * std::cos(1.1 * x - 0.6 * y),
                               1.0 + 0.5 * std::sin(0.9 * x + 1.4 * y)};
};

}  // namespace
