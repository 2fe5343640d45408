// The direct solver of the Newton, sensitivity (and later adjoint) systems: the interface
// every implementation offers. Factoring is its own step, after assembly: factor(A) once,
// then any number of solves with several right-hand sides, A x = b or Aᵀ x = b, with the
// same factors. The counters and the summary report live here, once for all solvers.
//
// Implementations (one file each, registered in LinearSolverRegistry.cpp, chosen by the
// validated Solver → Linear Solver sublist):
//   Klu2NestedDissection  KLU2 with a METIS nested-dissection ordering (the default)
//   Klu2Amd               Amesos2's KLU2 as shipped (block triangular form + AMD)
//   GatheredSolver        a serial solver on rank 0 of a distributed matrix (gather, factor,
//                         scatter), for solvers that cannot factor a distributed matrix
#pragma once

#include <string>

#include <Teuchos_RCP.hpp>
#include <nlohmann/json_fwd.hpp>

#include "flowform/core/TpetraTypes.hpp"

namespace flowform {

class LinearSolver {
 public:
  virtual ~LinearSolver();

  /// Factors A (numeric; symbolic too when the pattern is new). Throws std::runtime_error
  /// when the matrix is singular (the message says so, for the caller to report).
  void factor(const Teuchos::RCP<const CrsMatrix>& A);
  /// x = A⁻¹ b with the current factors, one back-substitution per column of b.
  void solve(const MultiVector& b, MultiVector& x);
  /// x = A⁻ᵀ b with the same factors (adjoint problems). std::runtime_error on every rank
  /// when the solver has no transposed solve (supportsTranspose()).
  void solveTranspose(const MultiVector& b, MultiVector& x);

  /// The case's name of the solver and of its ordering, e.g. "KLU2", "Nested Dissection".
  virtual std::string type() const = 0;
  virtual std::string ordering() const = 0;
  /// Whether solveTranspose() is available.
  virtual bool supportsTranspose() const { return true; }
  /// Entries of L + U of the current factors on this process; -1 when unknown.
  virtual double factorEntries() const { return -1.0; }

  int numFactorizations() const { return m_numFactorizations; }
  /// Back-substitutions (right-hand sides solved, either orientation) so far.
  int numSolves() const { return m_numSolves; }
  /// "type", "ordering", "factorizations", "solves" and, when known, "factor_entries" into
  /// `out` (the summary's "linear_solver").
  void report(nlohmann::json& out) const;

 protected:
  virtual void doFactor(const Teuchos::RCP<const CrsMatrix>& A) = 0;
  virtual void doSolve(const MultiVector& b, MultiVector& x, bool transpose) = 0;

 private:
  int m_numFactorizations = 0;
  int m_numSolves = 0;
};

}  // namespace flowform
