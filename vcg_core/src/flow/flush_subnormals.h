// SPDX-License-Identifier: GPL-3.0-or-later
// A matrix close to its diagonal (M + τ/2 · C M⁻¹ C at a small τ: a fairing amount's filter, or its
// one-ring form M + i s C) has factor entries that decay geometrically with the distance in the
// mesh, down into subnormal numbers, on which the CPU's arithmetic is about a hundred times slower.
// Subnormal results are flushed to zero (and subnormal inputs read as zero) while a FlushSubnormals
// is alive; no value that matters to a solve is below 1e-308. The previous setting is put back after.
#pragma once

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace elastica {

class FlushSubnormals {
 public:
#if defined(__SSE__)
  FlushSubnormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
  ~FlushSubnormals() { _mm_setcsr(saved_); }

 private:
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  unsigned saved_;
#endif
};

}  // namespace elastica
