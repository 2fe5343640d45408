// The direct solvers of the registry (LinearSolverRegistry: KLU2 with nested dissection and
// with AMD, behind a GatheredSolver on 2 ranks; MUMPS with both orderings, on the
// distributed matrix), on matrices whose solution is known because
// b = A x_exact (and b = Aᵀ x_exact for the transposed solve):
//  - a non-symmetric convection–diffusion operator on a grid, several right-hand sides,
//    solved with A and with Aᵀ from the same factors;
//  - new values on the same pattern (the kept ordering must take the new numbers);
//  - a saddle-point matrix with zero diagonal (only pivoting off the diagonal factors it);
//  - a new pattern with the same solver (the ordering must be redone, not reused);
//  - a singular matrix: a clear std::runtime_error on every rank, no abort.
// Tolerance: the operators are well conditioned (κ ≲ 10³ for the 30×30 grid), so the
// backward-stable LU gives a relative error of order κ·ε ≈ 10⁻¹³; 10⁻¹⁰ leaves room for
// the pivot growth KLU2's threshold pivoting (tolerance 10⁻³) allows, and a wrong
// permutation or stale values give errors of order 1.
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "flowform/solvers/LinearSolver.hpp"
#include "flowform/solvers/LinearSolverRegistry.hpp"

namespace {

using namespace flowform;
using Teuchos::RCP;
/// Row gid -> its entries (gid, value).
using RowFunction = std::function<std::vector<std::pair<GO, double>>(GO)>;

constexpr double kTolerance = 1e-10;

RCP<const CrsMatrix> buildMatrix(GO n, const RowFunction& row) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = Teuchos::rcp(new Map(n, 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, 7));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO i = map->getGlobalElement(static_cast<LO>(l));
    std::vector<GO> cols;
    std::vector<double> vals;
    for (const auto& [j, v] : row(i)) {
      cols.push_back(j);
      vals.push_back(v);
    }
    A->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

/// Convection–diffusion on a grid m points wide, n points in all (5-point, upwinded
/// convection (1, 0.5)·∇ with Péclet number ~1): non-symmetric, diagonally dominant;
/// `shift` adds to the diagonal.
RowFunction convectionDiffusion(GO n, GO m, double shift) {
  return [n, m, shift](GO i) {
    const GO r = i / m, c = i % m;  // row, column of the grid
    std::vector<std::pair<GO, double>> e{{i, 4.0 + 1.5 + shift}};
    if (c > 0) e.push_back({i - 1, -1.0 - 1.0});
    if (c < m - 1) e.push_back({i + 1, -1.0});
    if (r > 0) e.push_back({i - m, -1.0 - 0.5});
    if (i + m < n) e.push_back({i + m, -1.0});
    return e;
  };
}

/// [[D, B], [Bᵀ, 0]] of size 2h, D = diag(2 + i mod 3), B = 1.5 I − (the shift by one):
/// rows h.. have a (stored) zero diagonal, so only off-diagonal pivots factor it.
RowFunction saddlePoint(GO h) {
  return [h](GO i) {
    std::vector<std::pair<GO, double>> e;
    if (i < h) {
      e.push_back({i, 2.0 + static_cast<double>(i % 3)});
      e.push_back({h + i, 1.5});
      if (i > 0) e.push_back({h + i - 1, -1.0});
    } else {
      const GO k = i - h;
      e.push_back({k, 1.5});
      if (k < h - 1) e.push_back({k + 1, -1.0});
      e.push_back({i, 0.0});
    }
    return e;
  };
}

/// Relative max-norm error of the solutions of A X = A X_exact (or Aᵀ X = Aᵀ X_exact),
/// X_exact with k columns.
double solveError(LinearSolver& solver, const RCP<const CrsMatrix>& A, size_t k, bool transpose = false) {
  MultiVector exact(A->getRowMap(), k), b(A->getRowMap(), k), x(A->getRowMap(), k);
  for (size_t j = 0; j < k; ++j) {
    auto col = exact.getDataNonConst(j);
    for (LO l = 0; l < static_cast<LO>(col.size()); ++l) {
      const double g = static_cast<double>(A->getRowMap()->getGlobalElement(l));
      col[l] = std::sin(0.37 * g + 1.3 * j) + 0.5 * std::cos(0.011 * g * g);
    }
  }
  A->apply(exact, b, transpose ? Teuchos::TRANS : Teuchos::NO_TRANS);
  if (transpose)
    solver.solveTranspose(b, x);
  else
    solver.solve(b, x);
  x.update(-1.0, exact, 1.0);
  std::vector<double> err(k), ref(k);
  x.normInf(Teuchos::ArrayView<double>(err));
  exact.normInf(Teuchos::ArrayView<double>(ref));
  double worst = 0.0;
  for (size_t j = 0; j < k; ++j) worst = std::max(worst, err[j] / ref[j]);
  return worst;
}

/// Every registered solver type with each ordering.
const std::pair<const char*, const char*> kSolvers[] = {
    {"KLU2", "Nested Dissection"}, {"KLU2", "AMD"}, {"MUMPS", "Nested Dissection"}, {"MUMPS", "AMD"}};

/// The registry's solver of that type and ordering, for matrices on the default communicator.
std::unique_ptr<LinearSolver> solverFor(const std::string& type, const std::string& ordering) {
  Teuchos::ParameterList list("Linear Solver");
  list.set("Type", type);
  list.set("Ordering", ordering);
  list.validateParametersAndSetDefaults(*validLinearSolverParameters());
  return createLinearSolver(list, *Teuchos::DefaultComm<int>::getComm());
}

/// With each ordering: one solver factors `matrices` in turn, then solves k right-hand
/// sides with the last one's factors. Checks the error and the counters.
void checkFactorInTurn(const std::vector<RCP<const CrsMatrix>>& matrices, size_t k, Teuchos::FancyOStream& out,
                       bool& success) {
  for (const auto& [type, o] : kSolvers) {
    const auto solver = solverFor(type, o);
    out << solver->type() << ", " << solver->ordering() << "\n";
    TEST_EQUALITY(solver->type(), std::string(type));
    for (const auto& A : matrices) solver->factor(A);
    const double error = solveError(*solver, matrices.back(), k);  // once: TEST_COMPARE evaluates twice
    TEST_COMPARE(error, <, kTolerance);
    if (!solver->supportsTranspose()) {
      // No transposed solve through Amesos2's KLU2 (Klu2Amd.cpp): it must refuse, not answer wrongly.
      MultiVector b(matrices.back()->getRowMap(), 1), x(matrices.back()->getRowMap(), 1);
      TEST_THROW(solver->solveTranspose(b, x), std::runtime_error);
    } else {
      const double transposeError = solveError(*solver, matrices.back(), k, true);
      TEST_COMPARE(transposeError, <, kTolerance);
    }
    TEST_EQUALITY(solver->numFactorizations(), static_cast<int>(matrices.size()));
    TEST_EQUALITY(solver->numSolves(), static_cast<int>(solver->supportsTranspose() ? 2 * k : k));
  }
}

TEUCHOS_UNIT_TEST(LinearSolver, NonSymmetricGridSeveralRightHandSides) {
  checkFactorInTurn({buildMatrix(900, convectionDiffusion(900, 30, 0.0))}, 3, out, success);
}

TEUCHOS_UNIT_TEST(LinearSolver, NewValuesOnTheSamePattern) {
  checkFactorInTurn({buildMatrix(900, convectionDiffusion(900, 30, 0.0)),
                     buildMatrix(900, convectionDiffusion(900, 30, 7.0))},  // same pattern
                    1, out, success);
}

TEUCHOS_UNIT_TEST(LinearSolver, ZeroDiagonalNeedsPivoting) {
  checkFactorInTurn({buildMatrix(400, saddlePoint(200))}, 2, out, success);
}

TEUCHOS_UNIT_TEST(LinearSolver, NewPatternWithTheSameSolver) {
  checkFactorInTurn({buildMatrix(900, convectionDiffusion(900, 30, 0.0)),
                     buildMatrix(900, convectionDiffusion(900, 45, 1.0))},  // a 45 × 20 grid
                    1, out, success);
}

TEUCHOS_UNIT_TEST(LinearSolver, SingularMatrixThrowsOnEveryRank) {
  // Row and column 7 are empty but for a stored zero.
  const auto A = buildMatrix(100, [](GO i) {
    if (i == 7) return std::vector<std::pair<GO, double>>{{7, 0.0}};
    std::vector<std::pair<GO, double>> e{{i, 3.0}};
    if (i > 0 && i - 1 != 7) e.push_back({i - 1, -1.0});
    if (i < 99 && i + 1 != 7) e.push_back({i + 1, -1.0});
    return e;
  });
  for (const auto& [type, o] : kSolvers) {
    out << type << ", " << o << "\n";
    const auto solver = solverFor(type, o);
    std::string message;
    try {
      solver->factor(A);
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
    out << "message: " << message << "\n";
    TEST_ASSERT(message.find("factorization failed") != std::string::npos);
  }
}

}  // namespace
