// Loops over vertices, faces and edges: across OpenMP threads on large meshes, plainly on small ones.
//
// Below kParallelGrain items a parallel region costs more than it saves, and when several
// processes share the cores (a test suite, MeshLab with other work) OpenMP's spinning threads slow
// everything down. An `if` clause on the pragma is not enough: the loop still goes through
// libgomp, whose per-region bookkeeping (a futex call each time) took a third of the time of a
// hole's flow on a 500-vertex patch. These helpers do not enter the OpenMP runtime at all below
// the grain.
#pragma once

#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace elastica {

inline constexpr int kParallelGrain = 20000;

/// body(i) for every i in [0, n), in parallel (static schedule) above kParallelGrain.
template <class Body>
void parallelFor(int n, const Body& body) {
#ifdef _OPENMP
  if (n > kParallelGrain) {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) body(i);
    return;
  }
#endif
  for (int i = 0; i < n; ++i) body(i);
}

/// Folds [0, n) into an accumulator: each thread starts from `init` and calls body(i, acc) for its
/// items (static schedule), then the partial results are joined in thread order with
/// join(acc, partial) — the same result for the same thread count on every run. (Not for bool:
/// std::vector<bool> packs bits.)
template <class Acc, class Body, class Join>
Acc parallelReduce(int n, const Acc& init, const Body& body, const Join& join) {
#ifdef _OPENMP
  if (n > kParallelGrain) {
    std::vector<Acc> partial(omp_get_max_threads(), init);
#pragma omp parallel
    {
      Acc mine = init;  // a local: threads updating neighbouring vector slots would share cache lines
#pragma omp for schedule(static) nowait
      for (int i = 0; i < n; ++i) body(i, mine);
      partial[omp_get_thread_num()] = mine;
    }
    Acc acc = init;
    for (const Acc& p : partial) join(acc, p);
    return acc;
  }
#else
  (void)join;  // one accumulator: nothing to join without OpenMP
#endif
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
