// The flow and its energy balance in one kernel (physics/kernels/ThermoMechanicalKernel.hpp):
//  - its assembled Jacobian (T rows with u columns: convection, heating, SUPG's τ(u)) matches
//    central differences of the assembled residual, on P1 and Q1 meshes, plane and
//    axisymmetric, in the diffusive (ρc = 1) and convective (ρc = 1e3: cell Péclet ≫ 1) regimes;
//  - with a temperature-dependent law (Sellars–Tegart) the same, the flow rows now with T columns;
//  - without flow (u = 0: held on three sides, free on the fourth) and with T prescribed on the boundary to T = a + b x + d y in plane
//    strain, a linear T is reproduced (no heating, no convection, diffusion exact for linear T).
#include "AssemblyProblem.hpp"

#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/physics/kernels/ThermoMechanicalKernel.hpp"

namespace {  // AssemblyProblem.hpp's, with its using-declarations

FieldRegistry flowAndTemperature() {
  FieldRegistry fields = FieldRegistry::flow();
  fields.add({"Temperature", 1});
  return fields;
}

struct ThermalProblem {
  Mesh mesh;
  std::unique_ptr<DofMap> dofMap;
  std::unique_ptr<BoundaryConditions> bcs;
  std::unique_ptr<Assembler> assembler;

  ThermalProblem(Mesh m, const ParameterList& bcList, const FlowPhysics& physics, const RCP<const Comm>& comm,
                 const ThermalProperties& properties)
      : mesh(std::move(m)) {
    const FieldRegistry fields = flowAndTemperature();
    dofMap = std::make_unique<DofMap>(mesh, comm, std::vector<std::array<GO, 2>>{}, fields);
    bcs = std::make_unique<BoundaryConditions>(bcList, mesh, *dofMap);
    assembler = std::make_unique<Assembler>(mesh, *dofMap, *bcs);
    FlowPhysics withProperties = physics;
    withProperties.thermal = properties;
    assembler->setPhysics(withProperties);
    assembler->setKernels({makeCellKernel(ThermoMechanicalKernel{}, fields)});
  }
  RCP<Vector> vector() const { return Teuchos::rcp(new Vector(dofMap->ownedMap())); }
};

ThermalProperties properties(double rhoC) {
  ThermalProperties p;
  p.conductivity = 0.7;
  p.density = rhoC;
  p.specificHeat = 1.0;
  p.heatFraction = 0.9;
  return p;
}

/// |J v − FD|∞ / |J v|∞ at a smooth state with T = T0 + 0.3 T1 sin(1.3x − 0.7y) and a smooth
/// direction in (u, p, T): J v against (F(x + δv) − F(x − δv)) / (2δ), δ = 1e-6, as AssemblyTest
/// does (asserted ≤ 1e-7: the FD's truncation δ² |F'''| and round-off ε |F| / δ, below 1e-8 of |J v|).
double jacobianError(const ThermalProblem& problem, double T0, double T1) {
  const std::function<double(double, double)> temperature = [=](double x, double y) {
    return T0 + 0.3 * T1 * std::sin(1.3 * x - 0.7 * y);
  };
  const Field direction = [](double x, double y) {
    return std::array<double, 3>{std::cos(0.7 * x + 2.0 * y), std::sin(1.9 * x - 0.5 * y), std::cos(1.2 * x * y)};
  };
  const std::function<double(double, double)> temperatureDirection = [](double x, double y) { return std::cos(x + y); };
  auto x = problem.vector(), v = problem.vector(), jv = problem.vector(), fp = problem.vector();
  interpolate(problem.mesh, *problem.dofMap, kSmooth, temperature, *x);
  problem.bcs->imposeOnSolution(*x);
  interpolate(problem.mesh, *problem.dofMap, direction, temperatureDirection, *v);
  jacobianAndDifference(*problem.assembler, *x, *v, 1e-6, *jv, *fp);
  fp->update(-1.0, *jv, 1.0);
  return fp->normInf() / jv->normInf();
}

TEUCHOS_UNIT_TEST(ThermoMechanicalKernel, JacobianMatchesFiniteDifferences) {
  const auto comm = worldComm();
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric})
      for (double rhoC : {1.0, 1e3}) {
        const ThermalProblem problem(makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3), generalConditions(),
                                     makePhysics(geometry, kNonlinear, 0.1, 0.3, -0.7), comm, properties(rhoC));
        const double err = jacobianError(problem, 1.0, 1.0);
        out << cellTypeName(type) << (geometry == Geometry::Axisymmetric ? ", axisymmetric" : ", plane")
            << ", rho c = " << rhoC << ": |Jv - FD|inf / |Jv|inf = " << err << "\n";
        TEST_COMPARE(err, <=, 1e-7);
      }
}

TEUCHOS_UNIT_TEST(ThermoMechanicalKernel, TemperatureDependentLawJacobianMatchesFiniteDifferences) {
  // Sellars–Tegart read at each cell's temperature by the flow rows and by the heating: the
  // Jacobian's ∂R_u/∂T and ∂R_T/∂T through σ̄(T) against central differences, as above. Q/(R T) ≈ 25 at T ≈ 700: σ̄ changes by about 3 % per kelvin, a stiff coupling.
  const auto comm = worldComm();
  MaterialParameters<double> law;
  law.law = kMaterialLawIndex<SellarsTegart>;
  for (int i = 0; i < SellarsTegart::kNumParameters; ++i) law.values[i] = SellarsTegart::kParameters[i].defaultValue;
  law.cutoff = 1e-2;
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
      FlowPhysics physics = makePhysics(geometry, kNonlinear, 0.1, 0.3, -0.7);
      physics.material = law;
      const ThermalProblem problem(makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3), generalConditions(), physics,
                                   comm, properties(1.0));
      const double err = jacobianError(problem, 700.0, 50.0);
      out << cellTypeName(type) << (geometry == Geometry::Axisymmetric ? ", axisymmetric" : ", plane")
          << ", Sellars-Tegart: |Jv - FD|inf / |Jv|inf = " << err << "\n";
      TEST_COMPARE(err, <=, 1e-7);
    }
}

TEUCHOS_UNIT_TEST(ThermoMechanicalKernel, LinearTemperatureWithoutFlowIsExact) {
  // u = 0 (all velocities prescribed 0), T prescribed on the boundary nodes: one Newton step on
  // the linear T rows (the flow rows are satisfied) gives the nodal T, which must be linear.
  const auto comm = worldComm();
  const std::function<double(double, double)> linear = [](double x, double y) { return 2.0 - 0.4 * x + 0.9 * y; };
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    // Held on three sides, traction-free on the fourth: u = 0, p = 0 solve the flow rows.
    const ParameterList held = bcList({{"top", "Velocity", {{"Velocity X", 0.0}, {"Velocity Y", 0.0}}},
                                       {"bottom", "Velocity", {{"Velocity X", 0.0}, {"Velocity Y", 0.0}}},
                                       {"left", "Velocity", {{"Velocity X", 0.0}, {"Velocity Y", 0.0}}},
                                       {"right", "Traction", {}}});
    ThermalProblem problem(makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3), held,
                           makePhysics(Geometry::PlaneStrain, kNonlinear, 0.1, 0.0, 0.0), comm, properties(1.0));
    const DofMap& d = *problem.dofMap;
    const int t = d.fields().component("Temperature");
    std::vector<Assembler::PrescribedValue> values;
    for (GO node : boundaryNodes(problem.mesh))
      values.push_back({node, t, linear(problem.mesh.coords[node][0], problem.mesh.coords[node][1])});
    problem.assembler->setPrescribedValues(values);
    auto x = problem.vector(), f = problem.vector();
    const Field still = [](double, double) { return std::array<double, 3>{0.0, 0.0, 0.0}; };
    interpolate(problem.mesh, d, still, [](double, double) { return 0.0; }, *x);
    Teuchos::ParameterList linearSolver("Linear Solver");
    linearSolver.validateParametersAndSetDefaults(*validLinearSolverParameters());
    FlowModel model(*problem.assembler, createLinearSolver(linearSolver, *comm));
    auto dx = problem.vector();
    model.residual(*x, *f);
    model.computeJacobian(*x);
    model.solve(*f, *dx);
    x->update(-1.0, *dx, 1.0);
    double err = 0.0;
    {
      auto xv = x->getLocalViewHost(Tpetra::Access::ReadOnly);
      for (LO n = 0; n < d.numOwnedNodes(); ++n) {
        const auto& xy = problem.mesh.coords[d.overlapNodes()[n]];
        err = std::max(err, std::abs(xv(d.dof(n, t), 0) - linear(xy[0], xy[1])));
      }
    }
    err = globalMax(*comm, err);
    out << cellTypeName(type) << ": max |T_h - T| = " << err << "\n";
    TEST_COMPARE(err, <=, 1e-10);
  }
}

}  // namespace
