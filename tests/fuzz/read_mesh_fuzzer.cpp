// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: one mesh reader (the format is fixed at compile time by ELASTICA_FUZZ_EXT,
// since readMesh picks the reader by extension), then the operators on whatever it accepted.
// A thrown elastica::Error is the expected answer to bad input; anything else (a crash, a
// sanitizer report, another exception, a non-finite curvature) is a bug.
#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/topology.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// The readers take a path: write the input to a file in memory-backed /dev/shm if there is one.
const std::string& scratchPath() {
  static const std::string path = [] {
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    return std::string(dir) + "/elastica-fuzz-" + std::to_string(getpid()) + ELASTICA_FUZZ_EXT;
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratchPath();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);

  elastica::io::MeshFile file;
  try {
    file = elastica::io::readMesh(path);
  } catch (const elastica::Error&) {
    return 0;
  }
  // Accepted: the mesh must be one the core takes as it is, the selection one byte per face.
  const elastica::TriMesh& mesh = file.mesh;
  if (file.report.hasFaceSelection != !file.faceSelection.empty() && mesh.faceCount() > 0) std::abort();
  if (!file.faceSelection.empty() && file.faceSelection.size() != mesh.faces.size()) std::abort();
  const elastica::Topology topo(mesh.vertexCount(), mesh.faces);
  if (topo.faceCount() == 0 || topo.nonManifoldVertexCount() != 0 || topo.inconsistentEdgeCount() != 0) std::abort();
  const elastica::Geometry geo = elastica::computeGeometry(topo, mesh.positions);
  const elastica::Curvature c = elastica::computeCurvature(topo, geo, mesh.positions);
  const double e = elastica::totalCurvatureEnergy(topo, geo, c);
  // Finite input gives finite curvature unless coordinates are so large that squares overflow.
  double extent = 0;
  for (const auto& p : mesh.positions) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  if (extent < 1e100 && !std::isfinite(e)) std::abort();
  return 0;
}
