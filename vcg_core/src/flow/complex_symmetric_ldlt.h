// SPDX-License-Identifier: GPL-3.0-or-later
// Sparse LDLᵀ of a complex SYMMETRIC matrix (Aᵀ = A, no conjugation), without pivoting: the
// fairing amount's one-ring form M + i s C (flow/principal_part_filter.h), whose real part M is
// positive definite, so every leading block is nonsingular and the factorisation exists for any
// symmetric ordering, even where C is indefinite (the clamped cotangents of slivers). CHOLMOD
// factorises Hermitian matrices only and Eigen's SimplicialLDLT conjugates, hence our own:
// Eigen's AMD ordering on the pattern, the elimination tree and column counts, then T. Davis's
// up-looking LDL ("Algorithm 849", ACM TOMS 31, 2005), written here for std::complex<double>.
// Serial: the same bits at any thread count.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

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
  /// Solves A X = B for the columns of B with the last successful factorisation, one pass over
  /// the factor for all of them (B and X may be the same matrix).
  void solve(const Eigen::MatrixXcd& B, Eigen::MatrixXcd& X) const;

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
  std::vector<std::int64_t> columnStart_;
  std::vector<int> rowIndex_;  // L, strictly lower, by column
  std::vector<Complex> value_;
  std::vector<Complex> diagonal_;
  double multiplyAdds_ = 0;
  bool factored_ = false;
};

}  // namespace elastica
