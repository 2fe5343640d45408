#include "flowform/solvers/Mumps.hpp"

#include <dlfcn.h>
#include <dmumps_c.h>
#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace flowform {

namespace {

// MUMPS's job codes and its 1-based control and information arrays.
constexpr int kInit = -1, kEnd = -2, kAnalyse = 1, kFactor = 2, kSolve = 3;
constexpr int kWorkspaceRetries = 4;  // ICNTL(14) up to 16× its first value
int& icntl(DMUMPS_STRUC_C& id, int k) { return id.icntl[k - 1]; }
int infog(const DMUMPS_STRUC_C& id, int k) { return id.infog[k - 1]; }

MPI_Comm rawComm(const Comm& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  return mpi ? static_cast<MPI_Comm>(*mpi->getRawMpiComm()) : MPI_COMM_SELF;
}

/// One BLAS thread per rank unless the user sets OPENBLAS_NUM_THREADS or OMP_NUM_THREADS
/// (docs/toolchain.md "Ranks and BLAS threads"): the 2-D fronts are too small for a second
/// thread to help, and OpenBLAS's idle threads spin on a core that another process (a second
/// rank, the next test, a parallel sweep) needs. Looked up at run time: a BLAS other than
/// OpenBLAS has no such symbol and is left as it is.
void oneBlasThreadUnlessAsked() {
  static const bool done = [] {
    if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("OMP_NUM_THREADS")) return true;
    using SetThreads = void (*)(int);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
    return true;
  }();
  (void)done;
}

}  // namespace

struct Mumps::Impl {
  DMUMPS_STRUC_C id{};
  bool initialized = false, analysed = false, factored = false;
  Ordering ordering = Ordering::Metis;
  MPI_Comm comm = MPI_COMM_NULL;
  // This rank's triplets (1-based global indices) of the pattern the analysis belongs to.
  std::vector<MUMPS_INT> rows, cols;
  std::vector<double> values;
  // Right-hand sides and solutions on rank 0.
  Teuchos::RCP<const Map> rootMap;
  Teuchos::RCP<const Import> toRoot;

  void call(int job, const char* what) {
    id.job = job;
    dmumps_c(&id);
    check(what);
  }
  /// Throws for the last call's INFOG(1) < 0 (an error, the same on every rank; −10:
  /// numerically singular).
  void check(const char* what) const {
    if (infog(id, 1) < 0)
      throw std::runtime_error(std::string("MUMPS ") + what + " failed (INFOG(1) = " + std::to_string(infog(id, 1)) +
                               ", INFOG(2) = " + std::to_string(infog(id, 2)) + ")" +
                               (infog(id, 1) == -10 ? ": the matrix is numerically singular (singular Jacobian?)" : ""));
  }
  void end() {
    if (!initialized) return;
    id.job = kEnd;
    dmumps_c(&id);
    initialized = analysed = factored = false;
  }
  ~Impl() { end(); }
};

Mumps::Mumps(Ordering ordering) : m_impl(new Impl) { m_impl->ordering = ordering; }
Mumps::~Mumps() = default;

std::string Mumps::ordering() const {
  // The case's names (Solver/Linear Solver/Ordering).
  return m_impl->ordering == Ordering::Metis ? "Nested Dissection" : "AMD";
}

double Mumps::factorEntries() const {
  if (!m_impl->factored) return -1.0;
  const int e = infog(m_impl->id, 29);  // negative: millions of entries
  return e >= 0 ? static_cast<double>(e) : -1e6 * e;
}

void Mumps::doFactor(const Teuchos::RCP<const CrsMatrix>& A) {
  Impl& d = *m_impl;
  const MPI_Comm comm = rawComm(*A->getRowMap()->getComm());
  if (d.initialized && comm != d.comm) d.end();
  if (!d.initialized) {
    oneBlasThreadUnlessAsked();
    d.comm = comm;
    d.id = DMUMPS_STRUC_C{};
    d.id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
    d.id.par = 1;  // rank 0 works too
    d.id.sym = 0;  // unsymmetric
    d.call(kInit, "initialization");
    d.initialized = true;
    icntl(d.id, 1) = -1;  // no error, diagnostic or statistics output: flowform reports INFOG
    icntl(d.id, 2) = -1;
    icntl(d.id, 3) = -1;
    icntl(d.id, 4) = 0;
    icntl(d.id, 18) = 3;  // distributed assembled matrix: each rank gives its own entries
    icntl(d.id, 7) = d.ordering == Ordering::Metis ? 5 : 0;  // METIS nested dissection, or AMD
    icntl(d.id, 28) = 1;  // sequential analysis (the orderings above)
    icntl(d.id, 20) = 0;  // dense right-hand sides on rank 0
    icntl(d.id, 21) = 0;  // solution on rank 0
  }
  // This rank's rows as triplets with global (1-based) indices.
  const auto rowMap = A->getRowMap();
  const auto colMap = A->getColMap();
  const auto local = A->getLocalMatrixHost();
  const size_t nnz = local.values.extent(0);
  std::vector<MUMPS_INT> rows(nnz), cols(nnz);
  for (LO i = 0; i < static_cast<LO>(rowMap->getNodeNumElements()); ++i)
    for (size_t k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k) {
      rows[k] = static_cast<MUMPS_INT>(rowMap->getGlobalElement(i) + 1);
      cols[k] = static_cast<MUMPS_INT>(colMap->getGlobalElement(local.graph.entries(k)) + 1);
    }
  d.values.assign(local.values.data(), local.values.data() + nnz);
  // A new pattern on any rank means a new analysis on all (collective decision).
  int changed = !d.analysed || rows != d.rows || cols != d.cols ? 1 : 0, anyChanged = 0;
  MPI_Allreduce(&changed, &anyChanged, 1, MPI_INT, MPI_MAX, comm);
  d.factored = false;
  d.id.n = static_cast<MUMPS_INT>(A->getGlobalNumRows());
  d.id.nnz_loc = static_cast<MUMPS_INT8>(nnz);
  if (anyChanged) {
    d.rows = std::move(rows);
    d.cols = std::move(cols);
    d.id.irn_loc = d.rows.data();
    d.id.jcn_loc = d.cols.data();
    d.analysed = false;
    d.call(kAnalyse, "analysis");
    d.analysed = true;
    // Right-hand sides and solutions travel to and from rank 0 with this Import.
    const GO n = static_cast<GO>(A->getGlobalNumRows());
    d.rootMap = Teuchos::rcp(new Map(n, rowMap->getComm()->getRank() == 0 ? n : 0, 0, rowMap->getComm()));
    d.toRoot = Teuchos::rcp(new Import(rowMap, d.rootMap));
  }
  d.id.a_loc = d.values.data();
  // Off-diagonal pivots (the contact and friction rows) can fill in beyond the analysis's
  // estimate: INFOG(1) = −8, −9, −11, −12, −14, −15 say a workspace was too small. The
  // factorization is tried again with ICNTL(14) (the estimate's relaxation, %) doubled, at most
  // kWorkspaceRetries times; another error, or the last try's, is thrown.
  for (int retry = 0;; ++retry) {
    d.id.job = kFactor;
    dmumps_c(&d.id);
    const int e = infog(d.id, 1);
    const bool workspace = e == -8 || e == -9 || e == -11 || e == -12 || e == -14 || e == -15;
    if (!workspace || retry == kWorkspaceRetries) break;
    icntl(d.id, 14) = 2 * std::max(icntl(d.id, 14), 20);
  }
  d.check("numeric factorization");
  d.factored = true;
}

void Mumps::doSolve(const MultiVector& b, MultiVector& x, bool transpose) {
  Impl& d = *m_impl;
  if (!d.factored) throw std::logic_error("Mumps::solve before a successful factor()");
  const size_t k = b.getNumVectors();
  MultiVector bRoot(d.rootMap, k);
  bRoot.doImport(b, *d.toRoot, Tpetra::INSERT);
  const bool root = b.getMap()->getComm()->getRank() == 0;
  std::vector<double> rhs;
  if (root) {
    // Column-major, leading dimension n: MultiVector's own host layout, copied for safety.
    rhs.resize(static_cast<size_t>(d.id.n) * k);
    for (size_t j = 0; j < k; ++j) {
      auto col = bRoot.getData(j);
      std::copy(col.begin(), col.end(), rhs.begin() + j * d.id.n);
    }
  }
  d.id.rhs = root ? rhs.data() : nullptr;
  d.id.nrhs = static_cast<MUMPS_INT>(k);
  d.id.lrhs = d.id.n;
  icntl(d.id, 9) = transpose ? 0 : 1;  // 1: A x = b; otherwise Aᵀ x = b
  d.call(kSolve, "solve");
  MultiVector xRoot(d.rootMap, k);
  if (root)
    for (size_t j = 0; j < k; ++j) {
      auto col = xRoot.getDataNonConst(j);
      std::copy(rhs.begin() + j * d.id.n, rhs.begin() + (j + 1) * d.id.n, col.begin());
    }
  x.doExport(xRoot, *d.toRoot, Tpetra::INSERT);
}

}  // namespace flowform
