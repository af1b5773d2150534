#include "surface_distance.h"

#include "mesh/box.h"
#include "mesh/face_tree.h"
#include "mesh/surface_projection.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace elastica::bench {

DistanceStats sampledDistance(const TriMesh& a, const TriMesh& b, int perEdge) {
  if (b.faces.empty()) return {};
  // The core's bounding-box tree over b's faces: the exact nearest face, as brute force would find
  // it, in time that grows with the sampled mesh, not with both (a 2,000-edge hole's patch and
  // truth hold ~10^5 faces each).
  std::vector<Box> boxes;
  boxes.reserve(b.faces.size());
  for (const Face& f : b.faces) boxes.push_back(boxOf(b, f));
  const BoxTree tree(boxes);
  auto faceDistance2 = [&](int face, const Vec3& p) {
    const Face& g = b.faces[face];
    return (closestOnTriangle(p, b.positions[g[0]], b.positions[g[1]], b.positions[g[2]]) - p).squaredNorm();
  };
  double sum = 0, worst = 0;
  long count = 0;
  for (const Face& f : a.faces) {
    for (int i = 0; i <= perEdge; ++i) {
      for (int j = 0; i + j <= perEdge; ++j) {
        const double u = double(i) / perEdge, v = double(j) / perEdge;
        const Vec3 p = (1 - u - v) * a.positions[f[0]] + u * a.positions[f[1]] + v * a.positions[f[2]];
        const double best = tree.nearest(p, faceDistance2).second;
        sum += best;
        worst = std::max(worst, best);
        ++count;
      }
    }
  }
  return {count ? std::sqrt(sum / count) : 0, std::sqrt(worst)};
}

TriMesh facesOf(const TriMesh& m, const std::vector<std::uint8_t>& keep) {
  TriMesh out;
  std::vector<int> index(m.positions.size(), -1);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!keep[f]) continue;
    Face t;
    for (int k = 0; k < 3; ++k) {
      int& i = index[m.faces[f][k]];
      if (i < 0) {
        i = out.vertexCount();
        out.positions.push_back(m.positions[m.faces[f][k]]);
      }
      t[k] = i;
    }
    out.faces.push_back(t);
  }
  return out;
}

}  // namespace elastica::bench
