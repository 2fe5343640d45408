// A second, independent field beside the flow (physics kernels as plug-ins): the passive
// scalar c of AdvectionDiffusionKernel, registered after the flow's fields and assembled by
// its own kernel, on P1 and Q1 meshes, at 1 and 2 ranks, advected by a prescribed w or by
// the flow's u_h (then the kernel reads u and owns c only):
//  - the flow's rows are untouched: at the same flow values, the residual and the Jacobian
//    rows of (u_x, u_y, p) equal those of a flow-only assembly bitwise, entry by entry
//    (matched by node and component: the dof numbers differ), and their entries in the c
//    columns are exactly 0 — the flow does not read c;
//  - the scalar is exact: c = c0 + b x + d y with s = w·∇c and c prescribed on the
//    boundary is reproduced by Newton on the coupled system to 1e-10 (a linear field is in
//    the P1/Q1 space and the kernel's quadrature is exact for it, see the kernel's comment;
//    the solve is direct, so the error is round-off, ~1e-14 here);
//  - advected by u_h, the assembled Jacobian (its c rows have u columns) matches central
//    differences of the assembled residual;
//  - a set of kernels that leaves a field without rows, or owns one twice, is refused.
#include "AssemblyProblem.hpp"

#include "flowform/discretization/FieldRegistry.hpp"
#include "flowform/physics/kernels/AdvectionDiffusionKernel.hpp"
#include "flowform/physics/kernels/FlowKernel.hpp"

namespace {  // AssemblyProblem.hpp's, with its using-declarations

const double kC0 = 0.7, kB = -0.4, kD = 0.9;  // c = c0 + b x + d y

AdvectionDiffusionSettings scalarSettings() {
  AdvectionDiffusionSettings s;
  s.field = "Concentration";
  s.velocity[0] = 1.3;
  s.velocity[1] = -0.6;
  s.diffusivity = 0.5;
  s.source = s.velocity[0] * kB + s.velocity[1] * kD;  // w·∇c
  return s;
}

FieldRegistry flowAndScalar() {
  FieldRegistry fields = FieldRegistry::flow();
  fields.add({"Concentration", 1});
  return fields;
}

/// The flow and the passive scalar: Problem's members with the two-field registry.
using PrescribedScalar = AdvectionDiffusionKernel<AdvectingVelocity::Prescribed>;
using FlowAdvectedScalar = AdvectionDiffusionKernel<AdvectingVelocity::Flow>;

struct TwoFieldProblem {
  Mesh mesh;
  std::unique_ptr<DofMap> dofMap;
  std::unique_ptr<BoundaryConditions> bcs;
  std::unique_ptr<Assembler> assembler;
  std::unique_ptr<FlowModel> model;

  TwoFieldProblem(Mesh m, const ParameterList& bcList, const FlowPhysics& physics, const RCP<const Comm>& comm,
                  AdvectingVelocity velocity = AdvectingVelocity::Prescribed)
      : mesh(std::move(m)) {
    const FieldRegistry fields = flowAndScalar();
    dofMap = std::make_unique<DofMap>(mesh, comm, std::vector<std::array<GO, 2>>{}, fields);
    bcs = std::make_unique<BoundaryConditions>(bcList, mesh, *dofMap);
    assembler = std::make_unique<Assembler>(mesh, *dofMap, *bcs);
    assembler->setPhysics(physics);
    assembler->setKernels({makeCellKernel(FlowKernel{}, fields),
                           velocity == AdvectingVelocity::Prescribed
                               ? makeCellKernel(PrescribedScalar(scalarSettings()), fields)
                               : makeCellKernel(FlowAdvectedScalar(scalarSettings()), fields)});
    Teuchos::ParameterList linear("Linear Solver");
    linear.validateParametersAndSetDefaults(*validLinearSolverParameters());
    model = std::make_unique<FlowModel>(*assembler, createLinearSolver(linear, *comm));
  }
  RCP<Vector> vector() const { return Teuchos::rcp(new Vector(dofMap->ownedMap())); }
};

double exactScalar(double x, double y) { return kC0 + kB * x + kD * y; }

/// Row `row` of J (global ids) as (node, component) → value.
std::map<std::pair<GO, int>, double> rowOf(const FECrsMatrix& J, const DofMap& dofMap, GO row) {
  const size_t n = J.getNumEntriesInGlobalRow(row);
  typename FECrsMatrix::nonconst_global_inds_host_view_type cols("cols", n);
  typename FECrsMatrix::nonconst_values_host_view_type vals("vals", n);
  size_t count = 0;
  J.getGlobalRowCopy(row, cols, vals, count);
  std::map<std::pair<GO, int>, double> entries;
  for (size_t j = 0; j < count; ++j)
    entries[{dofMap.nodeOfGlobalDof(cols(j)), dofMap.fieldOfGlobalDof(cols(j))}] = vals(j);
  return entries;
}

TEUCHOS_UNIT_TEST(FieldKernel, FlowRowsUnchangedByAScalarField) {
  const auto comm = worldComm();
  const std::function<double(double, double)> scalar = [](double x, double y) {
    return 0.3 + std::sin(1.3 * x - 0.7 * y);  // any values: the flow must not see them
  };
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric})
    for (AdvectingVelocity velocity : {AdvectingVelocity::Prescribed, AdvectingVelocity::Flow}) {
      const Mesh mesh = makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3);
      const FlowPhysics physics = makePhysics(geometry, kNonlinear, 0.1, 0.2, -0.3);
      Problem flow(mesh, generalConditions(), physics, comm);
      TwoFieldProblem both(mesh, generalConditions(), physics, comm, velocity);
      auto x1 = flow.vector(), f1 = flow.vector(), x2 = both.vector(), f2 = both.vector();
      interpolate(flow.mesh, *flow.dofMap, kSmooth, *x1);
      interpolate(both.mesh, *both.dofMap, kSmooth, scalar, *x2);
      auto J1 = flow.assembler->createJacobian(), J2 = both.assembler->createJacobian();
      flow.assembler->jacobian(*x1, *J1, f1.get());
      both.assembler->jacobian(*x2, *J2, f2.get());

      // Same partition (it depends on the mesh only): the same owned nodes, in the same order.
      const DofMap &d1 = *flow.dofMap, &d2 = *both.dofMap;
      TEST_EQUALITY(d1.numOwnedNodes(), d2.numOwnedNodes());
      TEST_EQUALITY(d2.numGlobalDofs(), d1.numGlobalDofs() / 3 * 4);
      auto v1 = f1->getLocalViewHost(Tpetra::Access::ReadOnly), v2 = f2->getLocalViewHost(Tpetra::Access::ReadOnly);
      int residualDiffer = 0, jacobianDiffer = 0, coupled = 0;
      double flowScale = 0.0;
      for (LO n = 0; n < d1.numOwnedNodes(); ++n) {
        TEST_EQUALITY(d1.overlapNodes()[n], d2.overlapNodes()[n]);
        const GO node = d1.overlapNodes()[n];
        for (int c = 0; c < kNumFlowComponents; ++c) {
          flowScale = std::max(flowScale, std::abs(v1(d1.dof(n, c), 0)));
          if (v1(d1.dof(n, c), 0) != v2(d2.dof(n, c), 0)) ++residualDiffer;
          auto r1 = rowOf(*J1, d1, d1.globalDof(node, c)), r2 = rowOf(*J2, d2, d2.globalDof(node, c));
          for (const auto& [col, value] : r2) {
            if (col.second >= kNumFlowComponents) {
              if (value != 0.0) ++coupled;  // a c column in a flow row
            } else if (!r1.count(col) || r1[col] != value) {
              ++jacobianDiffer;
            }
          }
          for (const auto& [col, value] : r1)
            if (!r2.count(col)) ++jacobianDiffer;
        }
      }
      out << cellTypeName(type) << (geometry == Geometry::PlaneStrain ? ", plane strain" : ", axisymmetric")
          << (velocity == AdvectingVelocity::Flow ? ", w = u_h" : ", w prescribed") << ": flow rows differing in F: " << residualDiffer << ", in J: " << jacobianDiffer
          << ", nonzero c columns in flow rows: " << coupled << " (max |F_flow| " << flowScale << ")\n";
      TEST_COMPARE(globalMax(*comm, flowScale), >, 0.1);  // a real residual, not zeros compared
      TEST_EQUALITY(globalMax(*comm, residualDiffer), 0.0);
      TEST_EQUALITY(globalMax(*comm, jacobianDiffer), 0.0);
      TEST_EQUALITY(globalMax(*comm, coupled), 0.0);
    }
}

TEUCHOS_UNIT_TEST(FieldKernel, LinearScalarIsExact) {
  const auto comm = worldComm();
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4}) {
    TwoFieldProblem problem(makeMesh(type, 8, 5, 0.2, 0.0, 2.0, 1.0, 0.25, 0.3), generalConditions(),
                            makePhysics(Geometry::PlaneStrain, kNewtonian, 0.1, 0.0, 0.0), comm);
    const int cComponent = problem.dofMap->fields().component("Concentration");
    std::vector<Assembler::PrescribedValue> dirichlet;
    for (GO node : boundaryNodes(problem.mesh)) {
      const auto& xy = problem.mesh.coords[node];
      dirichlet.push_back({node, cComponent, exactScalar(xy[0], xy[1])});
    }
    problem.assembler->setPrescribedValues(dirichlet);

    // Newton on the coupled system from x = 0: the Newtonian flow and the scalar are both
    // linear, so the first step solves it and the second is round-off.
    auto x = problem.vector(), f = problem.vector(), dx = problem.vector();
    x->putScalar(0.0);
    int steps = 0;
    for (int k = 1; k <= 5; ++k) {
      problem.model->residual(*x, *f);
      problem.model->computeJacobian(*x);
      problem.model->solve(*f, *dx);
      x->update(-1.0, *dx, 1.0);
      steps = k;
      if (dx->normInf() <= 1e-12) break;
    }
    problem.model->residual(*x, *f);
    // The scalar's error at every node, and that the solve left the flow rows solved too.
    double error = 0.0, scale = 0.0;
    {
      auto v = x->getLocalViewHost(Tpetra::Access::ReadOnly);
      const DofMap& d = *problem.dofMap;
      for (LO n = 0; n < d.numOwnedNodes(); ++n) {
        const auto& xy = problem.mesh.coords[d.overlapNodes()[n]];
        error = std::max(error, std::abs(v(d.dof(n, cComponent), 0) - exactScalar(xy[0], xy[1])));
        scale = std::max(scale, std::abs(exactScalar(xy[0], xy[1])));
      }
    }
    error = globalMax(*comm, error);
    scale = globalMax(*comm, scale);
    out << cellTypeName(type) << ": Newton steps " << steps << ", max |c_h − c| = " << error << " (max |c| " << scale
        << "), |F| = " << f->normInf() << "\n";
    TEST_COMPARE(steps, <=, 2);
    TEST_COMPARE(scale, >, 0.5);
    TEST_COMPARE(error, <=, 1e-10);
    TEST_COMPARE(f->normInf(), <=, 1e-10);
  }
}

TEUCHOS_UNIT_TEST(FieldKernel, FlowAdvectedJacobianMatchesFiniteDifferences) {
  // J v against (F(x + δv) − F(x − δv)) / (2δ), δ = 1e-6, as in AssemblyTest's check (same
  // tolerance and reasons: 1e-7 |J v|∞). The c rows are bilinear in (u, c): their FD error is
  // round-off only; dropping the u columns of the c rows (the read-not-owned gather) errs by
  // |w_u·∇c| = O(1), which the second direction (u only) measures on its own.
  const auto comm = worldComm();
  const std::function<double(double, double)> scalar = [](double x, double y) { return std::sin(1.3 * x - 0.7 * y); };
  const Field direction = [](double x, double y) {
    return std::array<double, 3>{std::cos(0.7 * x + 2.0 * y), std::sin(1.9 * x - 0.5 * y), std::cos(1.2 * x * y)};
  };
  const std::function<double(double, double)> scalarDirection = [](double x, double y) { return std::cos(x + y); };
  const std::function<double(double, double)> none = [](double, double) { return 0.0; };
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (bool velocityOnly : {false, true}) {
      TwoFieldProblem problem(makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3), generalConditions(),
                              makePhysics(Geometry::PlaneStrain, kNonlinear, 0.1, 0.3, -0.7), comm, AdvectingVelocity::Flow);
      auto x = problem.vector(), v = problem.vector(), jv = problem.vector(), fp = problem.vector();
      interpolate(problem.mesh, *problem.dofMap, kSmooth, scalar, *x);
      problem.bcs->imposeOnSolution(*x);
      interpolate(problem.mesh, *problem.dofMap, direction, velocityOnly ? none : scalarDirection, *v);
      jacobianAndDifference(*problem.assembler, *x, *v, 1e-6, *jv, *fp);
      // The c rows of J v alone: their size shows the u columns are there.
      double cRows = 0.0;
      {
        auto jvv = jv->getLocalViewHost(Tpetra::Access::ReadOnly);
        const DofMap& d = *problem.dofMap;
        const int cc = d.fields().component("Concentration");
        for (LO n = 0; n < d.numOwnedNodes(); ++n) cRows = std::max(cRows, std::abs(jvv(d.dof(n, cc), 0)));
      }
      cRows = globalMax(*comm, cRows);
      fp->update(-1.0, *jv, 1.0);
      const double err = fp->normInf(), scale = jv->normInf();
      out << cellTypeName(type) << (velocityOnly ? ", direction in u only" : ", direction in u and c")
          << ": |Jv − FD|∞ / |Jv|∞ = " << err / scale << ", max |(Jv)_c| = " << cRows << "\n";
      TEST_COMPARE(err, <=, 1e-7 * scale);
      TEST_COMPARE(cRows, >, 1e-2);
    }
}

TEUCHOS_UNIT_TEST(FieldKernel, EveryFieldOwnedOnce) {
  const auto comm = worldComm();
  const Mesh mesh = makeMesh(CellType::Triangle3, 3, 2, 0.0, 0.0, 1.0, 1.0, 0.0);
  const FieldRegistry fields = flowAndScalar();
  DofMap dofMap(mesh, comm, {}, fields);
  BoundaryConditions bcs(bcList({}), mesh, dofMap);
  Assembler assembler(mesh, dofMap, bcs);  // the flow kernel alone: c has no rows
  Vector x(dofMap.ownedMap()), f(dofMap.ownedMap());
  TEST_THROW(assembler.residual(x, f), std::logic_error);
  TEST_THROW(assembler.setKernels({makeCellKernel(FlowKernel{}, fields), makeCellKernel(FlowKernel{}, fields)}),
             std::invalid_argument);
  assembler.setKernels({makeCellKernel(FlowKernel{}, fields), makeCellKernel(PrescribedScalar({}), fields)});
  TEST_NOTHROW(assembler.residual(x, f));
  AdvectionDiffusionSettings unknown;
  unknown.field = "Temperature";
  TEST_THROW(makeCellKernel(PrescribedScalar(unknown), fields), std::invalid_argument);
}

}  // namespace
