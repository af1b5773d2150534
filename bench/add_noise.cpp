// SPDX-License-Identifier: GPL-3.0-or-later
// add_noise IN OUT AMOUNT SEED: a noisy copy of a mesh for the denoising table (bench/denoise.sh):
// every vertex moved by a vector drawn uniformly from the ball of radius AMOUNT × the mesh's mean
// edge length (3-D noise: tangential as well as normal, as a scanner's is). Binary PLY.
#include <elastica/geometry.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/topology.h>

#include "test_meshes.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <utility>

using namespace elastica;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: add_noise IN OUT AMOUNT SEED\n");
    return 2;
  }
  try {
    TriMesh m = io::readMesh(argv[1]).mesh;
    const double radius = std::atof(argv[3]) * meanEdgeLength(Topology(m.vertexCount(), m.faces), m.positions);
    m = test::ballJittered(std::move(m), radius, static_cast<unsigned>(std::atoi(argv[4])));
    io::writePly(argv[2], m, {}, true);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "add_noise: %s\n", e.what());
    return 1;
  }
  return 0;
}
