#include "flowform/solvers/GatheredSolver.hpp"

#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>

namespace flowform {

GatheredSolver::GatheredSolver(std::unique_ptr<LinearSolver> serial) : m_serial(std::move(serial)) {}

void GatheredSolver::doFactor(const Teuchos::RCP<const CrsMatrix>& A) {
  const auto comm = A->getRowMap()->getComm();
  const bool root = comm->getRank() == 0;
  if (m_rootMap.is_null()) {
    const Tpetra::global_size_t n = A->getRowMap()->getGlobalNumElements();
    m_rootMap = Teuchos::rcp(new Map(n, root ? n : 0, 0, comm));
    m_toRoot = Teuchos::rcp(new Import(A->getRowMap(), m_rootMap));
    if (root) m_serialRowMap = Teuchos::rcp(new Map(n, 0, Teuchos::rcp(new Teuchos::SerialComm<int>())));
  }
  CrsMatrix rootMatrix(m_rootMap, 0);
  rootMatrix.doImport(*A, *m_toRoot, Tpetra::INSERT);
  rootMatrix.fillComplete(m_rootMap, m_rootMap);
  // Rank 0 factors; every rank must learn whether that worked, or the others would go on
  // into the next collective call while rank 0 unwinds (a hang).
  std::string failure;
  if (root) {
    try {
      // Same local CSR, maps on a serial communicator (a shallow copy of the arrays).
      const auto rootCols = rootMatrix.getColMap();
      std::vector<GO> colGids(rootCols->getNodeNumElements());
      for (size_t j = 0; j < colGids.size(); ++j) colGids[j] = rootCols->getGlobalElement(j);
      const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
      auto serialColMap =
          Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(colGids), 0, m_serialRowMap->getComm()));
      // This constructor returns a fill-complete matrix. A new matrix object each time: the
      // AMD path redoes its (cheap) ordering; the nested-dissection path compares patterns.
      m_serialMatrix = Teuchos::rcp(new CrsMatrix(rootMatrix.getLocalMatrixDevice(), m_serialRowMap, serialColMap,
                                                  m_serialRowMap, m_serialRowMap));
      m_serial->factor(m_serialMatrix);
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  int failed = failure.empty() ? 0 : 1;
  Teuchos::broadcast(*comm, 0, &failed);
  if (failed) throw std::runtime_error(root ? failure : "the factorization failed on rank 0");
}

void GatheredSolver::doSolve(const MultiVector& b, MultiVector& x, bool transpose) {
  const size_t k = b.getNumVectors();
  MultiVector bRoot(m_rootMap, k), xRoot(m_rootMap, k);
  bRoot.doImport(b, *m_toRoot, Tpetra::INSERT);
  if (b.getMap()->getComm()->getRank() == 0) {
    MultiVector bSerial(m_serialRowMap, k), xSerial(m_serialRowMap, k);
    Tpetra::deep_copy(bSerial, bRoot);  // same local layout
    if (transpose)
      m_serial->solveTranspose(bSerial, xSerial);
    else
      m_serial->solve(bSerial, xSerial);
    Tpetra::deep_copy(xRoot, xSerial);
  }
  x.doExport(xRoot, *m_toRoot, Tpetra::INSERT);
}

}  // namespace flowform
