// SPDX-License-Identifier: GPL-3.0-or-later
// Comparisons several tests share: bit-for-bit positions and a solve's relative difference. One
// definition here, not one per file, so the files can share a unity build.
#pragma once

#include <elastica/types.h>

#include <Eigen/Dense>

#include <cstring>

namespace elastica::test {

/// `a` and `b` hold the same bits (so -0.0 differs from 0.0, and a NaN can equal itself).
inline bool bitEqual(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; }

/// The largest difference of `x` from `direct`, relative to `direct`'s largest entry.
inline double relativeDifference(const Eigen::MatrixXd& x, const Eigen::MatrixXd& direct) {
  return (x - direct).lpNorm<Eigen::Infinity>() / direct.lpNorm<Eigen::Infinity>();
}

}  // namespace elastica::test
