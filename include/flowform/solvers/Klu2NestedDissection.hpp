// Sparse LU of one process's matrix with Amesos2's KLU2 and a METIS nested-dissection
// ordering, on one process (the default direct solver).
//
// Amesos2::Solver's KLU2 adapter always orders with AMD (after a block-triangular
// pre-ordering) and takes no user ordering. On the flow Jacobians AMD's fill grows faster
// than nested dissection's: on the channel (P1) at 3.2·10⁵ dofs L + U has 6.7·10⁷ entries
// with AMD and 4.9·10⁷ with METIS_NodeND, and the factorization is faster
// above 10⁵ dofs (docs/BENCHMARKS.md §6). This class therefore calls KLU2's own
// functions (the ones Amesos2 wraps, from Amesos2's headers) with the permutation
//
//   P = METIS_NodeND(pattern of A + Aᵀ),   factor  P Aᵀ Pᵀ  (threshold partial pivoting, as
//                                                            Amesos2's KLU2 does),
//
// computed once per sparsity pattern: a Newton sequence pays the ordering and KLU2's
// symbolic analysis on the first factorization only.
//
// Storage: Tpetra keeps A by rows (CSR); read as columns (CSC) that is Aᵀ, which is what
// KLU2 factors here (Amesos2 does the same on one process). Solves of A x = b then use
// KLU2's transposed solve. Solves of Aᵀ x = b use the same transposed solve on a second
// factorization, of A itself, made on the first such solve after each factor() (KLU2's
// plain solve is wrong on permuted factors in Trilinos 13.2; docs/toolchain.md); it is not
// counted in numFactorizations().
#pragma once

#include <memory>

#include "flowform/core/TpetraTypes.hpp"
#include "flowform/solvers/LinearSolver.hpp"

namespace flowform {

class Klu2NestedDissection : public LinearSolver {
 public:
  Klu2NestedDissection();
  ~Klu2NestedDissection() override;
  Klu2NestedDissection(const Klu2NestedDissection&) = delete;
  Klu2NestedDissection& operator=(const Klu2NestedDissection&) = delete;

  std::string type() const override { return "KLU2"; }
  std::string ordering() const override { return "Nested Dissection"; }
  /// Entries of L + U of the current factors (diagonal counted once per factor).
  double factorEntries() const override;

 protected:
  /// A must be fill-complete with all its rows on this process (serial communicator). The
  /// ordering and symbolic analysis are redone only when A's sparsity pattern differs from
  /// the previous call's. Throws std::runtime_error when KLU2 finds A singular.
  void doFactor(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doSolve(const MultiVector& b, MultiVector& x, bool transpose) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace flowform
