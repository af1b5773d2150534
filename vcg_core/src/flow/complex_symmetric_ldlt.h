// SPDX-License-Identifier: GPL-3.0-or-later
// Sparse LDLᵀ of a complex SYMMETRIC matrix (Aᵀ = A, no conjugation), without pivoting: the
// fairing amount's one-ring form M + i s C (flow/principal_part_filter.h), whose real part M is
// positive definite, so every leading block is nonsingular and the factorisation exists for any
// symmetric ordering, even where C is indefinite (the clamped cotangents of slivers). CHOLMOD
// factorises Hermitian matrices only and Eigen's SimplicialLDLT conjugates, hence our own:
// Eigen's AMD ordering on the pattern, the elimination tree and column counts, then T. Davis's
// up-looking LDL ("Algorithm 849", ACM TOMS 31, 2005), written here for std::complex<double>,
// with the row indices stored once per supernode.
// Serial: the same bits at any thread count.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <complex>
#include <cstdint>
#include <vector>

namespace elastica {

class ComplexSymmetricLdlt {
 public:
  using Complex = std::complex<double>;
  using Matrix = Eigen::SparseMatrix<Complex>;  // column-major, compressed, both triangles stored

  /// Orders the pattern of `A` (square, symmetric, both triangles) and works out the factor's
  /// column counts. Call again only when the pattern changes.
  void analyzePattern(const Matrix& A);
  /// The numeric factorisation of `A` (the analysed pattern). False on a zero or non-finite pivot.
  bool factorize(const Matrix& A);
  /// The entries of `A` (the analysed pattern) that factorize() reads: those on or above the
  /// diagonal in the elimination order, half of them, in A's order, so that the factorisation of
  /// the result is the same bits. For a caller whose matrix sits beside the factor at its peak.
  Matrix factorizedPart(const Matrix& A) const;
  /// Solves A X = B for the columns of B with the last successful factorisation, one pass over
  /// the factor for all of them (B and X may be the same matrix).
  void solve(const Eigen::MatrixXcd& B, Eigen::MatrixXcd& X) const;
  /// Re[A⁻¹ B] for real B: what solve() gives for B's complex copy, the same arithmetic, without
  /// the copy (at 711,420 rows and three columns a complex matrix is 34 MB of the run's peak).
  void solveRealPart(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const;

  /// Nonzeros of L below the diagonal (after analyzePattern).
  std::int64_t factorNonZeros() const { return columnStart_.empty() ? 0 : columnStart_.back(); }
  /// Complex multiply-adds of the numeric factorisation (after analyzePattern): Σ_j c_j (c_j + 1) / 2,
  /// c_j the nonzeros of L's column j below the diagonal.
  double multiplyAdds() const { return multiplyAdds_; }
  bool factored() const { return factored_; }
  /// Frees the factor and its workspace.
  void clear();

 private:
  std::vector<int> order_, position_;  // order_[k]: the row eliminated k-th; position_ its inverse
  std::vector<int> parent_;            // elimination tree of the permuted matrix
  // Row indices per supernode (consecutive columns j, j + 1, …, last whose patterns nest: a chain
  // of the elimination tree with counts falling by one): column j's rows are j + 1 … last, then
  // the rows only the last column stores. One record per column: one load where the factorisation
  // visits it. On a 711,420-vertex scan the default fair's peak RSS went 1,374 → 1,279 MB
  // (docs/decisions.md, "The amount's solver").
  struct ColumnRows {
    std::int64_t stored = 0;  // rowIndex_ offset of the column's entry `implied` (its first stored row)
    int implied = 0;          // last − j: the rows j + 1 … last, not stored
  };
  // The solve in the elimination order, in place: y's row k is the right-hand side's row order_[k].
  using Rows = Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  void solvePermuted(Rows& y) const;
  // Calls f(t, row) for the first `entries` rows of L's column j, in ascending order: the order,
  // and so the arithmetic, of a row index per entry.
  template <class F>
  void forEachRow(int j, std::int64_t entries, F&& f) const {
    const ColumnRows& c = columnRows_[j];
    const std::int64_t implied = std::min<std::int64_t>(entries, c.implied);
    std::int64_t t = 0;
    for (; t < implied; ++t) f(t, j + 1 + static_cast<int>(t));
    for (; t < entries; ++t) f(t, rowIndex_[static_cast<std::size_t>(c.stored + t)]);  // c.stored + t ≥ 0 here
  }

  std::vector<std::int64_t> columnStart_;  // L's values of column j: value_[columnStart_[j] …]
  std::vector<ColumnRows> columnRows_;
  std::int64_t storedRows_ = 0;
  std::vector<int> rowIndex_;  // the supernodes' last columns' rows, strictly lower
  std::vector<Complex> value_;
  std::vector<Complex> diagonal_;
  double multiplyAdds_ = 0;
  bool factored_ = false;
};

}  // namespace elastica
