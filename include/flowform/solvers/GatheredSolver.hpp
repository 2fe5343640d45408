// A serial direct solver used on a distributed matrix: the rows are gathered to rank 0 and
// factored there by the wrapped solver; right-hand sides and solutions travel with the same
// Import. Debian's Amesos2 KLU2 gives wrong answers on a distributed matrix
// (docs/toolchain.md), so KLU2 runs this way under mpirun: results equal the serial run's,
// and the factorization does not scale with the ranks.
#pragma once

#include <memory>

#include "flowform/solvers/LinearSolver.hpp"

namespace flowform {

class GatheredSolver : public LinearSolver {
 public:
  /// `serial` factors rank 0's gathered matrix (other ranks never call it).
  explicit GatheredSolver(std::unique_ptr<LinearSolver> serial);

  std::string type() const override { return m_serial->type(); }
  std::string ordering() const override { return m_serial->ordering(); }
  double factorEntries() const override { return m_serial->factorEntries(); }
  bool supportsTranspose() const override { return m_serial->supportsTranspose(); }

 protected:
  void doFactor(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doSolve(const MultiVector& b, MultiVector& x, bool transpose) override;

 private:
  std::unique_ptr<LinearSolver> m_serial;
  Teuchos::RCP<const Map> m_rootMap;        ///< all rows on rank 0 (distributed comm)
  Teuchos::RCP<const Import> m_toRoot;      ///< owned -> root
  Teuchos::RCP<const Map> m_serialRowMap;   ///< rank 0 only, serial comm
  Teuchos::RCP<CrsMatrix> m_serialMatrix;   ///< rank 0 only
};

}  // namespace flowform
