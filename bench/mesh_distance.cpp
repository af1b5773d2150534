// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_distance A B: how far two surfaces are apart, both ways, for the denoising table
// (bench/denoise.sh): the RMS and largest distance from points sampled on A's faces to B's surface,
// and from B's to A's, each also as a fraction of B's bounding-box diagonal. One JSON line.
#include "surface_distance.h"

#include <elastica/geometry.h>
#include <elastica/io/mesh_reader.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <exception>
#include <iostream>

using namespace elastica;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mesh_distance A B\n");
    return 2;
  }
  try {
    const TriMesh a = io::readMesh(argv[1]).mesh, b = io::readMesh(argv[2]).mesh;
    const double diagonal = boundingBoxDiagonal(b.positions);
    const bench::DistanceStats ab = bench::sampledDistance(a, b, 3), ba = bench::sampledDistance(b, a, 3);
    nlohmann::json j;
    j["a"] = argv[1];
    j["b"] = argv[2];
    j["diagonal"] = diagonal;
    j["a_to_b"] = {{"rms", ab.rms}, {"max", ab.max}, {"rms_per_diagonal", ab.rms / diagonal}};
    j["b_to_a"] = {{"rms", ba.rms}, {"max", ba.max}, {"rms_per_diagonal", ba.rms / diagonal}};
    std::cout << j.dump() << "\n";
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mesh_distance: %s\n", e.what());
    return 1;
  }
  return 0;
}
