#include "flowform/solvers/Klu2Amd.hpp"

#include <stdexcept>

namespace flowform {

void Klu2Amd::doFactor(const Teuchos::RCP<const CrsMatrix>& A) {
  // Amesos2 keeps the symbolic factorization (AMD) of the matrix object it was made with.
  if (m_solver.is_null() || m_matrix.get() != A.get()) {
    m_matrix = A;
    m_solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", A);
    m_solver->symbolicFactorization();
  }
  try {
    m_solver->numericFactorization();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("KLU2 numeric factorization failed (singular Jacobian?): ") + e.what());
  }
}

void Klu2Amd::doSolve(const MultiVector& b, MultiVector& x, bool transpose) {
  if (m_solver.is_null()) throw std::logic_error("Klu2Amd::solve before a successful factor()");
  if (transpose) throw std::logic_error("Klu2Amd has no transposed solve (supportsTranspose)");
  m_solver->solve(Teuchos::ptrFromRef(x), Teuchos::ptrFromRef(b));
}

}  // namespace flowform
