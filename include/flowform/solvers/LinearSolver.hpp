// Direct solution of the Newton (and sensitivity) systems with Amesos2 KLU2.
//
// Ordering (case: Solver → Linear Solver → Ordering):
//   "Nested Dissection" (default): METIS_NodeND, KLU2 called through its own functions
//                       (KluNestedDissection.hpp: Amesos2::Solver takes no user ordering);
//   "AMD": Amesos2::Solver's KLU2 as shipped (block-triangular form + AMD).
// Both use KLU2's threshold partial pivoting; nested dissection has less fill on these
// Jacobians and factors 1.7× faster at 3.2·10⁵ and 10⁶ dofs, 0.02–0.07 s slower below
// 10⁵ (docs/BENCHMARKS.md §6).
//
// One process: KLU2 on the assembled matrix; the symbolic factorization (ordering) is done
// once, since the sparsity never changes, and each new Jacobian costs one numeric
// factorization. The factors stay until the next factor() call, so further right-hand
// sides (the sensitivity solves) cost one back-substitution each.
//
// Several processes: Debian's Amesos2 KLU2 gives wrong answers on a distributed matrix
// (TOOLCHAIN.md), so the matrix is gathered to rank 0 and factored there by a serial
// KLU2; right-hand sides and solutions travel with the same Import. This keeps results
// identical to the serial run; it does not scale the factorization (docs/BENCHMARKS.md).
#pragma once

#include <memory>

#include <Teuchos_RCP.hpp>

#include "flowform/TpetraTypes.hpp"

namespace flowform {

class LinearSolver {
 public:
  enum class Ordering { NestedDissection, Amd };
  /// The names used in the case file, in the order of the enum.
  static const char* orderingName(Ordering ordering);

  explicit LinearSolver(Ordering ordering = Ordering::NestedDissection);
  ~LinearSolver();

  /// Factors A (numeric; symbolic too on the first call). Throws std::runtime_error when
  /// the matrix is singular (the message says so, for the caller to report).
  void factor(const Teuchos::RCP<const CrsMatrix>& A);
  /// x = A⁻¹ b with the current factors, one back-substitution per column of b.
  void solve(const MultiVector& b, MultiVector& x);

  Ordering ordering() const { return m_ordering; }
  /// Entries of L + U of the current factors on this process; -1 when unknown (the AMD
  /// path: Amesos2 does not report them; ranks other than 0 on several processes).
  double factorEntries() const;
  int numFactorizations() const { return m_numFactorizations; }
  /// Back-substitutions (right-hand sides solved) so far.
  int numSolves() const { return m_numSolves; }

 private:
  struct Impl;
  /// Factors a matrix whose rows are all on this process (serial communicator).
  void factorLocal(const Teuchos::RCP<const CrsMatrix>& A);
  /// Rank 0's part of a gathered factorization: the serial KLU2 on the gathered rows.
  void factorOnRoot(const CrsMatrix& rootMatrix);
  /// x = A⁻¹ b on this process, with the factors of factorLocal.
  void solveLocal(const MultiVector& b, MultiVector& x);
  std::unique_ptr<Impl> m_impl;
  Ordering m_ordering;
  int m_numFactorizations = 0;
  int m_numSolves = 0;
};

}  // namespace flowform
