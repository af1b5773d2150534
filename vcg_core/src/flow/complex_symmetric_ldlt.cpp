// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/complex_symmetric_ldlt.h"

#include "flow/flush_subnormals.h"

#include <Eigen/OrderingMethods>
#ifdef ELASTICA_HAVE_CHOLMOD
#include <cholmod.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <utility>

namespace elastica {
namespace {

using Complex = ComplexSymmetricLdlt::Complex;

// y −= a·b, written out: std::complex's operator* checks for NaN and calls a library routine,
// which keeps the inner loops from being compiled as plain multiply-adds (the same bits either way
// for finite values).
inline void subtractProductCsl(Complex& y, const Complex& a, const Complex& b) {
  const double re = a.real() * b.real() - a.imag() * b.imag();
  const double im = a.real() * b.imag() + a.imag() * b.real();
  y = Complex(y.real() - re, y.imag() - im);
}

inline Complex productCsl(const Complex& a, const Complex& b) {
  return Complex(a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real());
}

// Eigen's AMD on A's pattern (values unused; it symmetrises A + Aᵀ, a no-op here): the rows in
// the order they are eliminated.
std::vector<int> amdOrderingCsl(const ComplexSymmetricLdlt::Matrix& A) {
  const int n = static_cast<int>(A.rows());
  Eigen::SparseMatrix<double> pattern(n, n);
  pattern.resizeNonZeros(A.nonZeros());
  std::copy(A.outerIndexPtr(), A.outerIndexPtr() + n + 1, pattern.outerIndexPtr());
  std::copy(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), pattern.innerIndexPtr());
  std::fill(pattern.valuePtr(), pattern.valuePtr() + A.nonZeros(), 1.0);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> eliminated;
  Eigen::AMDOrdering<int>()(pattern, eliminated);  // eliminated[k]: the row taken k-th
  return std::vector<int>(eliminated.indices().data(), eliminated.indices().data() + n);
}

#ifdef ELASTICA_HAVE_CHOLMOD
// METIS's nested dissection (through CHOLMOD, postordered) on A's upper triangle's pattern; empty
// if it failed. On the one-ring patterns measured it gave 0.70–0.94× AMD's fill and the faster
// analysis plus factorisation (docs/decisions.md, "The amount's solver").
std::vector<int> metisOrderingCsl(const ComplexSymmetricLdlt::Matrix& A) {
  const int n = static_cast<int>(A.rows());
  cholmod_common common;
  cholmod_start(&common);
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<std::size_t>(n);
  view.nzmax = static_cast<std::size_t>(A.nonZeros());
  view.p = const_cast<int*>(A.outerIndexPtr());
  view.i = const_cast<int*>(A.innerIndexPtr());
  view.stype = 1;  // the upper triangle (both are stored)
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_PATTERN;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  std::vector<int> order(n);
  const int ok = cholmod_metis(&view, nullptr, 0, 1, order.data(), &common);
  cholmod_finish(&common);
  if (!ok) order.clear();
  return order;
}
#endif

// Elimination tree and column counts of A ordered by `order` (Davis's ldl_symbolic): row k of L
// reaches, from each entry i < k of A's row k, up the tree to the first node already marked for
// k. Returns the nonzeros of L below the diagonal.
std::int64_t symbolicCsl(const ComplexSymmetricLdlt::Matrix& A, const std::vector<int>& order,
                         std::vector<int>& parent, std::vector<int>& count) {
  const int n = static_cast<int>(A.rows());
  std::vector<int> position(n), flag(n);
  for (int k = 0; k < n; ++k) position[order[k]] = k;
  parent.assign(n, -1);
  count.assign(n, 0);
  std::int64_t fill = 0;
  for (int k = 0; k < n; ++k) {
    flag[k] = k;
    const int col = order[k];
    for (int p = A.outerIndexPtr()[col]; p < A.outerIndexPtr()[col + 1]; ++p) {
      for (int i = position[A.innerIndexPtr()[p]]; i < k && flag[i] != k; i = parent[i]) {
        if (parent[i] == -1) parent[i] = k;
        ++count[i];
        ++fill;
        flag[i] = k;
      }
    }
  }
  return fill;
}

}  // namespace

void ComplexSymmetricLdlt::clear() {
  *this = ComplexSymmetricLdlt();
}

void ComplexSymmetricLdlt::analyzePattern(const Matrix& A) {
  const int n = static_cast<int>(A.rows());
  factored_ = false;
  std::vector<int>().swap(rowIndex_);
  std::vector<Complex>().swap(value_);
  // The ordering of less fill of Eigen's AMD and (with CHOLMOD) METIS's nested dissection; METIS
  // first, AMD where it is not smaller. Both are deterministic.
  std::vector<int> parent, count;
  bool have = false;
  std::int64_t best = 0;
  auto consider = [&](std::vector<int>&& order) {
    const std::int64_t fill = symbolicCsl(A, order, parent, count);
    if (have && fill >= best) return;
    have = true, best = fill;
    order_ = std::move(order);
    parent_.swap(parent);
    columnStart_.assign(n + 1, 0);
    multiplyAdds_ = 0;
    for (int k = 0; k < n; ++k) {
      columnStart_[k + 1] = columnStart_[k] + count[k];
      multiplyAdds_ += 0.5 * static_cast<double>(count[k]) * (count[k] + 1);
    }
  };
#ifdef ELASTICA_HAVE_CHOLMOD
  std::vector<int> metis = metisOrderingCsl(A);
  if (!metis.empty()) consider(std::move(metis));
#endif
  consider(amdOrderingCsl(A));
  position_.assign(n, 0);
  for (int k = 0; k < n; ++k) position_[order_[k]] = k;
  // Supernodes: column j ends where j + 1 is not its parent or has not one entry fewer. Within
  // one, column j's rows are j + 1 … last, then the last column's (L_{*,j} \ {j+1} ⊆ L_{*,j+1}
  // for parent j + 1, with equal counts it is all of it), so only each last column stores rows.
  std::vector<int> last(n, 0);
  for (int j = n - 1; j >= 0; --j) {
    const bool joins = j + 1 < n && parent_[j] == j + 1 &&
                       columnStart_[j + 1] - columnStart_[j] == columnStart_[j + 2] - columnStart_[j + 1] + 1;
    last[j] = joins ? last[j + 1] : j;
  }
  columnRows_.assign(n, ColumnRows{});
  storedRows_ = 0;
  for (int j = 0; j < n; ++j) {
    if (last[j] != j) continue;
    for (int i = j; i >= 0 && last[i] == j; --i) columnRows_[i] = ColumnRows{storedRows_ - (j - i), j - i};
    storedRows_ += columnStart_[j + 1] - columnStart_[j];
  }
}

ComplexSymmetricLdlt::Matrix ComplexSymmetricLdlt::factorizedPart(const Matrix& A) const {
  const int n = static_cast<int>(A.rows());
  Matrix part(n, n);
  std::int64_t kept = 0;
  for (int col = 0; col < n; ++col)
    for (Matrix::InnerIterator it(A, col); it; ++it) kept += position_[it.row()] <= position_[col];
  part.resizeNonZeros(static_cast<Eigen::Index>(kept));
  std::int64_t next = 0;
  for (int col = 0; col < n; ++col) {
    part.outerIndexPtr()[col] = static_cast<int>(next);
    for (Matrix::InnerIterator it(A, col); it; ++it)
      if (position_[it.row()] <= position_[col]) {
        part.innerIndexPtr()[next] = static_cast<int>(it.row());
        part.valuePtr()[next++] = it.value();
      }
  }
  part.outerIndexPtr()[n] = static_cast<int>(next);
  return part;
}

bool ComplexSymmetricLdlt::factorize(const Matrix& A) {
  const int n = static_cast<int>(A.rows());
  if (columnStart_.size() != static_cast<std::size_t>(n) + 1) analyzePattern(A);
  factored_ = false;
  [[maybe_unused]] FlushSubnormals flush;  // empty without SSE
  rowIndex_.resize(storedRows_);
  value_.resize(columnStart_.back());
  diagonal_.resize(n);  // holds 1/D
  std::vector<Complex> y(n, Complex(0, 0));
  std::vector<int> stack(n), flag(n), count(n, 0);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const Complex* a = A.valuePtr();
  for (int k = 0; k < n; ++k) {  // row k of L and D_k (Davis's ldl_numeric, up-looking)
    int top = n;
    flag[k] = k;
    const int col = order_[k];
    for (int p = outer[col]; p < outer[col + 1]; ++p) {
      int i = position_[inner[p]];
      if (i > k) continue;
      y[i] += a[p];
      int length = 0;  // the path up the tree from i to the marked part: pushed in reverse
      for (; flag[i] != k; i = parent_[i]) stack[length++] = i, flag[i] = k;
      while (length > 0) stack[--top] = stack[--length];
    }
    Complex d = y[k];
    y[k] = Complex(0, 0);
    for (; top < n; ++top) {  // rows i of L's row k in topological order
      const int i = stack[top];
      const Complex yi = y[i];
      y[i] = Complex(0, 0);
      const Complex* li = value_.data() + columnStart_[i];
      forEachRow(i, count[i], [&](std::int64_t t, int row) { subtractProductCsl(y[row], li[t], yi); });
      const Complex l = productCsl(yi, diagonal_[i]);
      subtractProductCsl(d, l, yi);
      if (columnRows_[i].implied == 0) rowIndex_[columnRows_[i].stored + count[i]] = k;  // else implied
      value_[columnStart_[i] + count[i]] = l;
      ++count[i];
    }
    if (!std::isfinite(d.real()) || !std::isfinite(d.imag()) || d == Complex(0, 0)) return false;
    diagonal_[k] = Complex(1, 0) / d;
    if (!std::isfinite(diagonal_[k].real()) || !std::isfinite(diagonal_[k].imag())) return false;
  }
  factored_ = true;
  return true;
}

void ComplexSymmetricLdlt::solve(const Eigen::MatrixXcd& B, Eigen::MatrixXcd& X) const {
  const int n = static_cast<int>(order_.size());
  Rows y(n, B.cols());
  for (int k = 0; k < n; ++k) y.row(k) = B.row(order_[k]);
  solvePermuted(y);
  X.resize(n, B.cols());
  for (int k = 0; k < n; ++k) X.row(order_[k]) = y.row(k);
}

void ComplexSymmetricLdlt::solveRealPart(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
  const int n = static_cast<int>(order_.size());
  Rows y(n, B.cols());
  for (int k = 0; k < n; ++k) y.row(k) = B.row(order_[k]).cast<Complex>();
  solvePermuted(y);
  X.resize(n, B.cols());
  for (int k = 0; k < n; ++k) X.row(order_[k]) = y.row(k).real();
}

void ComplexSymmetricLdlt::solvePermuted(Rows& y) const {
  const int n = static_cast<int>(order_.size());
  const int m = static_cast<int>(y.cols());
  [[maybe_unused]] FlushSubnormals flush;
  // The columns side by side per row: one pass over the factor for all of them (each column's
  // arithmetic is the same as alone).
  Complex* row = y.data();
  for (int j = 0; j < n; ++j) {  // L y = Pb
    const Complex* lj = value_.data() + columnStart_[j];
    forEachRow(j, columnStart_[j + 1] - columnStart_[j], [&](std::int64_t t, int r) {
      Complex* target = row + static_cast<std::ptrdiff_t>(r) * m;
      for (int c = 0; c < m; ++c) subtractProductCsl(target[c], lj[t], row[static_cast<std::ptrdiff_t>(j) * m + c]);
    });
  }
  for (int j = 0; j < n; ++j)  // D
    for (int c = 0; c < m; ++c) y(j, c) = productCsl(y(j, c), diagonal_[j]);
  for (int j = n - 1; j >= 0; --j) {  // Lᵀ (no conjugation)
    Complex* out = row + static_cast<std::ptrdiff_t>(j) * m;
    const Complex* lj = value_.data() + columnStart_[j];
    forEachRow(j, columnStart_[j + 1] - columnStart_[j], [&](std::int64_t t, int r) {
      const Complex* source = row + static_cast<std::ptrdiff_t>(r) * m;
      for (int c = 0; c < m; ++c) subtractProductCsl(out[c], lj[t], source[c]);
    });
  }
}

}  // namespace elastica
