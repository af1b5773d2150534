// SPDX-License-Identifier: GPL-3.0-or-later
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

// The sum is the chunked one: kReduceChunks contiguous chunks, each summed in order, the partial
// sums added in chunk order, whatever the number of threads (1, 2, 3, 4, or every region made
// serial): the same bits, written out here independently of the helper.
TEST(Parallel, ReductionBitsDoNotDependOnTheThreads) {
  const int n = 5 * kParallelGrain + 3;
  double expected = 0;
  const int q = n / kReduceChunks, r = n % kReduceChunks;
  for (int c = 0, begin = 0; c < kReduceChunks; ++c) {
    const int end = begin + q + (c < r ? 1 : 0);
    double part = 0;
    for (int i = begin; i < end; ++i) part += term(i);
    expected += part;
    begin = end;
  }
  EXPECT_EQ(parallelSum(n, term), expected);
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
  for (int t : {1, 2, 3, 4}) {
    omp_set_num_threads(t);
    EXPECT_EQ(parallelSum(n, term), expected) << t << " threads";
  }
  omp_set_num_threads(threads);
#endif
  const SerialRegions serial;
  EXPECT_EQ(parallelSum(n, term), expected);
}

// Below the grain one accumulator folds the range in order.
TEST(Parallel, SmallReductionIsOneOrderedSum) {
  const int n = kParallelGrain;
  double expected = 0;
  for (int i = 0; i < n; ++i) expected += term(i);
  EXPECT_EQ(parallelSum(n, term), expected);
}
