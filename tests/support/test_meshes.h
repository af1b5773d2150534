// Helpers shared by the numerical tests.
#pragma once

#include <elastica/hole_filling.h>
#include <elastica/types.h>

#include <cstdint>
#include <random>
#include <vector>

namespace elastica::test {

/// One byte per face of `filled`: 1 on the faces fillHoles added.
inline std::vector<std::uint8_t> newFaceFlags(const TriMesh& filled, const HoleFillReport& r) {
  std::vector<std::uint8_t> flags(filled.faces.size());
  for (int f = 0; f < filled.faceCount(); ++f) flags[f] = r.isNewFace(f);
  return flags;
}

/// Scales all positions of `m` by `s` about the origin.
inline TriMesh scaled(TriMesh m, double s) {
  for (Vec3& p : m.positions) p *= s;
  return m;
}

/// Reverses the orientation of every face.
inline TriMesh flipped(TriMesh m) {
  for (Face& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

/// Moves each vertex by a uniform random offset of at most `amplitude` along each axis.
inline TriMesh jittered(TriMesh m, double amplitude, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Vec3& p : m.positions) p += Vec3(u(rng), u(rng), u(rng));
  return m;
}

}  // namespace elastica::test
