// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/complex_symmetric_ldlt.h"

#include <Eigen/OrderingMethods>

#include <cmath>

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

}  // namespace

void ComplexSymmetricLdlt::clear() {
  *this = ComplexSymmetricLdlt();
}

void ComplexSymmetricLdlt::analyzePattern(const Matrix& A) {
  const int n = static_cast<int>(A.rows());
  factored_ = false;
  // Eigen's AMD on the pattern (values unused; it symmetrises A + Aᵀ, a no-op here).
  Eigen::SparseMatrix<double> pattern(n, n);
  pattern.resizeNonZeros(A.nonZeros());
  std::copy(A.outerIndexPtr(), A.outerIndexPtr() + n + 1, pattern.outerIndexPtr());
  std::copy(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), pattern.innerIndexPtr());
  std::fill(pattern.valuePtr(), pattern.valuePtr() + A.nonZeros(), 1.0);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> eliminated;
  Eigen::AMDOrdering<int>()(pattern, eliminated);  // eliminated[k]: the row taken k-th
  Eigen::SparseMatrix<double>().swap(pattern);
  order_.assign(eliminated.indices().data(), eliminated.indices().data() + n);
  position_.assign(n, 0);
  for (int k = 0; k < n; ++k) position_[order_[k]] = k;
  // Elimination tree and column counts (Davis's ldl_symbolic): row k of L reaches, from each
  // entry i < k of A's row k, up the tree to the first node already marked for k.
  parent_.assign(n, -1);
  std::vector<int> flag(n), count(n, 0);
  for (int k = 0; k < n; ++k) {
    flag[k] = k;
    const int col = order_[k];
    for (int p = A.outerIndexPtr()[col]; p < A.outerIndexPtr()[col + 1]; ++p) {
      for (int i = position_[A.innerIndexPtr()[p]]; i < k && flag[i] != k; i = parent_[i]) {
        if (parent_[i] == -1) parent_[i] = k;
        ++count[i];
        flag[i] = k;
      }
    }
  }
  columnStart_.assign(n + 1, 0);
  multiplyAdds_ = 0;
  for (int k = 0; k < n; ++k) {
    columnStart_[k + 1] = columnStart_[k] + count[k];
    multiplyAdds_ += static_cast<double>(count[k]) * count[k];
  }
  std::vector<int>().swap(rowIndex_);
  std::vector<Complex>().swap(value_);
}

bool ComplexSymmetricLdlt::factorize(const Matrix& A) {
  const int n = static_cast<int>(A.rows());
  if (columnStart_.size() != static_cast<std::size_t>(n) + 1) analyzePattern(A);
  factored_ = false;
  rowIndex_.resize(columnStart_.back());
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
      const std::int64_t end = columnStart_[i] + count[i];
      for (std::int64_t p = columnStart_[i]; p < end; ++p) subtractProductCsl(y[rowIndex_[p]], value_[p], yi);
      const Complex l = productCsl(yi, diagonal_[i]);
      subtractProductCsl(d, l, yi);
      rowIndex_[end] = k;
      value_[end] = l;
      ++count[i];
    }
    if (!std::isfinite(d.real()) || !std::isfinite(d.imag()) || d == Complex(0, 0)) return false;
    diagonal_[k] = Complex(1, 0) / d;
    if (!std::isfinite(diagonal_[k].real()) || !std::isfinite(diagonal_[k].imag())) return false;
  }
  factored_ = true;
  return true;
}

void ComplexSymmetricLdlt::solve(const Eigen::VectorXcd& b, Eigen::VectorXcd& x) const {
  const int n = static_cast<int>(order_.size());
  Eigen::VectorXcd y(n);
  for (int k = 0; k < n; ++k) y[k] = b[order_[k]];
  for (int j = 0; j < n; ++j) {  // L y = Pb
    const Complex yj = y[j];
    for (std::int64_t p = columnStart_[j]; p < columnStart_[j + 1]; ++p) subtractProductCsl(y[rowIndex_[p]], value_[p], yj);
  }
  for (int j = 0; j < n; ++j) y[j] = productCsl(y[j], diagonal_[j]);  // D
  for (int j = n - 1; j >= 0; --j) {  // Lᵀ (no conjugation)
    Complex s = y[j];
    for (std::int64_t p = columnStart_[j]; p < columnStart_[j + 1]; ++p) subtractProductCsl(s, value_[p], y[rowIndex_[p]]);
    y[j] = s;
  }
  x.resize(n);
  for (int k = 0; k < n; ++k) x[order_[k]] = y[k];
}

}  // namespace elastica
