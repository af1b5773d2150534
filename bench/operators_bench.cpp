// SPDX-License-Identifier: GPL-3.0-or-later
// Throughput of one geometry + curvature pass (what every explicit flow step recomputes),
// in vertices per second, on icospheres of 10 k, 41 k and 164 k vertices.
#include <elastica/curvature.h>
#include <elastica/shapes.h>

#include <benchmark/benchmark.h>

namespace {

void BM_GeometryAndCurvature(benchmark::State& state) {
  const elastica::TriMesh m = elastica::shapes::icosphere(1.0, static_cast<int>(state.range(0)));
  const elastica::Topology topo(m.vertexCount(), m.faces);
  elastica::Geometry geo;
  elastica::Curvature curv;
  std::vector<elastica::Vec3> lp;
  for (auto _ : state) {
    elastica::computeGeometry(topo, m.positions, elastica::VertexArea::Mixed, geo);
    elastica::computeCurvature(topo, geo, m.positions, {}, curv, lp);
    benchmark::DoNotOptimize(curv.H.data());
  }
  state.SetItemsProcessed(state.iterations() * m.vertexCount());
  state.counters["vertices"] = m.vertexCount();
}
BENCHMARK(BM_GeometryAndCurvature)->Arg(5)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
