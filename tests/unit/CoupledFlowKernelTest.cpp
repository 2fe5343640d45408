// The flow and the fields it carries in one kernel (physics/kernels/CoupledFlowKernel.hpp):
//  - its assembled Jacobian (T rows with u columns: convection, heating, SUPG's τ(u)) matches
//    central differences of the assembled residual, on P1 and Q1 meshes, plane and
//    axisymmetric, in the diffusive (ρc = 1) and convective (ρc = 1e3: cell Péclet ≫ 1) regimes;
//  - with a temperature-dependent law (Sellars–Tegart) the same, the flow rows now with T columns;
//  - with a Strain field and Hensel–Spittel read at each cell's strain (and temperature): the ε rows
//    (convection, the source e_r − e0, SUPG's τ(u)) and the flow rows' ε columns the same;
//  - without flow (u = 0: held on three sides, free on the fourth) and with T prescribed on the boundary to T = a + b x + d y in plane
//    strain, a linear T is reproduced (no heating, no convection, diffusion exact for linear T).
#include "AssemblyProblem.hpp"

#include <type_traits>

#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/physics/kernels/CoupledFlowKernel.hpp"

namespace {  // AssemblyProblem.hpp's, with its using-declarations

template <bool Thermal, bool Strain>
FieldRegistry coupledFields() {
  FieldRegistry fields = FieldRegistry::flow();
  if (Thermal) fields.add({"Temperature", 1});
  if (Strain) fields.add({"Strain", 1});
  return fields;
}

struct ThermalProblem {
  Mesh mesh;
  std::unique_ptr<DofMap> dofMap;
  std::unique_ptr<BoundaryConditions> bcs;
  std::unique_ptr<Assembler> assembler;

  /// The flow with the fields of CoupledFlowKernel<Thermal, Strain> (the temperature alone by default).
  template <bool Thermal = true, bool Strain = false>
  ThermalProblem(Mesh m, const ParameterList& bcList, const FlowPhysics& physics, const RCP<const Comm>& comm,
                 const ThermalProperties& properties, std::bool_constant<Thermal> = {},
                 std::bool_constant<Strain> = {})
      : mesh(std::move(m)) {
    const FieldRegistry fields = coupledFields<Thermal, Strain>();
    dofMap = std::make_unique<DofMap>(mesh, comm, std::vector<std::array<GO, 2>>{}, fields);
    bcs = std::make_unique<BoundaryConditions>(bcList, mesh, *dofMap);
    assembler = std::make_unique<Assembler>(mesh, *dofMap, *bcs);
    FlowPhysics withProperties = physics;
    withProperties.thermal = properties;
    assembler->setPhysics(withProperties);
    assembler->setKernels({makeCellKernel(CoupledFlowKernel<Thermal, Strain>{}, fields)});
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

/// |J v − FD|∞ / |J v|∞ at a smooth state with T = T0 + 0.3 T1 sin(1.3x − 0.7y) (and a strain
/// ε = 0.6 + 0.4 cos(0.9x + 1.1y)) and a smooth direction in (u, p, T, ε): J v against
/// (F(x + δv) − F(x − δv)) / (2δ), δ = 1e-6, as AssemblyTest does (asserted ≤ 1e-7: the FD's
/// truncation δ² |F‴| and round-off ε |F| / δ, below 1e-8 of |J v|).
double jacobianError(const ThermalProblem& problem, double T0, double T1) {
  const DofMap& d = *problem.dofMap;
  const int t = d.fields().componentOf("Temperature");
  // x ← the flow `flow`, the temperature and the strain at the nodes (owned dofs).
  const auto fill = [&](Vector& x, const Field& flow, const std::function<double(double, double)>& temperature,
                        const std::function<double(double, double)>& strain) {
    auto v = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const Map& map = *x.getMap();
    for (size_t i = 0; i < x.getLocalLength(); ++i) {
      const GO g = map.getGlobalElement(static_cast<LO>(i));
      const auto& xy = problem.mesh.coords[d.nodeOfGlobalDof(g)];
      const int c = d.fieldOfGlobalDof(g);
      v(i, 0) = c < kNumFlowComponents ? flow(xy[0], xy[1])[c]
                : c == t               ? temperature(xy[0], xy[1])
                                       : strain(xy[0], xy[1]);
    }
  };
  const Field direction = [](double x, double y) {
    return std::array<double, 3>{std::cos(0.7 * x + 2.0 * y), std::sin(1.9 * x - 0.5 * y), std::cos(1.2 * x * y)};
  };
  auto x = problem.vector(), v = problem.vector(), jv = problem.vector(), fp = problem.vector();
  fill(*x, kSmooth, [=](double x, double y) { return T0 + 0.3 * T1 * std::sin(1.3 * x - 0.7 * y); },
       [](double x, double y) { return 0.6 + 0.4 * std::cos(0.9 * x + 1.1 * y); });
  problem.bcs->imposeOnSolution(*x);
  fill(*v, direction, [](double x, double y) { return std::cos(x + y); },
       [](double x, double y) { return std::sin(0.8 * x - 1.3 * y); });
  jacobianAndDifference(*problem.assembler, *x, *v, 1e-6, *jv, *fp);
  fp->update(-1.0, *jv, 1.0);
  return fp->normInf() / jv->normInf();
}

TEUCHOS_UNIT_TEST(CoupledFlowKernel, JacobianMatchesFiniteDifferences) {
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

TEUCHOS_UNIT_TEST(CoupledFlowKernel, TemperatureDependentLawJacobianMatchesFiniteDifferences) {
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

TEUCHOS_UNIT_TEST(CoupledFlowKernel, StrainFieldJacobianMatchesFiniteDifferences) {
  // Hensel–Spittel read at each cell's regularized strain ε̃ = sqrt(ε² + ε_min²) (m2 = −0.1,
  // m4 = −0.05, m7 = 0.3: σ̄ changes by about 20 % over the state's strains) and, with the
  // Temperature field too, at its temperature: the flow rows' ε (and T) columns and the ε rows'
  // u columns (u·∇ε, the source e_r − e0, τ(u)) against central differences, as above. ε_min =
  // 0.5 and ε_max = 0.9 put parts of the state (ε from 0.2 to 1) on both bends of the strain the
  // law reads.
  const auto comm = worldComm();
  MaterialParameters<double> law;
  law.law = kMaterialLawIndex<HenselSpittel>;
  for (int i = 0; i < HenselSpittel::kNumParameters; ++i) law.values[i] = HenselSpittel::kParameters[i].defaultValue;
  law.values[HenselSpittel::kM7] = 0.3;
  law.cutoff = 1e-2;
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric})
      for (bool thermal : {false, true}) {
        FlowPhysics physics = makePhysics(geometry, kNonlinear, 0.1, 0.3, -0.7);
        physics.material = law;
        physics.strainField.minimumStrain = 0.5;
        physics.strainField.maximumStrain = 0.9;
        const Mesh mesh = makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3);
        const double err =
            thermal ? jacobianError(ThermalProblem(mesh, generalConditions(), physics, comm, properties(1.0),
                                                   std::true_type{}, std::true_type{}),
                                    1300.0, 50.0)
                    : jacobianError(ThermalProblem(mesh, generalConditions(), physics, comm, properties(1.0),
                                                   std::false_type{}, std::true_type{}),
                                    1300.0, 50.0);
        out << cellTypeName(type) << (geometry == Geometry::Axisymmetric ? ", axisymmetric" : ", plane")
            << (thermal ? ", T and eps" : ", eps") << ", Hensel-Spittel: |Jv - FD|inf / |Jv|inf = " << err << "\n";
        TEST_COMPARE(err, <=, 1e-7);
      }
}

TEUCHOS_UNIT_TEST(CoupledFlowKernel, LinearTemperatureWithoutFlowIsExact) {
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
