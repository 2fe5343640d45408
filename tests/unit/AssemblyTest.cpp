// The assembled problem (Assembler + DofMap + BoundaryConditions), on 1 and 2 ranks:
//  - patch test: at the nodal interpolant of a linear, divergence-free velocity with a
//    linear pressure and the body force f = grad p that balances it, every row of an
//    interior node vanishes (P1/Q1 on distorted meshes, plane strain and axisymmetric,
//    Newtonian and nonlinear — constant D means constant μ);
//  - exact solves: boundary-value problems whose exact solution is such a field (Couette
//    shear, planar extension with symmetry lines, axisymmetric squeeze) are reproduced to
//    round-off by Newton with the assembled Jacobian;
//  - the assembled Jacobian against central differences of the assembled residual, with
//    velocity, inclined-symmetry and traction conditions;
//  (parallel = serial: AssemblyParallelTest.cpp)
#include "AssemblyProblem.hpp"

namespace {  // AssemblyProblem.hpp's, with its using-declarations

// ---------------------------------------------------------------------------------------
// Patch test
// ---------------------------------------------------------------------------------------

// Round-off only: with the quadrature exact for these fields (P1: constant and linear
// integrands on the centroid / 3-point rule; Q1: integrands of degree ≤ 3 per reference
// direction for 2×2 Gauss, also axisymmetric where every term carries r), an interior
// row is a sum of ≤ 8 cell contributions of size ≤ S (S = the largest boundary momentum
// row, |σ| h) that cancel: ≈ 10 eps S ≈ 2e-15 S. Continuity rows are smaller still
// (h²|grad u| ≤ h|σ| here). 1e-12 leaves a 500× margin; a missing term or a wrong
// quadrature breaks the cancellation at O(h^k) ≈ 1e-3..1 of S.
constexpr double kPatchTol = 1e-12;

TEUCHOS_UNIT_TEST(Assembly, PatchTestInteriorResidualVanishes) {
  const auto comm = worldComm();
  // Plane strain: u = (a x + b y + c, d x − a y + e), p = p0 + px x + py y, f = grad p.
  const double a = 0.4, b = -0.7, c = 0.2, d = 0.3, e = -0.5, p0 = 0.8, px = -0.6, py = 0.45;
  const Field plane = [=](double x, double y) {
    return std::array<double, 3>{a * x + b * y + c, d * x - a * y + e, p0 + px * x + py * y};
  };
  // Axisymmetric (x = r, y = z): u = (a r, −2a z + e), div u = a + a − 2a = 0, D constant
  // with D_rr = D_θθ so the hoop term vanishes; p = p0 + pr r + pz z, f = grad p.
  const Field axi = [=](double r, double z) {
    return std::array<double, 3>{a * r, -2 * a * z + e, p0 + px * r + py * z};
  };
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric})
      for (const auto& material : {kNewtonian, kNonlinear}) {
        // Axisymmetric meshes touch the axis (x0 = 0); the inclined top tests general cells.
        const Mesh mesh = makeMesh(type, 6, 5, 0.0, -0.5, 2.0, 1.0, 0.25, 0.3);
        Problem problem(mesh, bcList({}), makePhysics(geometry, material, 0.1, px, py), comm);
        auto x = problem.vector(), f = problem.vector();
        interpolate(problem.mesh, *problem.dofMap, geometry == Geometry::PlaneStrain ? plane : axi, *x);
        problem.assembler->residual(*x, *f);

        const auto onBoundary = boundaryNodes(problem.mesh);
        auto fv = f->getLocalViewHost(Tpetra::Access::ReadOnly);
        const Map& map = *f->getMap();
        double boundaryMax = 0.0, interiorMax = 0.0;
        for (size_t i = 0; i < f->getLocalLength(); ++i) {
          const GO g = map.getGlobalElement(static_cast<LO>(i));
          if (onBoundary.count(problem.dofMap->nodeOfGlobalDof(g))) {
            if (problem.dofMap->fieldOfGlobalDof(g) != kP) boundaryMax = std::max(boundaryMax, std::abs(fv(i, 0)));
          } else {
            interiorMax = std::max(interiorMax, std::abs(fv(i, 0)));
          }
        }
        boundaryMax = globalMax(*comm, boundaryMax);
        interiorMax = globalMax(*comm, interiorMax);
        out << caseName(type, geometry, material) << ": max interior |F| = " << interiorMax
            << ", max boundary momentum |F| = " << boundaryMax << "\n";
        TEST_COMPARE(boundaryMax, >, 0.1);  // the scale is the field's, not round-off
        TEST_COMPARE(interiorMax, <=, kPatchTol * boundaryMax);
      }
}

// ---------------------------------------------------------------------------------------
// Exact solves
// ---------------------------------------------------------------------------------------

/// Newton on the problem from x: x −= J⁻¹ F(x) until the step is below 1e-12 (round-off
/// for dofs of size ~1). Returns the number of steps, or maxSteps + 1 if it did not stop.
int newton(Problem& problem, Vector& x, int maxSteps) {
  auto f = problem.vector(), dx = problem.vector();
  for (int k = 1; k <= maxSteps; ++k) {
    problem.model->residual(x, *f);
    problem.model->computeJacobian(x);
    problem.model->solve(*f, *dx);
    x.update(-1.0, *dx, 1.0);
    if (dx->normInf() <= 1e-12) return k;
  }
  return maxSteps + 1;
}

/// max |x − x_exact| over all dofs and ranks.
double errorTo(const Problem& problem, const Vector& x, const Field& exact) {
  auto xe = problem.vector();
  interpolate(problem.mesh, *problem.dofMap, exact, *xe);
  xe->update(1.0, x, -1.0);
  return xe->normInf();
}

/// A boundary-value problem whose exact solution is `exact` (in the discrete space).
struct ExactCase {
  std::string name;
  Geometry geometry;
  Field exact;
  std::vector<Group> groups;
  double rotation = 0.0;  ///< the mesh and the whole case turned by this angle about 0
};

/// `ec` turned by θ about the origin: u'(x) = R u(Rᵀx), p'(x) = p(Rᵀx); prescribed
/// velocity vectors and tractions turn with it (a group must give both velocity
/// components: one component alone is not a condition in the turned frame), symmetry
/// lines turn with the mesh. Every side of the turned rectangle is inclined, so symmetry
/// conditions act on both velocity components of a node.
ExactCase turned(ExactCase ec, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  const Field ref = ec.exact;
  ec.exact = [=](double x, double y) {
    const auto v = ref(c * x + s * y, -s * x + c * y);
    return std::array<double, 3>{c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]};
  };
  for (auto& g : ec.groups) {
    auto& v = g.values;
    for (const std::string kind : {"Velocity", "Traction"}) {
      const std::string X = kind + " X", Y = kind + " Y";
      if (!v.count(X) && !v.count(Y)) continue;
      if (kind == "Velocity" && !(v.count(X) && v.count(Y)))
        throw std::logic_error("turned(): group '" + g.name + "' gives one velocity component only");
      const double vx = v.count(X) ? v[X] : 0.0, vy = v.count(Y) ? v[Y] : 0.0;
      v[X] = c * vx - s * vy;
      v[Y] = s * vx + c * vy;
    }
  }
  ec.name += " (turned)";
  ec.rotation = theta;
  return ec;
}

/// The exact cases for a material (their tractions depend on μ). On [0, 2] × [0, 1]:
///   Couette: u = (b y + c, e), p = p0; walls y = 0, 1 move with the flow; the ends carry
///     t = σ n, σ = [[−p0, μ b], [μ b, −p0]].
///   Extension: u = (a x, −a y), p = p0; symmetry lines x = 0 and y = 0; u_y = −a on the
///     top with zero shear traction; t = (2 μ a − p0, 0) on x = 2.
///   Axisymmetric squeeze (x = r): u = (a r, −2a z + e), p = p0; axis r = 0 (symmetry);
///     u_z = e on z = 0 with zero shear traction; t = (0, σ_zz) = (0, −4 μ a − p0) on z = 1
///     (an edge along which r varies, so the 2π r weight of the traction integral is
///     tested) and t = (2 μ a − p0, 0) on r = 2.
///   Plane-strain cases turned by 30° (see turned()): Couette, and the extension with
///     t = σ n = (0, −2 μ a − p0) on the top instead of the velocity.
std::vector<ExactCase> exactCases(const MaterialParameters<double>& m) {
  const double a = 0.6, b = 0.8, c = 0.3, e = -0.2, p0 = 0.7;
  const double muShear = viscosityOf(2 * (b / 2) * (b / 2), m);  // D:D = 2 D_xy²
  const double muExt = viscosityOf(2 * a * a, m);                // D_xx² + D_yy²
  const double muAxi = viscosityOf(6 * a * a, m);                // a² + 4a² + a²
  std::vector<ExactCase> cases = {
      {"Couette", Geometry::PlaneStrain,
       [=](double, double y) { return std::array<double, 3>{b * y + c, e, p0}; },
       {{"bottom", "Velocity", {{"Velocity X", c}, {"Velocity Y", e}}},
        {"top", "Velocity", {{"Velocity X", b + c}, {"Velocity Y", e}}},
        {"left", "Traction", {{"Traction X", p0}, {"Traction Y", -muShear * b}}},
        {"right", "Traction", {{"Traction X", -p0}, {"Traction Y", muShear * b}}}}},
      {"extension", Geometry::PlaneStrain,
       [=](double x, double y) { return std::array<double, 3>{a * x, -a * y, p0}; },
       {{"left", "Symmetry", {}},
        {"bottom", "Symmetry", {}},
        {"top", "Velocity", {{"Velocity Y", -a}}},
        {"right", "Traction", {{"Traction X", 2 * muExt * a - p0}}}}},
      {"axisymmetric squeeze", Geometry::Axisymmetric,
       [=](double r, double z) { return std::array<double, 3>{a * r, -2 * a * z + e, p0}; },
       {{"left", "Symmetry", {}},
        {"bottom", "Velocity", {{"Velocity Y", e}}},
        {"top", "Traction", {{"Traction Y", -4 * muAxi * a - p0}}},
        {"right", "Traction", {{"Traction X", 2 * muAxi * a - p0}}}}},
  };
  const double theta = M_PI / 6;
  cases.push_back(turned(cases[0], theta));
  ExactCase extension = cases[1];
  extension.groups[2] = {"top", "Traction", {{"Traction Y", -2 * muExt * a - p0}}};
  cases.push_back(turned(extension, theta));
  return cases;
}

// The exact field is a discrete solution (patch test + exact boundary integrals of the
// constant tractions), so the computed one differs from it only by the direct solver's
// round-off, of order cond(J)·eps on dofs of size ≤ 1.6 (observed: ≤ 4e-15 on these
// 162-dof systems). Tolerance 1e-10 allows cond(J) up to ~1e5 without a spurious
// failure; a wrong traction, constraint or kernel term shows as an O(h..1) error.
constexpr double kSolveTol = 1e-10;

TEUCHOS_UNIT_TEST(Assembly, ExactLinearFlowsAreReproduced) {
  const auto comm = worldComm();
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (const auto& material : {kNewtonian, kNonlinear})
      for (const auto& ec : exactCases(material)) {
        Mesh mesh = makeMesh(type, 8, 5, 0.0, 0.0, 2.0, 1.0, 0.25);
        for (auto& xy : mesh.coords) {
          const double c = std::cos(ec.rotation), s = std::sin(ec.rotation);
          xy = {c * xy[0] - s * xy[1], s * xy[0] + c * xy[1]};
        }
        Problem problem(mesh, bcList(ec.groups), makePhysics(ec.geometry, material, 0.1, 0.0, 0.0), comm);
        auto x = problem.vector();
        int iterations = 0;
        if (isNewtonian(material)) {
          // Linear: the first step from the constrained zero field solves it; the second
          // is round-off.
          problem.bcs->imposeOnSolution(*x);
          iterations = newton(problem, *x, 10);
          TEST_COMPARE(iterations, <=, 2);
        } else {
          // Newton from the exact field plus a smooth 10 % disturbance of all dofs
          // (constraints re-imposed); quadratic convergence needs the exact tangent.
          const Field start = [&](double x, double y) {
            auto v = ec.exact(x, y);
            for (int c = 0; c < 3; ++c) v[c] += 0.1 * std::sin(2.1 * x + 1.3 * y + c);
            return v;
          };
          interpolate(problem.mesh, *problem.dofMap, start, *x);
          problem.bcs->imposeOnSolution(*x);
          iterations = newton(problem, *x, 10);
          TEST_COMPARE(iterations, <=, 8);
        }
        const double err = errorTo(problem, *x, ec.exact);
        out << ec.name << ", " << caseName(type, ec.geometry, material) << ": " << iterations
            << " Newton step(s), max |u_h − u| = " << err << "\n";
        TEST_COMPARE(err, <=, kSolveTol);
      }
}

// ---------------------------------------------------------------------------------------
// Assembled Jacobian vs finite differences
// ---------------------------------------------------------------------------------------

TEUCHOS_UNIT_TEST(Assembly, JacobianMatchesDirectionalFiniteDifferences) {
  // J v against (F(x + δv) − F(x − δv)) / (2δ) for a smooth direction v of size 1, δ = 1e-6:
  // truncation (δ²/6)|F'''[v,v,v]| ≲ 1e-12 × 10² |J v| (strain rates O(1) ≫ e0, so each
  // derivative of μ brings O(1)), round-off eps |F| / δ ≈ 2e-10 |F|. Tolerance 1e-7 |J v|∞:
  // 100× above both; a constraint row or traction term missing from J, or a kernel
  // derivative dropped, errs by O(1e-2..1).
  const auto comm = worldComm();
  const Field direction = [](double x, double y) {
    return std::array<double, 3>{std::cos(0.7 * x + 2.0 * y), std::sin(1.9 * x - 0.5 * y), std::cos(1.2 * x * y)};
  };
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
      Problem problem(makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3), generalConditions(),
                      makePhysics(geometry, kNonlinear, 0.1, 0.3, -0.7), comm);
      auto x = problem.vector(), v = problem.vector(), jv = problem.vector(), fp = problem.vector();
      interpolate(problem.mesh, *problem.dofMap, kSmooth, *x);
      problem.bcs->imposeOnSolution(*x);
      interpolate(problem.mesh, *problem.dofMap, direction, *v);
      jacobianAndDifference(*problem.assembler, *x, *v, 1e-6, *jv, *fp);
      fp->update(-1.0, *jv, 1.0);
      const double err = fp->normInf(), scale = jv->normInf();
      out << caseName(type, geometry, kNonlinear) << ": |Jv − FD|∞ / |Jv|∞ = " << err / scale << "\n";
      TEST_COMPARE(err, <=, 1e-7 * scale);
    }
}

TEUCHOS_UNIT_TEST(Assembly, ConstrainingTheReactionsGivesTheResidual) {
  // Assembler::constrainResidual on the unconstrained residual against the constrained assembly:
  // the row operations are linear, so only the order of the sums differs (round-off, 1e-13 of
  // |F|∞); a constraint kind or a traction handled differently errs by O(|F|).
  const auto comm = worldComm();
  for (CellType type : {CellType::Triangle3, CellType::Quadrilateral4})
    for (Geometry geometry : {Geometry::PlaneStrain, Geometry::Axisymmetric}) {
      Problem problem(makeMesh(type, 6, 4, 0.2, 0.0, 2.0, 1.0, 0.2, 0.3), generalConditions(),
                      makePhysics(geometry, kNonlinear, 0.1, 0.3, -0.7), comm);
      auto x = problem.vector(), constrained = problem.vector(), reactions = problem.vector();
      interpolate(problem.mesh, *problem.dofMap, kSmooth, *x);
      problem.bcs->imposeOnSolution(*x);
      problem.assembler->residual(*x, *constrained);
      problem.assembler->residual(*x, *reactions, false);
      problem.assembler->constrainResidual(*x, *reactions);
      reactions->update(-1.0, *constrained, 1.0);
      const double err = reactions->normInf(), scale = constrained->normInf();
      out << caseName(type, geometry, kNonlinear) << ": |constrain(reactions) − F|∞ / |F|∞ = " << err / scale << "\n";
      TEST_COMPARE(scale, >, 0.0);
      TEST_COMPARE(err, <=, 1e-13 * scale);
    }
}

}  // namespace
