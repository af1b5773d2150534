// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/secant_pairs.h"

#include <cmath>

namespace elastica {
namespace {

// A pair whose curvature s·y is below this fraction of |s||y| is dropped: W along s is then nearly
// flat or concave (a flip of the mesh between the two gradients can make y point anywhere), and
// 1/(s·y) would blow the update up.
constexpr double kMinCurvature = 1e-8;

}  // namespace

double frobeniusDot(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double sum = 0;
  for (Eigen::Index c = 0; c < a.cols(); ++c)
    for (Eigen::Index r = 0; r < a.rows(); ++r) sum += a(r, c) * b(r, c);
  return sum;
}

bool SecantPairs::add(const Eigen::MatrixXd& s, const Eigen::MatrixXd& y) {
  const double sy = frobeniusDot(s, y);
  const double scale = std::sqrt(frobeniusDot(s, s) * frobeniusDot(y, y));
  if (!(sy > kMinCurvature * scale) || !std::isfinite(sy)) return false;
  pairs_.push_back({s, y, 1 / sy});
  if (static_cast<int>(pairs_.size()) > capacity_) pairs_.pop_front();
  return true;
}

bool SecantPairs::apply(const Eigen::MatrixXd& g,
                        const std::function<bool(const Eigen::MatrixXd&, Eigen::MatrixXd&)>& applyH0,
                        Eigen::MatrixXd& hg) const {
  Eigen::MatrixXd q = g;
  alpha_.assign(pairs_.size(), 0.0);
  for (int i = size() - 1; i >= 0; --i) {  // newest first
    alpha_[i] = pairs_[i].rho * frobeniusDot(pairs_[i].s, q);
    q -= alpha_[i] * pairs_[i].y;
  }
  if (!applyH0(q, hg)) return false;
  for (int i = 0; i < size(); ++i) {  // oldest first
    const double beta = pairs_[i].rho * frobeniusDot(pairs_[i].y, hg);
    hg += (alpha_[i] - beta) * pairs_[i].s;
  }
  return true;
}

}  // namespace elastica
