// Sparse LU of one process's matrix with Amesos2's KLU2 and a METIS nested-dissection
// ordering.
//
// Amesos2::Solver's KLU2 adapter always orders with AMD (after a block-triangular
// pre-ordering) and takes no user ordering. On the flow Jacobians AMD's fill grows faster
// than nested dissection's: on the channel (P1) at 3.2·10⁵ dofs L + U has 6.7·10⁷ entries
// with AMD and 4.9·10⁷ with METIS_NodeND, and one factorization takes 24.8 s against 14.5 s;
// at 10⁶ dofs 146 s against 88 s (docs/BENCHMARKS.md §6). This class therefore calls KLU2's own
// functions (the ones Amesos2 wraps, from Amesos2's headers) with the permutation
//
//   P = METIS_NodeND(pattern of A + Aᵀ),   factor  P Aᵀ Pᵀ  (threshold partial pivoting, as
//                                                            Amesos2's KLU2 does),
//
// computed once per sparsity pattern: a Newton sequence pays the ordering and KLU2's
// symbolic analysis on the first factorization only.
//
// Storage: Tpetra keeps A by rows (CSR); read as columns (CSC) that is Aᵀ, which is what
// KLU2 factors here (Amesos2 does the same on one process). Solves then use the
// transposed solve, which gives A x = b.
#pragma once

#include <memory>

#include "flowform/TpetraTypes.hpp"

namespace flowform {

class KluNestedDissection {
 public:
  KluNestedDissection();
  ~KluNestedDissection();
  KluNestedDissection(const KluNestedDissection&) = delete;
  KluNestedDissection& operator=(const KluNestedDissection&) = delete;

  /// Factors A, a fill-complete matrix whose rows all live on this process (serial
  /// communicator). The ordering and symbolic analysis are redone only when A's sparsity
  /// pattern differs from the previous call's. Throws std::runtime_error when KLU2 finds A
  /// singular.
  void factor(const CrsMatrix& A);
  /// x = A⁻¹ b for every column of b, with the current factors.
  void solve(const MultiVector& b, MultiVector& x) const;

  /// Entries of L + U of the current factors (diagonal counted once per factor).
  double factorEntries() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace flowform
