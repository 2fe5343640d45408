// ∂R/∂h of the assembled problem (Assembler::parameterDerivative, docs/theory.md §4) against central
// differences of the assembled residual, for every parameter — ν and m of every wall or of
// one, σ0, γ, n — on P1 and Q1 meshes, plane strain and axisymmetric, with velocity
// constraints and two contact walls whose nodes are in stick, slip and tension; the
// directional evaluation Assembler::tangent against J v; the parameter names. On 1 and 2
// ranks (the friction couples wall neighbours across the partition).
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/drivers/Simulation.hpp"
#include "flowform/solvers/ContactStatusLoop.hpp"
#include "StructuredMesh.hpp"

#include <Teuchos_XMLParameterListHelpers.hpp>

namespace {

using namespace flowform;
using Teuchos::ParameterList;
using Teuchos::RCP;

/// A structured nx × ny mesh of [x0, x0 + 1] × [0, 1], interior nodes moved by up to a
/// fifth of a cell; triangles on alternating diagonals. Groups bottom, right, top, left.
Mesh makeMesh(CellType type, int nx, int ny, double x0) {
  return test::structuredMesh(type, nx, ny, "SensitivityTest mesh", [&](int i, int j) {
    double xi = double(i) / nx, eta = double(j) / ny;
    if (i > 0 && i < nx && j > 0 && j < ny) {
      xi += 0.2 / nx * std::sin(7.1 * i + 3.3 * j);
      eta += 0.2 / ny * std::cos(5.3 * i - 2.9 * j);
    }
    return std::array<double, 2>{x0 + xi, eta};
  });
}

/// Inflow u = (1, 0) on the left; the bottom a Coulomb wall (ν = 0.3), the top an Orowan
/// wall (ν = 1, m = 0.3: limited by ν p where p is small, by m σ̄/√3 elsewhere); the right
/// traction-free. κ_t = 10 with μ_k = σ̄_k = 1: α_t = 10 W.
ParameterList conditions() {
  ParameterList bcs("Boundary Conditions");
  ParameterList& left = bcs.sublist("left");
  left.set("Type", "Velocity");
  left.set("Velocity X", 1.0);
  left.set("Velocity Y", 0.0);
  ParameterList& bottom = bcs.sublist("bottom");
  bottom.set("Type", "Contact Wall");
  bottom.set("Friction Law", "Coulomb");
  bottom.set("Friction Coefficient", 0.3);
  ParameterList& top = bcs.sublist("top");
  top.set("Type", "Contact Wall");
  top.set("Friction Law", "Orowan");
  top.set("Friction Coefficient", 1.0);
  top.set("Shear Factor", 0.3);
  return bcs;
}

/// The state: on the bottom wall p = 0.8 > 0 and u_t = 0.01 sin(6x), so α_t |u_t| is below
/// and above f̂ ≈ ν p L at different nodes (stick and slip); on the top wall p = 0.6 +
/// cos(3x) changes sign along x (tension and compression) and u_t ≈ −0.6 (slip). u·n = 0 on
/// both walls. Smooth in the interior.
std::array<double, 3> state(double x, double y) {
  return {0.01 * std::sin(6.0 * x) + y * (0.5 + 0.2 * std::cos(2.0 * x)), 0.2 * x * y * (1.0 - y),
          0.8 + y * (std::cos(3.0 * x) - 0.2)};
}

/// Mesh, walls, maps, conditions and assembler of one case (never moved: members refer
/// to each other).
struct Problem {
  Mesh mesh;
  std::vector<ContactWall> walls;
  std::unique_ptr<DofMap> dofMap;
  std::unique_ptr<BoundaryConditions> bcs;
  std::unique_ptr<Assembler> assembler;
  FlowPhysics physics;

  Problem(CellType type, Geometry geometry, const RCP<const Comm>& comm) : mesh(makeMesh(type, 6, 4, 0.5)) {
    const ParameterList bcList = conditions();
    std::vector<std::array<GO, 2>> couplings;
    for (const char* wall : {"bottom", "top"}) {
      walls.emplace_back(wall, bcList.sublist(wall), mesh, geometry);
      for (const auto& c : walls.back().couplings()) couplings.push_back(c);
    }
    dofMap = std::make_unique<DofMap>(mesh, comm, couplings);
    bcs = std::make_unique<BoundaryConditions>(bcList, mesh, *dofMap);
    assembler = std::make_unique<Assembler>(mesh, *dofMap, *bcs);
    physics.kernel.geometry = geometry;
    physics.kernel.beta = 0.1;
    physics.material = flowform::powerLaw(0.5, 1.3, 5.0, 1e-2);
    assembler->setPhysics(physics);
    assembler->setContactWalls(&walls);
  }
  RCP<Vector> vector() const { return Teuchos::rcp(new Vector(dofMap->ownedMap())); }
  RCP<Vector> stateVector() const {
    auto x = vector();
    auto v = x->getLocalViewHost(Tpetra::Access::OverwriteAll);
    const Map& map = *x->getMap();
    for (size_t i = 0; i < x->getLocalLength(); ++i) {
      const GO g = map.getGlobalElement(static_cast<LO>(i));
      const auto& xy = mesh.coords[dofMap->nodeOfGlobalDof(g)];
      v(i, 0) = state(xy[0], xy[1])[dofMap->fieldOfGlobalDof(g)];
    }
    return x;
  }
};

std::string caseName(CellType type, Geometry geometry) {
  return std::string(cellTypeName(type)) + (geometry == Geometry::PlaneStrain ? ", plane strain" : ", axisymmetric");
}

const char* const kParameters[] = {"Friction Coefficient", "Friction Coefficient:bottom", "Friction Coefficient:top",
                                   "Shear Factor",         "Shear Factor:top",            "Yield Stress",
                                   "Rate Constant",        "Rate Exponent"};

TEUCHOS_UNIT_TEST(Sensitivity, AssembledParameterDerivativeMatchesFiniteDifferences) {
  // Central differences of the assembled residual, δ = 1e-6 (absolute for ν, m; relative
  // for σ0, γ, n). Inside a branch of the contact law R is linear in ν and m, and in σ0; in
  // γ and n smooth with derivatives O(1)·|R| (μ ∝ (e/γ)^(1/n), e = O(1)), so truncation
  // (δ²/6)|R'''| ≈ 1e-12 |R|. Round-off eps |R| / δ ≈ 2e-10 |R|, and |∂R/∂h| ≥ 1e-2 |R|
  // here: 1e-6 of max|∂R/∂h| leaves > 100×. A term of ∂R/∂h missing (the contact part, one
  // wall, the stabilization's μ_K, the axisymmetric hoop term) errs by O(1e-2..1).
  // The branches of every wall node are the same at h ± δ as at h (asserted), so the
  // differences never straddle a kink.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  setLogEnabled(false);
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
      Problem problem(type, geometry, comm);
      const auto x = problem.stateVector();
      problem.bcs->imposeOnSolution(*x);

      const auto branches = wallBranches(problem.walls, *problem.dofMap, *x);
      int count[5] = {0, 0, 0, 0, 0};
      for (const auto& wall : branches)
        for (FrictionBranch b : wall) ++count[static_cast<int>(b)];
      out << caseName(type, geometry) << ": wall nodes with no friction " << count[1] << ", stick " << count[2]
          << ", slip " << count[3] << ", slip (Tresca-limited) " << count[4] << "\n";
      TEST_COMPARE(count[static_cast<int>(FrictionBranch::Stick)], >, 0);
      TEST_COMPARE(count[static_cast<int>(FrictionBranch::Slip)], >, 0);
      TEST_COMPARE(count[static_cast<int>(FrictionBranch::NoFriction)], >, 0);
      TEST_COMPARE(count[static_cast<int>(FrictionBranch::SlipTresca)], >, 0);

      for (const char* name : kParameters) {
        const SensitivityParameter h = parseSensitivityParameter(name, problem.walls, 0);
        auto ad = problem.vector(), fp = problem.vector(), fm = problem.vector();
        problem.assembler->parameterDerivative(*x, h, *ad);
        const double delta = h.finiteDifferenceStep(1e-6, problem.physics);
        bool sameBranches = true;
        for (double sign : {1.0, -1.0}) {
          FlowPhysics physics = problem.physics;
          std::vector<ContactWall> walls = problem.walls;
          shiftParameter(h, sign * delta, physics, walls);
          problem.assembler->setPhysics(physics);
          problem.assembler->setContactWalls(&walls);
          problem.assembler->residual(*x, sign > 0 ? *fp : *fm);
          sameBranches = sameBranches && wallBranches(walls, *problem.dofMap, *x) == branches;
        }
        problem.assembler->setPhysics(problem.physics);
        problem.assembler->setContactWalls(&problem.walls);
        fp->update(-1.0 / (2 * delta), *fm, 1.0 / (2 * delta));
        fp->update(-1.0, *ad, 1.0);
        const double err = fp->normInf(), scale = ad->normInf();
        out << "  " << name << ": max |dR/dh| = " << scale << ", max |AD − FD| / max |AD| = " << err / scale << "\n";
        TEST_ASSERT(sameBranches);
        TEST_COMPARE(scale, >, 0.0);
        TEST_COMPARE(err, <=, 1e-6 * scale);
      }
    }
}

TEUCHOS_UNIT_TEST(Sensitivity, ConstraintRowsDoNotDependOnParameters) {
  // Prescribed-velocity rows a·u − b carry no h: ∂R/∂h is exactly 0 there.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Problem problem(CellType::Quadrilateral4, Geometry::PlaneStrain, comm);
  const auto x = problem.stateVector();
  problem.bcs->imposeOnSolution(*x);
  int nonzero = 0, constrained = 0;
  for (const char* name : kParameters) {
    auto d = problem.vector();
    problem.assembler->parameterDerivative(*x, parseSensitivityParameter(name, problem.walls, 0), *d);
    auto v = d->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO n = 0; n < problem.dofMap->numOwnedNodes(); ++n)
      if (problem.bcs->constraints()[n].kind == NodeConstraint::Kind::Full) {
        ++constrained;
        nonzero += v(problem.dofMap->dof(n, kUx), 0) != 0.0 || v(problem.dofMap->dof(n, kUy), 0) != 0.0;
      }
  }
  int total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, constrained, Teuchos::outArg(total));
  TEST_COMPARE(total, >, 0);
  TEST_EQUALITY_CONST(nonzero, 0);
}

TEUCHOS_UNIT_TEST(Sensitivity, TangentIsJacobianTimesDirectionPlusParameterDerivative) {
  // tangent(x, v, h) = J v + ∂R/∂h: the directional evaluation the responses use. Both
  // sides are AD of the same residual, so they agree to round-off (1e-12 of the scale).
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    Problem problem(type, Geometry::Axisymmetric, comm);
    const auto x = problem.stateVector();
    problem.bcs->imposeOnSolution(*x);
    auto v = problem.vector(), jv = problem.vector(), dh = problem.vector(), t = problem.vector();
    v->randomize();
    auto J = problem.assembler->createJacobian();
    problem.assembler->jacobian(*x, *J);
    J->apply(*v, *jv);
    const SensitivityParameter h = parseSensitivityParameter("Friction Coefficient", problem.walls, 0);
    problem.assembler->parameterDerivative(*x, h, *dh);
    problem.assembler->tangent(*x, v.get(), &h, *t);
    t->update(-1.0, *jv, -1.0, *dh, 1.0);
    const double scale = std::max(jv->normInf(), dh->normInf());
    out << cellTypeName(type) << ": |tangent − Jv − dR/dh| / scale = " << t->normInf() / scale << "\n";
    TEST_COMPARE(t->normInf(), <=, 1e-12 * scale);
  }
}

TEUCHOS_UNIT_TEST(Sensitivity, ExtrusionFrictionSensitivityIsExactlyZeroInStickAndTension) {
  // Paper eq. 28 on a converged extrusion (h = 0.2): ν enters R only through the friction of
  // slipping wall nodes, so ∂R/∂ν is exactly 0 (not to round-off) in every row but those —
  // at sticking nodes (ν = 0.3: the container and die face stick near the dead zone) and at
  // nodes without compression (ν = 0: the die-land nodes near the exit corner are in
  // tension); at slipping nodes it is f̂/ν = P_k (nonzero also at ν = 0).
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  setLogEnabled(false);
  for (double nu : {0.0, 0.3}) {
    auto params = Teuchos::getParametersFromXmlFile(FLOWFORM_SOURCE_DIR "/xml/extrusion.xml");
    params->sublist("Mesh").sublist("Geo Parameters").set("h", 0.2);
    params->sublist("Mesh").sublist("Geo Parameters").set("hc", 0.05);
    params->sublist("Adaptivity").set("Enabled", false);  // this mesh, solved once
    Teuchos::ParameterList& bcs = params->sublist("Boundary Conditions");  // every contact wall of the scene
    for (auto it = bcs.begin(); it != bcs.end(); ++it)
      if (bcs.sublist(bcs.name(it)).get<std::string>("Type", "") == "Contact Wall")
        bcs.sublist(bcs.name(it)).set("Friction Coefficient", nu);
    Simulation sim(*params, FLOWFORM_SOURCE_DIR "/xml", comm);
    TEST_ASSERT(sim.run().converged);
    const auto& walls = sim.problem().contactWalls();

    const auto branches = wallBranches(walls, sim.problem().dofMap(), sim.problem().solution());
    // Per node: does any wall through it slip there?
    std::vector<int> slips(sim.problem().mesh().numNodes(), 0), walled(sim.problem().mesh().numNodes(), 0);
    int count[5] = {0, 0, 0, 0, 0};
    for (size_t w = 0; w < walls.size(); ++w)
      for (int k = 0; k < walls[w].numNodes(); ++k) {
        const GO node = walls[w].curve().nodes[k];
        walled[node] = 1;
        slips[node] |= branches[w][k] == FrictionBranch::Slip;
        ++count[static_cast<int>(branches[w][k])];
      }
    Vector d(sim.problem().dofMap().ownedMap());
    sim.problem().model().assembler().parameterDerivative(sim.problem().solution(), parseSensitivityParameter("Friction Coefficient", walls, 0),
                                                d);
    auto v = d.getLocalViewHost(Tpetra::Access::ReadOnly);
    int nonzeroWithoutSlip = 0, nonzeroAtSlip = 0, zeroWallRows = 0;
    for (LO n = 0; n < sim.problem().dofMap().numOwnedNodes(); ++n) {
      const GO node = sim.problem().dofMap().overlapNodes()[n];
      const DofMap& dofs = sim.problem().dofMap();
      const bool nonzero = v(dofs.dof(n, kUx), 0) != 0.0 || v(dofs.dof(n, kUy), 0) != 0.0 || v(dofs.dof(n, kP), 0) != 0.0;
      if (slips[node]) nonzeroAtSlip += nonzero;
      else nonzeroWithoutSlip += nonzero;
      zeroWallRows += walled[node] && !slips[node] && !nonzero;
    }
    int local[3] = {nonzeroWithoutSlip, nonzeroAtSlip, zeroWallRows}, global[3];
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 3, local, global);
    out << "ν = " << nu << ": wall nodes free " << count[0] << ", no friction " << count[1] << ", stick " << count[2]
        << ", slip " << count[3] << "; nonzero rows of dR/dν at slip nodes " << global[1]
        << ", elsewhere " << global[0] << "; exactly zero at non-slipping wall nodes " << global[2] << "\n";
    TEST_EQUALITY_CONST(global[0], 0);
    TEST_COMPARE(global[1], >, 0);
    TEST_COMPARE(global[2], >, 0);
    if (nu == 0.3) TEST_COMPARE(count[static_cast<int>(FrictionBranch::Stick)], >, 0);
    if (nu == 0.0) TEST_COMPARE(count[static_cast<int>(FrictionBranch::NoFriction)] + count[0], >, 0);
  }
}

TEUCHOS_UNIT_TEST(Sensitivity, ParameterNamesAreValidated) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Problem problem(CellType::Triangle3, Geometry::PlaneStrain, comm);
  const SensitivityParameter nu = parseSensitivityParameter("Friction Coefficient:top", problem.walls, 0);
  TEST_EQUALITY(nu.symbol, std::string("nu_top"));
  TEST_EQUALITY_CONST(nu.wall, 1);
  auto message = [&](const std::string& name, const std::vector<ContactWall>& walls) {
    try {
      parseSensitivityParameter(name, walls, 0);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Unknown: the message lists the allowed names, the walls' included.
  const std::string unknown = message("Friction Coefficent", problem.walls);
  TEST_ASSERT(unknown.find("Friction Coefficent") != std::string::npos);
  TEST_ASSERT(unknown.find("'Rate Exponent'") != std::string::npos);
  TEST_ASSERT(unknown.find("'Shear Factor:top'") != std::string::npos);
  // A friction parameter without walls, an unknown wall, a law that does not use it.
  TEST_ASSERT(message("Friction Coefficient", {}).find("no contact wall") != std::string::npos);
  TEST_ASSERT(message("Friction Coefficient:nosuch", problem.walls).find("nosuch") != std::string::npos);
  TEST_ASSERT(message("Shear Factor:bottom", problem.walls).find("uses") != std::string::npos);
  TEST_ASSERT(message("Yield Stress:bottom", problem.walls).find("not per wall") != std::string::npos);
  // Steps: absolute for friction, relative for the material.
  TEST_EQUALITY_CONST(nu.finiteDifferenceStep(2e-4, problem.physics), 2e-4);
  const SensitivityParameter n = parseSensitivityParameter("Rate Exponent", problem.walls, 0);
  TEST_FLOATING_EQUALITY(n.finiteDifferenceStep(2e-4, problem.physics), 1e-3, 1e-14);
}

}  // namespace
