#include "mesh/thickness.h"
#include "mesh/box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace elastica {
namespace {

constexpr int kLeafFaces = 4;

// A bounding-volume hierarchy of the faces (median split on the longest axis of the centroids'
// box): the ray casts are O(log F) each rather than O(F).
struct FaceTree {
  struct Node {
    Box box;
    int left = -1, right = -1;  // children; -1 at a leaf
    int begin = 0, end = 0;     // the leaf's range of `order`
  };
  std::vector<Node> nodes;
  std::vector<int> order;

  explicit FaceTree(const TriMesh& mesh) {
    const int nf = mesh.faceCount();
    order.resize(nf);
    std::iota(order.begin(), order.end(), 0);
    std::vector<Vec3> centre(nf);
    for (int f = 0; f < nf; ++f) {
      const Face& t = mesh.faces[f];
      centre[f] = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3;
    }
    if (nf > 0) build(mesh, centre, 0, nf);
  }

  int build(const TriMesh& mesh, const std::vector<Vec3>& centre, int begin, int end) {
    const int id = static_cast<int>(nodes.size());
    nodes.emplace_back();
    Box box, centres;
    for (int i = begin; i < end; ++i) {
      const Box b = boxOf(mesh, mesh.faces[order[i]]);
      box.add(b.lo);
      box.add(b.hi);
      centres.add(centre[order[i]]);
    }
    nodes[id].box = box;
    if (end - begin <= kLeafFaces) {
      nodes[id].begin = begin;
      nodes[id].end = end;
      return id;
    }
    int axis = 0;
    const Vec3 extent = centres.hi - centres.lo;
    if (extent.y() > extent[axis]) axis = 1;
    if (extent.z() > extent[axis]) axis = 2;
    const int mid = begin + (end - begin) / 2;
    // Ties broken by index, so the tree (and nothing else depends on it) is the same on every run.
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](int a, int b) {
      return centre[a][axis] < centre[b][axis] || (centre[a][axis] == centre[b][axis] && a < b);
    });
    const int left = build(mesh, centre, begin, mid);
    const int right = build(mesh, centre, mid, end);
    nodes[id].left = left;
    nodes[id].right = right;
    return id;
  }
};

// Entry distance of the ray o + t d (t >= 0) into the box, or infinity if it misses it.
double rayEntersBox(const Vec3& o, const Vec3& invD, const Box& box) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double a = (box.lo[k] - o[k]) * invD[k], b = (box.hi[k] - o[k]) * invD[k];
    if (std::isnan(a) || std::isnan(b)) {  // a zero direction component along a slab face: inside or not
      if (o[k] < box.lo[k] || o[k] > box.hi[k]) return std::numeric_limits<double>::infinity();
      continue;
    }
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

// Möller–Trumbore: the distance along the ray to triangle abc (edges included), or infinity.
double rayHitsTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0 || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
  const double inv = 1 / det;
  const Vec3 s = o - a;
  const double u = s.dot(p) * inv;
  if (u < 0 || u > 1) return std::numeric_limits<double>::infinity();
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0 || u + v > 1) return std::numeric_limits<double>::infinity();
  const double t = e2.dot(q) * inv;
  return t > 0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace

std::vector<double> faceThickness(const TriMesh& mesh) {
  const int nf = mesh.faceCount();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> thickness(nf, inf);
  // Six times the enclosed volume: negative when the faces' normals point inward.
  double volume = 0;
  for (const Face& t : mesh.faces) volume += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]]));
  const double inward = volume < 0 ? 1 : -1;
  const FaceTree tree(mesh);
  std::vector<int> stack;
  for (int f = 0; f < nf; ++f) {
    const Face& t = mesh.faces[f];
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double length = n.norm();
    if (!(length > 0) || !std::isfinite(length)) continue;
    const Vec3 d = inward * n / length;
    const Vec3 o = (a + b + c) / 3;
    const Vec3 invD(1 / d.x(), 1 / d.y(), 1 / d.z());
    double best = inf;
    stack.assign(1, 0);
    while (!stack.empty()) {
      const FaceTree::Node& node = tree.nodes[stack.back()];
      stack.pop_back();
      if (!(rayEntersBox(o, invD, node.box) < best)) continue;
      if (node.left < 0) {
        for (int i = node.begin; i < node.end; ++i) {
          const int g = tree.order[i];
          if (g == f) continue;
          const Face& s = mesh.faces[g];
          best = std::min(best, rayHitsTriangle(o, d, mesh.positions[s[0]], mesh.positions[s[1]], mesh.positions[s[2]]));
        }
      } else {
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }
    thickness[f] = best;
  }
  return thickness;
}

double thinnestFeature(const TriMesh& mesh, double quantile) {
  const std::vector<double> thickness = faceThickness(mesh);
  std::vector<std::pair<double, double>> byThickness;  // (thickness, area)
  double total = 0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (!std::isfinite(thickness[f])) continue;
    const Face& t = mesh.faces[f];
    const double area =
        0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm();
    byThickness.emplace_back(thickness[f], area);
    total += area;
  }
  if (byThickness.empty() || !(total > 0)) return 0;
  std::sort(byThickness.begin(), byThickness.end());
  const double wanted = std::clamp(quantile, 0.0, 1.0) * total;
  double below = 0;
  for (const auto& [t, area] : byThickness) {
    below += area;
    if (below >= wanted) return t;
  }
  return byThickness.back().first;
}

}  // namespace elastica
