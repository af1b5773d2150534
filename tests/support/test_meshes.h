// Helpers shared by the numerical tests.
#pragma once

#include <elastica/hole_filling.h>
#include <elastica/types.h>

#include <cstdint>
#include <functional>
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

/// `m` without the faces for which `cut(centroid)` is true and the vertices left without a face.
inline TriMesh cutAway(const TriMesh& m, const std::function<bool(const Vec3&)>& cut) {
  TriMesh out;
  std::vector<int> index(m.positions.size(), -1);
  for (const Face& f : m.faces) {
    const Vec3 c = (m.positions[f[0]] + m.positions[f[1]] + m.positions[f[2]]) / 3.0;
    if (cut(c)) continue;
    Face g;
    for (int k = 0; k < 3; ++k) {
      if (index[f[k]] < 0) {
        index[f[k]] = out.vertexCount();
        out.positions.push_back(m.positions[f[k]]);
      }
      g[k] = index[f[k]];
    }
    out.faces.push_back(g);
  }
  return out;
}

}  // namespace elastica::test
