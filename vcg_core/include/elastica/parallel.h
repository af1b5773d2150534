// When loops run in parallel. Below this many items a parallel region costs more than it saves,
// and when several processes share the cores (a test suite, MeshLab with other work) OpenMP's
// spinning threads slow everything down: small meshes run single-threaded.
#pragma once

namespace elastica {

inline constexpr int kParallelGrain = 20000;

}  // namespace elastica
