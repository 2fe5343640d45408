// Parallel = serial for the assembled problem: on N ranks the residual and the Jacobian,
// gathered by global dof, equal those of the same case assembled on one rank (a split
// communicator), on a generated mesh and on the channel scene.
#include "AssemblyProblem.hpp"

namespace {  // AssemblyProblem.hpp's, with its using-declarations

/// Residual and Jacobian gathered on rank 0, by global dof. Other ranks get empty ones.
struct Gathered {
  std::vector<double> f;
  std::vector<std::map<GO, double>> rows;
};

/// Assembles F(x) and J(x) for the field `state` (constraints imposed) and gathers them.
/// Also checks that residual() and jacobian()'s F agree (the two assembly paths).
Gathered assembleAndGather(const Mesh& mesh, const DofMap& dofMap, const Assembler& assembler,
                           const BoundaryConditions& bcs, const Field& state, double& pathDifference) {
  const auto comm = dofMap.comm();
  const GO numDofs = dofMap.numGlobalDofs();
  Vector x(dofMap.ownedMap()), f(dofMap.ownedMap()), fj(dofMap.ownedMap());
  interpolate(mesh, dofMap, state, x);
  bcs.imposeOnSolution(x);
  assembler.residual(x, f);
  auto J = assembler.createJacobian();
  assembler.jacobian(x, *J, &fj);
  fj.update(-1.0, f, 1.0);
  pathDifference = fj.normInf() / f.normInf();

  const bool root = comm->getRank() == 0;
  auto rootMap = Teuchos::rcp(new Map(numDofs, root ? numDofs : 0, 0, comm));
  Import toRoot(dofMap.ownedMap(), rootMap);
  Vector fRoot(rootMap);
  fRoot.doImport(f, toRoot, Tpetra::INSERT);
  auto JRoot = Tpetra::importAndFillCompleteCrsMatrix<CrsMatrix>(Teuchos::rcp_implicit_cast<const CrsMatrix>(J),
                                                                 toRoot, rootMap, rootMap);
  Gathered g;
  if (!root) return g;
  auto fv = fRoot.getLocalViewHost(Tpetra::Access::ReadOnly);
  g.f.assign(fv.data(), fv.data() + numDofs);
  g.rows.resize(numDofs);
  CrsMatrix::nonconst_global_inds_host_view_type cols("cols", JRoot->getNodeMaxNumRowEntries());
  CrsMatrix::nonconst_values_host_view_type vals("vals", JRoot->getNodeMaxNumRowEntries());
  for (GO row = 0; row < numDofs; ++row) {
    size_t n = 0;
    JRoot->getGlobalRowCopy(row, cols, vals, n);
    for (size_t k = 0; k < n; ++k) g.rows[row][cols(k)] = vals(k);
  }
  return g;
}

// Each cell's contribution is computed from bitwise the same coordinates and dofs on any
// number of ranks; only the order in which a shared row's ≤ 8 contributions are summed
// differs (locally, then by the Export's ADD). That is ≤ 8 eps of the largest contribution,
// which is at most ~10× the row's largest entry: 1e-12 of that scale leaves a margin of
// > 50. Any partition-dependent error (a shared row counted twice or missed, a constraint
// applied on the wrong rank, a wrong column map) is O(1) of the entry.
constexpr double kParallelTol = 1e-12;

/// Compares the gathered results of the N-rank and the one-rank assembly on rank 0 and
/// returns the verdict on every rank.
bool sameAssembly(const Gathered& par, const Gathered& ser, const Comm& comm, Teuchos::FancyOStream& out) {
  int bad = 0;
  if (comm.getRank() == 0) {
    double fScale = 0.0;
    for (double v : ser.f) fScale = std::max(fScale, std::abs(v));
    double fErr = 0.0, jErr = 0.0;
    int patternMismatch = 0;
    for (size_t i = 0; i < ser.f.size(); ++i) {
      fErr = std::max(fErr, std::abs(par.f[i] - ser.f[i]) / fScale);
      const auto& rp = par.rows[i];
      const auto& rs = ser.rows[i];
      if (rp.size() != rs.size()) ++patternMismatch;
      double rowScale = 0.0;
      for (const auto& [col, v] : rs) rowScale = std::max(rowScale, std::abs(v));
      for (const auto& [col, v] : rs) {
        const auto it = rp.find(col);
        if (it == rp.end()) { ++patternMismatch; continue; }
        jErr = std::max(jErr, std::abs(it->second - v) / rowScale);
      }
    }
    out << "residual: max |F_N − F_1| / max|F_1| = " << fErr << "; Jacobian: max |J_N − J_1| / row max = " << jErr
        << "; pattern mismatches: " << patternMismatch << " (" << comm.getSize() << " rank(s))\n";
    bad = !(fErr <= kParallelTol && jErr <= kParallelTol && patternMismatch == 0 && fScale > 0.0);
  }
  Teuchos::broadcast(comm, 0, Teuchos::outArg(bad));
  return bad == 0;
}

TEUCHOS_UNIT_TEST(Assembly, ParallelEqualsSerialGeneratedMesh) {
  // Distorted mesh with an inclined symmetry line, nonlinear law, body force.
  const auto comm = worldComm();
  const auto serialComm = comm->split(comm->getRank(), 0);  // rank 0's is the serial reference
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
      const auto physics = makePhysics(geometry, kNonlinear, 0.1, 0.3, -0.7);
      const Mesh mesh = makeMesh(type, 7, 5, 0.0, 0.0, 2.0, 1.0, 0.25, 0.3);
      double pathDiff = 0.0;
      Problem par(mesh, generalConditions(), physics, comm);
      const Gathered gp = assembleAndGather(par.mesh, *par.dofMap, *par.assembler, *par.bcs, kSmooth, pathDiff);
      // residual() and the F of jacobian() are the same sums of the same values.
      TEST_COMPARE(globalMax(*comm, pathDiff), <=, 1e-14);
      Gathered gs;
      if (comm->getRank() == 0) {
        Problem ser(mesh, generalConditions(), physics, serialComm);
        gs = assembleAndGather(ser.mesh, *ser.dofMap, *ser.assembler, *ser.bcs, kSmooth, pathDiff);
      }
      out << caseName(type, geometry, kNonlinear) << ": ";
      TEST_ASSERT(sameAssembly(gp, gs, *comm, out));
    }
}

/// The channel scene (meshes/channel.geo, N = 4) with symmetry, velocity, mixed and
/// traction groups and the nonlinear law, through Simulation as the driver builds it.
ParameterList channelCase(const std::string& elementType, const std::string& geometry) {
  ParameterList p("flowform");
  p.sublist("Problem").set("Geometry", geometry);
  p.sublist("Problem").set("Body Force X", 0.3);
  p.sublist("Problem").set("Body Force Y", -0.7);
  ParameterList& m = p.sublist("Material");
  m.set("Yield Stress", 0.5);
  m.set("Rate Constant", 1.0);
  m.set("Rate Exponent", 5.0);
  m.set("Strain Rate Cutoff", 1e-2);
  p.sublist("Stabilization").set("Beta", 0.1);
  ParameterList& mesh = p.sublist("Mesh");
  mesh.set("File", std::string(FLOWFORM_SOURCE_DIR) + "/meshes/channel.geo");
  mesh.set("Element Type", elementType);
  mesh.sublist("Geo Parameters").set("N", 4.0);
  p.sublist("Boundary Conditions") = bcList({{"bottom", "Symmetry", {}},
                                             {"top", "Velocity", {{"Velocity X", 0.3}, {"Velocity Y", 0.0}}},
                                             {"inlet", "Velocity", {{"Velocity Y", 0.0}, {"Traction X", 4.0}}},
                                             {"outlet", "Traction", {{"Traction X", -0.5}, {"Traction Y", 0.2}}}});
  return p;
}

TEUCHOS_UNIT_TEST(Assembly, ParallelEqualsSerialChannel) {
  const auto comm = worldComm();
  const auto serialComm = comm->split(comm->getRank(), 0);
  const Field state = [](double x, double y) {
    return std::array<double, 3>{(1 - y * y) * (1 + 0.2 * std::sin(x)), 0.1 * std::sin(1.5 * x) * (1 - y * y),
                                 4.0 - x + 0.3 * y};
  };
  for (const std::string type : {"Triangle", "Quadrilateral"})
    for (const std::string geometry : {"Plane Strain", "Axisymmetric"}) {
      const ParameterList params = channelCase(type, geometry);
      Simulation par(params, "", comm);
      // The conditions as the Simulation built them, to impose them on the state.
      const BoundaryConditions parBcs(par.parameters().sublist("Boundary Conditions"), par.problem().mesh(), par.problem().dofMap());
      double pathDiff = 0.0;
      const Gathered gp =
          assembleAndGather(par.problem().mesh(), par.problem().dofMap(), par.problem().model().assembler(), parBcs, state, pathDiff);
      TEST_COMPARE(globalMax(*comm, pathDiff), <=, 1e-14);
      Gathered gs;
      if (comm->getRank() == 0) {
        Simulation ser(params, "", serialComm);
        const BoundaryConditions serBcs(ser.parameters().sublist("Boundary Conditions"), ser.problem().mesh(), ser.problem().dofMap());
        gs = assembleAndGather(ser.problem().mesh(), ser.problem().dofMap(), ser.problem().model().assembler(), serBcs, state, pathDiff);
      }
      out << "channel, " << type << ", " << geometry << ": ";
      TEST_ASSERT(sameAssembly(gp, gs, *comm, out));
    }
}

}  // namespace
