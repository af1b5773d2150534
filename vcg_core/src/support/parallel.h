// SPDX-License-Identifier: GPL-3.0-or-later
// Loops over vertices, faces and edges: across OpenMP threads on large meshes, plainly on small ones.
//
// Below kParallelGrain items a parallel region costs more than it saves, and when several
// processes share the cores (a test suite, MeshLab with other work) OpenMP's spinning threads slow
// everything down. An `if` clause on the pragma is not enough: the loop still goes through
// libgomp, whose per-region bookkeeping (a futex call each time) took a third of the time of a
// hole's flow on a 500-vertex patch. These helpers do not enter the OpenMP runtime at all below
// the grain.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace elastica {

inline constexpr int kParallelGrain = 20000;

/// The threads a parallel region gets: OpenMP's (OMP_NUM_THREADS or the cores), fewer when other
/// processes keep the cores busy. A region's threads meet at barriers; a thread that the kernel
/// has given to another process holds the others there, spinning. On this 2-core machine beside
/// another job (load 2.4), the default fair of a 163,842-vertex sphere took 11.4 s on two threads
/// and 7.7 s on one. The one-minute load average counts this process's own busy thread, so a core
/// is taken as free while load − 1 leaves it so; read at most once a second per calling thread.
inline int parallelTeamSize() {
#ifdef _OPENMP
  thread_local int cached = 0;
  thread_local std::chrono::steady_clock::time_point readAt;
  const auto now = std::chrono::steady_clock::now();
  if (cached == 0 || now - readAt > std::chrono::seconds(1)) {
    const int threads = omp_get_max_threads();
    double load = 0;
    cached = threads;
    if (getloadavg(&load, 1) == 1)
      cached = std::clamp(static_cast<int>(std::lround(omp_get_num_procs() + 1 - load)), 1, threads);
    readAt = now;
  }
  return cached;
#else
  return 1;
#endif
}

/// body(i) for every i in [0, n), in parallel (static schedule) above kParallelGrain.
template <class Body>
void parallelFor(int n, const Body& body) {
#ifdef _OPENMP
  if (n > kParallelGrain) {
    const int team = parallelTeamSize();
#pragma omp parallel for schedule(static) num_threads(team) if (team > 1)
    for (int i = 0; i < n; ++i) body(i);
    return;
  }
#endif
  for (int i = 0; i < n; ++i) body(i);
}

/// Folds [0, n) into an accumulator. Above kParallelGrain the range is cut into kReduceChunks
/// contiguous chunks, each folded from `init` with body(i, acc), and the partial results are joined
/// in chunk order with join(acc, partial); below it, one accumulator folds the whole range. The
/// chunks are the same whatever runs them (OMP_NUM_THREADS, parallelTeamSize, a build without
/// OpenMP), so the result's bits never depend on the machine, its core count or its load.
/// (Not for bool: std::vector<bool> packs bits.)
inline constexpr int kReduceChunks = 16;
template <class Acc, class Body, class Join>
Acc parallelReduce(int n, const Acc& init, const Body& body, const Join& join) {
  if (n > kParallelGrain) {
    std::vector<Acc> partial(kReduceChunks, init);
    auto fold = [&](int c) {
      const int q = n / kReduceChunks, r = n % kReduceChunks;  // the first r chunks get one more
      const int begin = c * q + (c < r ? c : r), end = begin + q + (c < r ? 1 : 0);
      Acc mine = init;  // a local: threads updating neighbouring vector slots would share cache lines
      for (int i = begin; i < end; ++i) body(i, mine);
      partial[c] = mine;
    };
#ifdef _OPENMP
    const int team = parallelTeamSize();
#pragma omp parallel for schedule(static) num_threads(team) if (team > 1)
    for (int c = 0; c < kReduceChunks; ++c) fold(c);
#else
    for (int c = 0; c < kReduceChunks; ++c) fold(c);
#endif
    Acc acc = init;
    for (const Acc& p : partial) join(acc, p);
    return acc;
  }
  Acc acc = init;
  for (int i = 0; i < n; ++i) body(i, acc);
  return acc;
}

/// While one is alive (and `on`), every parallel region runs on the calling thread alone; the
/// setting is put back after. For work made of many small regions on a shared machine: libgomp's
/// idle threads spin between regions, and on a 2-core machine with other jobs running a hole's
/// fill took 2.7 times as long with its regions on two threads as on one.
class SerialRegions {
 public:
#ifdef _OPENMP
  explicit SerialRegions(bool on = true) : on_(on), levels_(omp_get_max_active_levels()) {
    if (on_) omp_set_max_active_levels(0);
  }
  ~SerialRegions() {
    if (on_) omp_set_max_active_levels(levels_);
  }
  SerialRegions(const SerialRegions&) = delete;
  SerialRegions& operator=(const SerialRegions&) = delete;

 private:
  bool on_;
  int levels_;
#else
  explicit SerialRegions(bool = true) {}
#endif
};

/// Σ body(i) over [0, n).
template <class Body>
double parallelSum(int n, const Body& body) {
  return parallelReduce(
      n, 0.0, [&](int i, double& s) { s += body(i); }, [](double& s, double p) { s += p; });
}

}  // namespace elastica
