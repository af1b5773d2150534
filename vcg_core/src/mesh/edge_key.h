// SPDX-License-Identifier: GPL-3.0-or-later
// An undirected edge packed in one integer, for hash sets and maps of edges (subdivision, flips).
#pragma once

#include <algorithm>
#include <cstdint>

namespace elastica {

/// The same key for (a, b) and (b, a): the smaller index in the high 32 bits.
inline std::uint64_t edgeKey(int a, int b) {
  const auto [lo, hi] = std::minmax(a, b);
  return (std::uint64_t(std::uint32_t(lo)) << 32) | std::uint32_t(hi);
}

}  // namespace elastica
