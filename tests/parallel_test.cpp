// The OpenMP loops (support/parallel.h): every index once, and reductions whose bits do not depend
// on how many threads the machine's load leaves them.
#include "support/parallel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace elastica;

namespace {

// Terms of very different magnitudes: a sum in another order or grouping differs in its last bits.
double term(int i) { return std::sin(0.37 * i) * std::pow(10.0, i % 17 - 8); }

}  // namespace

TEST(Parallel, ForVisitsEveryIndexOnce) {
  const int n = 3 * kParallelGrain + 7;
  std::vector<int> visits(n, 0);
  parallelFor(n, [&](int i) { ++visits[i]; });
  for (int i = 0; i < n; ++i) ASSERT_EQ(visits[i], 1) << i;
}

TEST(Parallel, TeamSizeIsBetweenOneAndOpenMpsThreads) {
  const int team = parallelTeamSize();
  EXPECT_GE(team, 1);
#ifdef _OPENMP
  EXPECT_LE(team, omp_get_max_threads());
#endif
}

// The sum is the chunked one: omp_get_max_threads() contiguous chunks as a static schedule cuts
// them, each summed in order, the partial sums added in chunk order. On one thread (SerialRegions)
// it is the same bits.
TEST(Parallel, ReductionBitsDoNotDependOnTheThreads) {
  const int n = 5 * kParallelGrain + 3;
  int chunks = 1;
#ifdef _OPENMP
  chunks = omp_get_max_threads();
#endif
  double expected = 0;
  if (chunks == 1) {
    for (int i = 0; i < n; ++i) expected += term(i);
  } else {
    const int q = n / chunks, r = n % chunks;
    for (int c = 0, begin = 0; c < chunks; ++c) {
      const int end = begin + q + (c < r ? 1 : 0);
      double part = 0;
      for (int i = begin; i < end; ++i) part += term(i);
      expected += part;
      begin = end;
    }
  }
  const double any = parallelSum(n, term);
  EXPECT_EQ(any, expected);
  const SerialRegions serial;
  EXPECT_EQ(parallelSum(n, term), expected);
}
