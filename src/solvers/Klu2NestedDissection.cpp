#include "flowform/solvers/Klu2NestedDissection.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include <Amesos2_KLU2_FunctionMap.hpp>  // KLU2's functions, in namespace KLU2
#include <metis.h>

namespace flowform {

namespace {

using KluInt = int;
using KluCommon = KLU2::klu_common<double, KluInt>;
using KluSymbolic = KLU2::klu_symbolic<double, KluInt>;
using KluNumeric = KLU2::klu_numeric<double, KluInt>;

/// METIS nested dissection of the graph of A + Aᵀ (diagonal left out), A given as CSR.
/// Returns perm with perm[k] = the old index of the k-th row/column of the permuted matrix,
/// which is KLU2's convention for P and Q. (METIS 5 returns that array as `perm`; its
/// inverse is `iperm`.)
std::vector<KluInt> nestedDissection(const std::vector<KluInt>& rowStart, const std::vector<KluInt>& cols) {
  const KluInt n = static_cast<KluInt>(rowStart.size()) - 1;
  // Aᵀ by counting.
  std::vector<KluInt> tStart(n + 1, 0), tCols(cols.size());
  for (KluInt c : cols) ++tStart[c + 1];
  for (KluInt i = 0; i < n; ++i) tStart[i + 1] += tStart[i];
  std::vector<KluInt> fill(tStart.begin(), tStart.end() - 1);
  for (KluInt i = 0; i < n; ++i)
    for (KluInt k = rowStart[i]; k < rowStart[i + 1]; ++k) tCols[fill[cols[k]]++] = i;
  // Row i of A + Aᵀ: the union of the two rows, without i itself.
  std::vector<idx_t> xadj(n + 1, 0), adjncy;
  adjncy.reserve(2 * cols.size());
  std::vector<KluInt> row;
  for (KluInt i = 0; i < n; ++i) {
    row.assign(cols.begin() + rowStart[i], cols.begin() + rowStart[i + 1]);
    row.insert(row.end(), tCols.begin() + tStart[i], tCols.begin() + tStart[i + 1]);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    for (KluInt j : row)
      if (j != i) adjncy.push_back(j);
    xadj[i + 1] = static_cast<idx_t>(adjncy.size());
  }
  idx_t nv = n;
  std::vector<idx_t> perm(n), iperm(n);
  if (n > 0) {
    const int status = METIS_NodeND(&nv, xadj.data(), adjncy.data(), nullptr, nullptr, perm.data(), iperm.data());
    if (status != METIS_OK)
      throw std::runtime_error("METIS_NodeND failed (status " + std::to_string(status) + ") ordering the Jacobian");
  }
  return std::vector<KluInt>(perm.begin(), perm.end());
}

}  // namespace

struct Klu2NestedDissection::Impl {
  KluCommon common;
  KluSymbolic* symbolic = nullptr;
  KluNumeric* numeric = nullptr;
  // The pattern the symbolic analysis belongs to: A's rows with columns as row indices.
  std::vector<KluInt> rowStart, cols;
  std::vector<KluInt> perm;    ///< the nested-dissection ordering of that pattern
  std::vector<double> values;  ///< A's values at the last factorization (for the transposed one)
  // Aᵀ's CSR and its factors, made on the first transposed solve after a factorization.
  std::vector<KluInt> tStart, tCols, tPosition;  ///< tPosition: the entry of A each entry of Aᵀ is
  KluSymbolic* tSymbolic = nullptr;
  KluNumeric* tNumeric = nullptr;

  Impl() { KLU2::klu_defaults<double, KluInt>(&common); }
  ~Impl() {
    freeNumeric();
    freeTransposed();
    if (symbolic) KLU2::klu_free_symbolic<double, KluInt>(&symbolic, &common);
  }
  void freeNumeric() {
    if (numeric) KLU2::klu_free_numeric<double, KluInt>(&numeric, &common);
    if (tNumeric) KLU2::klu_free_numeric<double, KluInt>(&tNumeric, &common);
  }
  void freeTransposed() {
    if (tSymbolic) KLU2::klu_free_symbolic<double, KluInt>(&tSymbolic, &common);
    tStart.clear();
  }
  /// Factors of Aᵀ's CSR read as CSC, i.e. of A itself: KLU2's transposed solve on them
  /// gives Aᵀ x = b.
  void factorTransposed() {
    const KluInt n = static_cast<KluInt>(rowStart.size()) - 1;
    if (tStart.empty()) {
      tStart.assign(n + 1, 0);
      tCols.resize(cols.size());
      tPosition.resize(cols.size());
      for (KluInt c : cols) ++tStart[c + 1];
      for (KluInt i = 0; i < n; ++i) tStart[i + 1] += tStart[i];
      std::vector<KluInt> fill(tStart.begin(), tStart.end() - 1);
      for (KluInt i = 0; i < n; ++i)
        for (KluInt k = rowStart[i]; k < rowStart[i + 1]; ++k) {
          tCols[fill[cols[k]]] = i;
          tPosition[fill[cols[k]]++] = k;
        }
      // The pattern of A + Aᵀ is the same, so the same ordering serves.
      tSymbolic = KLU2::klu_analyze_given<double, KluInt>(n, tStart.data(), tCols.data(), perm.data(), perm.data(),
                                                           &common);
      if (tSymbolic == nullptr)
        throw std::runtime_error("KLU2 symbolic analysis of the transpose failed (status " +
                                 std::to_string(common.status) + ")");
    }
    std::vector<double> tValues(tPosition.size());
    for (size_t k = 0; k < tPosition.size(); ++k) tValues[k] = values[tPosition[k]];
    tNumeric = KLU2::klu_factor<double, KluInt>(tStart.data(), tCols.data(), tValues.data(), tSymbolic, &common);
    if (tNumeric == nullptr || common.status != KLU_OK) {
      if (tNumeric) KLU2::klu_free_numeric<double, KluInt>(&tNumeric, &common);
      throw std::runtime_error("KLU2 factorization of the transpose failed (status " + std::to_string(common.status) + ")");
    }
  }
};

Klu2NestedDissection::Klu2NestedDissection() : m_impl(new Impl) {}
Klu2NestedDissection::~Klu2NestedDissection() = default;

void Klu2NestedDissection::doFactor(const Teuchos::RCP<const CrsMatrix>& matrix) {
  Impl& d = *m_impl;
  const CrsMatrix& A = *matrix;
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const auto local = A.getLocalMatrixHost();
  const KluInt n = static_cast<KluInt>(rowMap->getNodeNumElements());
  if (A.getGlobalNumRows() != static_cast<Tpetra::global_size_t>(n))
    throw std::logic_error("Klu2NestedDissection: the matrix is not all on this process");

  // Column indices as row indices (the column map may order the columns differently).
  std::vector<KluInt> rowStart(n + 1), cols(local.graph.entries.extent(0));
  std::vector<KluInt> colToRow(colMap->getNodeNumElements());
  for (size_t c = 0; c < colToRow.size(); ++c) colToRow[c] = rowMap->getLocalElement(colMap->getGlobalElement(c));
  for (KluInt i = 0; i <= n; ++i) rowStart[i] = static_cast<KluInt>(local.graph.row_map(i));
  for (size_t k = 0; k < cols.size(); ++k) cols[k] = colToRow[local.graph.entries(k)];

  d.freeNumeric();
  if (d.symbolic == nullptr || rowStart != d.rowStart || cols != d.cols) {
    if (d.symbolic) KLU2::klu_free_symbolic<double, KluInt>(&d.symbolic, &d.common);
    d.freeTransposed();
    d.rowStart = std::move(rowStart);
    d.cols = std::move(cols);
    d.perm = nestedDissection(d.rowStart, d.cols);
    std::vector<KluInt>& perm = d.perm;
    // The same permutation on both sides keeps the diagonal on the diagonal; no block
    // triangular form (a connected finite-element matrix is one block).
    d.common.btf = 0;
    d.symbolic = KLU2::klu_analyze_given<double, KluInt>(n, d.rowStart.data(), d.cols.data(), perm.data(),
                                                          perm.data(), &d.common);
    if (d.symbolic == nullptr)
      throw std::runtime_error("KLU2 symbolic analysis failed (status " + std::to_string(d.common.status) + ")");
  }
  // CSR read as CSC: KLU2 factors Aᵀ (see the header).
  // A copy of the values (O(nnz), small next to the factorization) for a later transposed
  // factorization: the matrix may be reassembled before a transposed solve asks for it.
  d.values.assign(local.values.data(), local.values.data() + local.values.extent(0));
  d.numeric = KLU2::klu_factor<double, KluInt>(d.rowStart.data(), d.cols.data(), d.values.data(), d.symbolic,
                                               &d.common);
  if (d.numeric == nullptr || d.common.status != KLU_OK) {
    d.freeNumeric();
    throw std::runtime_error(std::string("KLU2 numeric factorization failed (") +
                             (d.common.status == KLU_SINGULAR ? "singular Jacobian" : "status " + std::to_string(d.common.status)) +
                             ")");
  }
}

void Klu2NestedDissection::doSolve(const MultiVector& b, MultiVector& x, bool transpose) {
  Impl& d = *m_impl;
  if (d.numeric == nullptr) throw std::logic_error("Klu2NestedDissection::solve before a successful factor()");
  Tpetra::deep_copy(x, b);
  const KluInt n = static_cast<KluInt>(x.getLocalLength());
  // A x = b: KLU2's transposed solve on the factors of Aᵀ (CSR read as CSC). Aᵀ x = b: the
  // same on the factors of A, made on the first such solve after each factorization (one
  // more numeric factorization). KLU2's plain klu_solve would avoid it, but in Trilinos 13.2
  // it gives wrong answers on these permuted factors (errors of order 1 in
  // tests/unit/LinearSolverTest.cpp), so it is not used.
  if (transpose && d.tNumeric == nullptr) d.factorTransposed();
  KluNumeric* numeric = transpose ? d.tNumeric : d.numeric;
  KluSymbolic* symbolic = transpose ? d.tSymbolic : d.symbolic;
  for (size_t j = 0; j < x.getNumVectors(); ++j) {
    auto column = x.getDataNonConst(j);
    if (!KLU2::klu_tsolve<double, KluInt>(symbolic, numeric, n, 1, column.getRawPtr(), &d.common))
      throw std::runtime_error("KLU2 solve failed (status " + std::to_string(d.common.status) + ")");
  }
}

double Klu2NestedDissection::factorEntries() const {
  const Impl& d = *m_impl;
  return d.numeric ? static_cast<double>(d.numeric->lnz) + static_cast<double>(d.numeric->unz) : 0.0;
}

}  // namespace flowform
