// Amesos2's KLU2 as shipped (block-triangular pre-ordering + AMD), on one process: the
// "AMD" ordering of the KLU2 solver type, kept for comparison and as a fallback. No
// transposed solve (it throws): see Klu2Amd.cpp.
#pragma once

#include <Amesos2.hpp>

#include "flowform/solvers/LinearSolver.hpp"

namespace flowform {

class Klu2Amd : public LinearSolver {
 public:
  std::string type() const override { return "KLU2"; }
  std::string ordering() const override { return "AMD"; }
  /// Amesos2's KLU2 solves Aᵀ x = b through KLU2's klu_solve, which gives wrong answers on
  /// permuted factors in Trilinos 13.2 (Klu2NestedDissection.cpp).
  bool supportsTranspose() const override { return false; }

 protected:
  void doFactor(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doSolve(const MultiVector& b, MultiVector& x, bool transpose) override;

 private:
  Teuchos::RCP<const CrsMatrix> m_matrix;  ///< the matrix m_solver belongs to
  Teuchos::RCP<Amesos2::Solver<CrsMatrix, MultiVector>> m_solver;
};

}  // namespace flowform
