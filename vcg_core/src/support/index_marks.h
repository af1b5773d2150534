// SPDX-License-Identifier: GPL-3.0-or-later
// A set of indices below n as bits, read back in ascending order: a piece's faces and vertices
// gathered in the mesh's order without a sort (the curvature and the flow's energy measured a
// piece at a time: sorting each piece's faces and vertices cost 1.5 s of a 711k-vertex run).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace elastica {

class IndexMarks {
 public:
  explicit IndexMarks(std::size_t n) : bits_((n + 63) / 64, 0) {}
  void mark(int i) {
    const std::size_t w = static_cast<std::size_t>(i) >> 6;
    bits_[w] |= std::uint64_t{1} << (i & 63);
    low_ = std::min(low_, w);
    high_ = std::max(high_, w + 1);
  }
  /// The marked indices in ascending order into `out` (replacing its contents); the marks are cleared.
  void take(std::vector<int>& out) {
    out.clear();
    for (std::size_t w = low_; w < high_; ++w) {
      for (std::uint64_t b = bits_[w]; b != 0; b &= b - 1)
        out.push_back(static_cast<int>(64 * w + static_cast<std::size_t>(__builtin_ctzll(b))));
      bits_[w] = 0;
    }
    low_ = bits_.size(), high_ = 0;
  }

 private:
  std::vector<std::uint64_t> bits_;
  std::size_t low_ = bits_.size(), high_ = 0;  // the marked words: [low_, high_)
};

}  // namespace elastica
