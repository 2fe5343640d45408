#include "flowform/solvers/LinearSolver.hpp"

#include <Teuchos_TimeMonitor.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace flowform {

LinearSolver::~LinearSolver() = default;

void LinearSolver::factor(const Teuchos::RCP<const CrsMatrix>& A) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: factorization"));
  ++m_numFactorizations;
  doFactor(A);
}

void LinearSolver::solve(const MultiVector& b, MultiVector& x) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: linear solve"));
  m_numSolves += static_cast<int>(b.getNumVectors());  // one back-substitution per column
  doSolve(b, x, false);
}

void LinearSolver::solveTranspose(const MultiVector& b, MultiVector& x) {
  if (!supportsTranspose())
    throw std::runtime_error("the linear solver " + type() + " (" + ordering() + ") has no transposed solve");
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: linear solve"));
  m_numSolves += static_cast<int>(b.getNumVectors());
  doSolve(b, x, true);
}

void LinearSolver::report(nlohmann::json& out) const {
  out["type"] = type();
  out["ordering"] = ordering();
  out["factorizations"] = m_numFactorizations;
  out["solves"] = m_numSolves;
  // Fill of the last factorization (rank 0 holds it), where the solver reports it.
  if (factorEntries() > 0.0) out["factor_entries"] = factorEntries();
}

}  // namespace flowform
