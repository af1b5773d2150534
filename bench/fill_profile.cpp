// SPDX-License-Identifier: GPL-3.0-or-later
// Where a fill's time goes: fills the holes of one mesh (a holed scan written by
// `restoration_sweep --write-dir`) with `elastica fill`'s defaults, several times in one process,
// and prints each run's time (wall, and the process's CPU time: steadier on a loaded machine) and
// the stages' times of the fastest run (what the sweep's ms column
// measures, without reading, writing or scoring; run it under `perf record` for a profile).
//
//   fill_profile MESH [--runs N] [--write OUT.ply]
//
// --write saves the filled mesh as restoration_sweep writes its `_elastica.ply` (to compare the
// patches of two builds byte for byte).
#include "guarded_main.h"

#include <elastica/hole_filling.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace elastica;

static double cpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec;
}

static int run(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH [--runs N] [--write OUT.ply]\n", argv[0]);
    return 2;
  }
  int runs = 5;
  std::string out;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) {
      runs = std::max(std::atoi(argv[++i]), 1);
    } else if (a == "--write" && i + 1 < argc) {
      out = argv[++i];
    } else {
      std::fprintf(stderr, "fill_profile: unknown or incomplete argument %s\n", a.c_str());
      return 2;
    }
  }
  VcgMesh vm;
  io::readMesh(argv[1], vm);
  const TriMesh holed = toTriMesh(vm);
  HoleFillOptions opt;
  opt.maxHoleEdges = 1000000;  // as restoration_sweep
  HoleFillReport best;
  TriMesh filled;
  double bestMs = 0, bestCpu = 0;
  for (int r = 0; r < runs; ++r) {
    TriMesh m = holed;
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = cpuMs();
    HoleFillReport report = fillHoles(m, opt);
    const double ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = cpuMs() - cpuStart;
    std::printf("run %d: %.1f ms (cpu %.1f ms), %d new vertices\n", r + 1, ms, cpu, m.vertexCount() - holed.vertexCount());
    bestCpu = r == 0 ? cpu : std::min(bestCpu, cpu);
    if (r == 0 || ms < bestMs) bestMs = ms, best = std::move(report);
    if (r == 0) filled = std::move(m);
  }
  if (!out.empty()) {
    VcgMesh w;
    fromTriMesh(filled, w);
    io::writePly(out, w, io::PlyWriteOptions{});
  }
  std::printf("fastest: %.1f ms (least cpu %.1f ms)\n", bestMs, bestCpu);
  for (const HoleReport& h : best.holes) {
    std::printf("hole of %d edges: %.1f ms, %d new vertices, %.3f deg (the border allows %.3f), %lld steps\n",
                h.borderEdges, 1e3 * h.seconds, h.newVertices, h.minAngleDegrees, h.borderBoundDegrees, h.steps);
    for (const FillStageReport& s : h.stages)
      std::printf("  %-34s %8.1f ms  %s  %5.1f deg  E %.4f  %lld steps %s\n", s.stage.c_str(), 1e3 * s.seconds,
                  s.kept ? "kept" : "    ", s.minAngleDegrees, s.energy, s.steps, s.why.c_str());
  }
  return 0;
}

int main(int argc, char** argv) { return bench::guardedMain("fill_profile", run, argc, argv); }
