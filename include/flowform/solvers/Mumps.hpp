// MUMPS (multifrontal sparse LU, MPI-parallel) through its C interface, on the matrix as the
// ranks hold it: each rank hands MUMPS its own rows as triplets (distributed assembled
// input, ICNTL(18) = 3), so nothing is gathered to rank 0 for the factorization, and MUMPS
// factors with all ranks. Right-hand sides and solutions are centralized on rank 0 (vectors
// are O(n), the factors are not).
//
// Why not Amesos2's MUMPS adapter: it hands MUMPS a centralized matrix (ICNTL(18) = 0), i.e.
// it gathers every entry to rank 0 first (docs/toolchain.md).
//
// The analysis (ordering, ICNTL(7): METIS nested dissection by default; symbolic
// factorization) is done once per sparsity pattern; each Jacobian costs one numeric
// factorization. Solves of A x = b and Aᵀ x = b (ICNTL(9)) use the same factors, several
// right-hand sides at once. BLAS: whatever libblas.so.3 points to (OpenBLAS once
// libopenblas0-pthread is installed, scripts/setup); threads × ranks ≤ cores
// (docs/toolchain.md).
#pragma once

#include <memory>
#include <string>

#include "flowform/solvers/LinearSolver.hpp"

namespace flowform {

class Mumps : public LinearSolver {
 public:
  enum class Ordering { Metis, Amd };
  explicit Mumps(Ordering ordering = Ordering::Metis);
  ~Mumps() override;
  Mumps(const Mumps&) = delete;
  Mumps& operator=(const Mumps&) = delete;

  std::string type() const override { return "MUMPS"; }
  std::string ordering() const override;
  /// Entries of L + U (MUMPS's INFOG(29), all ranks).
  double factorEntries() const override;

 protected:
  /// Throws std::runtime_error on every rank when MUMPS reports an error (a singular matrix:
  /// "numerically singular"), with MUMPS's INFOG(1) and INFOG(2).
  void doFactor(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doSolve(const MultiVector& b, MultiVector& x, bool transpose) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace flowform
