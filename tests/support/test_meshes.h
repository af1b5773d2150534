// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the numerical tests.
#pragma once

#include <elastica/hole_filling.h>
#include <elastica/types.h>

#include <algorithm>
#include <array>
#include <cmath>
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

/// A unit UV sphere (latitude-longitude): `segments` meridians, `rings` bands from pole to pole,
/// a vertex of valence `segments` at each pole. Its polar triangles are needles of angle
/// 360°/segments: the irregular mesh a modelling program makes, not an icosphere.
inline TriMesh uvSphere(int segments, int rings) {
  TriMesh m;
  m.positions.emplace_back(0, 0, 1);
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = M_PI * i / rings, phi = 2 * M_PI * j / segments;
      m.positions.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  m.positions.emplace_back(0, 0, -1);
  const int south = static_cast<int>(m.positions.size()) - 1;
  auto at = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) m.faces.push_back({0, at(1, j), at(1, j + 1)});
  for (int i = 1; i < rings - 1; ++i)
    for (int j = 0; j < segments; ++j) {
      m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  for (int j = 0; j < segments; ++j) m.faces.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
  return m;
}

/// Moves each vertex by a uniform random offset of at most `amplitude` along each axis.
inline TriMesh jittered(TriMesh m, double amplitude, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Vec3& p : m.positions) p += Vec3(u(rng), u(rng), u(rng));
  return m;
}

/// Moves each vertex by a vector drawn uniformly from the ball of radius `radius` (3-D noise, as
/// bench/add_noise makes for the denoising table: tangential as well as normal).
inline TriMesh ballJittered(TriMesh m, double radius, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (Vec3& p : m.positions) {
    Vec3 d;
    do d = Vec3(u(rng), u(rng), u(rng));
    while (d.squaredNorm() > 1);
    p += radius * d;
  }
  return m;
}

/// Whether every vertex of `before` flagged in `kept` is a vertex of `after`, bit for bit (a
/// remeshing may renumber the vertices it does not move).
inline bool keepsPositions(const TriMesh& before, const std::vector<std::uint8_t>& kept, const TriMesh& after) {
  std::vector<std::array<double, 3>> points;
  for (const Vec3& p : after.positions) points.push_back({p.x(), p.y(), p.z()});
  std::sort(points.begin(), points.end());
  for (std::size_t v = 0; v < before.positions.size(); ++v) {
    const Vec3& p = before.positions[v];
    if (kept[v] && !std::binary_search(points.begin(), points.end(), std::array<double, 3>{p.x(), p.y(), p.z()}))
      return false;
  }
  return true;
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
