#include "flowform/LinearSolver.hpp"

#include <stdexcept>

#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "flowform/KluNestedDissection.hpp"

namespace flowform {

using Amesos2Solver = Amesos2::Solver<CrsMatrix, MultiVector>;

struct LinearSolver::Impl {
  // The factors: one of the two, by ordering.
  Teuchos::RCP<const CrsMatrix> matrix;  ///< the matrix `amd` belongs to
  Teuchos::RCP<Amesos2Solver> amd;
  KluNestedDissection nestedDissection;
  // Gather-to-root path.
  bool gather = false;
  Teuchos::RCP<const Map> rootMap;          ///< all rows on rank 0 (distributed comm)
  Teuchos::RCP<const Import> toRoot;        ///< owned -> root
  Teuchos::RCP<const Map> serialRowMap;     ///< rank 0 only, serial comm
  Teuchos::RCP<CrsMatrix> serialMatrix;     ///< rank 0 only
};

const char* LinearSolver::orderingName(Ordering ordering) {
  return ordering == Ordering::NestedDissection ? "Nested Dissection" : "AMD";
}

LinearSolver::LinearSolver(Ordering ordering) : m_impl(new Impl), m_ordering(ordering) {}
LinearSolver::~LinearSolver() = default;

namespace {

void numericFactor(Amesos2Solver& solver) {
  try {
    solver.numericFactorization();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("KLU2 numeric factorization failed (singular Jacobian?): ") + e.what());
  }
}

}  // namespace

void LinearSolver::factor(const Teuchos::RCP<const CrsMatrix>& A) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: factorization"));
  Impl& d = *m_impl;
  const auto comm = A->getRowMap()->getComm();
  ++m_numFactorizations;

  if (comm->getSize() == 1) {
    factorLocal(A);
    return;
  }

  // Gather the rows to rank 0 and factor there with a serial KLU2.
  d.gather = true;
  if (d.rootMap.is_null()) {
    const Tpetra::global_size_t n = A->getRowMap()->getGlobalNumElements();
    const size_t local = comm->getRank() == 0 ? n : 0;
    d.rootMap = Teuchos::rcp(new Map(n, local, 0, comm));
    d.toRoot = Teuchos::rcp(new Import(A->getRowMap(), d.rootMap));
    if (comm->getRank() == 0)
      d.serialRowMap = Teuchos::rcp(new Map(n, 0, Teuchos::rcp(new Teuchos::SerialComm<int>())));
  }
  CrsMatrix rootMatrix(d.rootMap, 0);
  rootMatrix.doImport(*A, *d.toRoot, Tpetra::INSERT);
  rootMatrix.fillComplete(d.rootMap, d.rootMap);
  // Rank 0 factors; every rank must learn whether that worked, or the others would go on
  // into the next collective call while rank 0 unwinds (a hang).
  std::string failure;
  if (comm->getRank() == 0) {
    try {
      factorOnRoot(rootMatrix);
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  int failed = failure.empty() ? 0 : 1;
  Teuchos::broadcast(*comm, 0, &failed);
  if (failed) throw std::runtime_error(comm->getRank() == 0 ? failure : "KLU2 numeric factorization failed on rank 0");
}

void LinearSolver::factorLocal(const Teuchos::RCP<const CrsMatrix>& A) {
  Impl& d = *m_impl;
  if (m_ordering == Ordering::NestedDissection) {
    d.nestedDissection.factor(*A);  // reorders only when the pattern changed
    return;
  }
  // Amesos2 keeps the symbolic factorization (AMD) of the matrix object it was made with.
  if (d.amd.is_null() || d.matrix.get() != A.get()) {
    d.matrix = A;
    d.amd = Amesos2::create<CrsMatrix, MultiVector>("KLU2", A);
    d.amd->symbolicFactorization();
  }
  numericFactor(*d.amd);
}

void LinearSolver::solveLocal(const MultiVector& b, MultiVector& x) {
  Impl& d = *m_impl;
  if (m_ordering == Ordering::NestedDissection)
    d.nestedDissection.solve(b, x);
  else
    d.amd->solve(Teuchos::ptrFromRef(x), Teuchos::ptrFromRef(b));
}

void LinearSolver::factorOnRoot(const CrsMatrix& rootMatrix) {
  Impl& d = *m_impl;
  // Same local CSR, maps on a serial communicator (a shallow copy of the arrays).
  const auto rootCols = rootMatrix.getColMap();
  std::vector<GO> colGids(rootCols->getNodeNumElements());
  for (size_t j = 0; j < colGids.size(); ++j) colGids[j] = rootCols->getGlobalElement(j);
  auto serialComm = d.serialRowMap->getComm();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto serialColMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(colGids), 0, serialComm));
  // This constructor returns a fill-complete matrix. A new matrix object each time: the
  // AMD path redoes its (cheap) ordering; the nested-dissection path compares patterns.
  d.serialMatrix = Teuchos::rcp(new CrsMatrix(rootMatrix.getLocalMatrixDevice(), d.serialRowMap, serialColMap,
                                              d.serialRowMap, d.serialRowMap));
  factorLocal(d.serialMatrix);
}

double LinearSolver::factorEntries() const {
  const double entries = m_ordering == Ordering::NestedDissection ? m_impl->nestedDissection.factorEntries() : 0.0;
  return entries > 0.0 ? entries : -1.0;
}

void LinearSolver::solve(const MultiVector& b, MultiVector& x) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: linear solve"));
  Impl& d = *m_impl;
  m_numSolves += static_cast<int>(b.getNumVectors());  // one back-substitution per column
  if (!d.gather) {
    solveLocal(b, x);
    return;
  }
  MultiVector bRoot(d.rootMap, b.getNumVectors()), xRoot(d.rootMap, b.getNumVectors());
  bRoot.doImport(b, *d.toRoot, Tpetra::INSERT);
  if (b.getMap()->getComm()->getRank() == 0) {
    MultiVector bSerial(d.serialRowMap, b.getNumVectors()), xSerial(d.serialRowMap, b.getNumVectors());
    Tpetra::deep_copy(bSerial, bRoot);  // same local layout
    solveLocal(bSerial, xSerial);
    Tpetra::deep_copy(xRoot, xSerial);
  }
  x.doExport(xRoot, *d.toRoot, Tpetra::INSERT);
}

}  // namespace flowform
