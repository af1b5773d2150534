#include "mesh/self_intersection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace elastica {
namespace {

struct Box {
  Vec3 lo, hi;
};

Box boxOf(const TriMesh& m, const Face& f) {
  const Vec3 &a = m.positions[f[0]], &b = m.positions[f[1]], &c = m.positions[f[2]];
  return {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
}

bool overlap(const Box& x, const Box& y) {
  return (x.lo.array() <= y.hi.array()).all() && (y.lo.array() <= x.hi.array()).all();
}

// How many vertices faces f and g share; with exactly one, its positions in f and g.
int sharedVertices(const Face& f, const Face& g, int& inF, int& inG) {
  int n = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f[i] == g[j]) ++n, inF = i, inG = j;
  return n;
}

// Segment pq crosses the interior of triangle abc: p and q strictly on opposite sides of its plane
// and the crossing point strictly inside (signed volumes of the same sign). Touching counts not:
// a flow meets exact contact with probability zero, and counting it would flag fans of valid
// meshes through round-off.
bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double dp = n.dot(p - a), dq = n.dot(q - a);
  if (!((dp > 0 && dq < 0) || (dp < 0 && dq > 0))) return false;
  const Vec3 d = q - p;
  const double u = d.dot((b - p).cross(c - p));
  const double v = d.dot((c - p).cross(a - p));
  const double w = d.dot((a - p).cross(b - p));
  return (u > 0 && v > 0 && w > 0) || (u < 0 && v < 0 && w < 0);
}

// Faces sharing no vertex cross if an edge of one crosses the other. Faces sharing one vertex s
// (vcglib's rule): the segment halfway between s and the opposite edge of one face, from
// (s + a)/2 to (s + b)/2, crosses the other face, which happens when one folds through the other
// around s. Faces sharing an edge never count (a fold across an edge is a face turning over,
// which the flow checks by normals).
bool trianglesCross(const TriMesh& m, const Face& f, const Face& g) {
  const auto& P = m.positions;
  int i = -1, j = -1;
  const int shared = sharedVertices(f, g, i, j);
  if (shared == 0) {
    for (int k = 0; k < 3; ++k) {
      if (segmentCrossesTriangle(P[f[k]], P[f[(k + 1) % 3]], P[g[0]], P[g[1]], P[g[2]])) return true;
      if (segmentCrossesTriangle(P[g[k]], P[g[(k + 1) % 3]], P[f[0]], P[f[1]], P[f[2]])) return true;
    }
    return false;
  }
  if (shared != 1) return false;
  auto halfway = [&](const Face& a, int at, const Face& b) {
    const Vec3& s = P[a[at]];
    return segmentCrossesTriangle(0.5 * (s + P[a[(at + 1) % 3]]), 0.5 * (s + P[a[(at + 2) % 3]]), P[b[0]], P[b[1]],
                                  P[b[2]]);
  };
  return halfway(f, i, g) || halfway(g, j, f);
}

// Calls visit(f, g) for each pair of faces (f < g) whose boxes overlap, skipping pairs with
// neither face in `only`; stops when visit returns true.
template <class Visit>
void candidatePairs(const TriMesh& m, const std::vector<std::uint8_t>* only, Visit visit) {
  const int nf = m.faceCount();
  if (nf < 2) return;
  std::vector<Box> boxes(nf);
  Box all{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  double edgeSum = 0;
  for (int f = 0; f < nf; ++f) {
    boxes[f] = boxOf(m, m.faces[f]);
    all.lo = all.lo.cwiseMin(boxes[f].lo);
    all.hi = all.hi.cwiseMax(boxes[f].hi);
    edgeSum += (boxes[f].hi - boxes[f].lo).maxCoeff();
  }
  // Cells of about the mean box size: each face lands in a few cells, each cell holds a few faces.
  const double cell = std::max(edgeSum / nf, 1e-300);
  auto cellOf = [&](double x, int axis) {
    return static_cast<std::int64_t>(std::floor((x - all.lo[axis]) / cell));
  };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  grid.reserve(static_cast<std::size_t>(nf) * 2);
  const std::int64_t kStride = 1 << 20;  // cells per axis before keys alias (aliasing only costs tests)
  auto key = [&](std::int64_t i, std::int64_t j, std::int64_t k) { return (i * kStride + j) * kStride + k; };
  // A face much larger than the mean (a CAD sliver's long side among small faces) would cover too
  // many cells: such faces are tested against every face instead.
  auto cellsOf = [&](const Box& b) {
    double n = 1;
    for (int axis = 0; axis < 3; ++axis) n *= double(cellOf(b.hi[axis], axis) - cellOf(b.lo[axis], axis) + 1);
    return n;
  };
  constexpr double kMaxCellsPerFace = 512;
  std::vector<int> large;
  for (int f = 0; f < nf; ++f) {
    const Box& b = boxes[f];
    if (cellsOf(b) > kMaxCellsPerFace) {
      large.push_back(f);
      continue;
    }
    for (std::int64_t i = cellOf(b.lo.x(), 0); i <= cellOf(b.hi.x(), 0); ++i)
      for (std::int64_t j = cellOf(b.lo.y(), 1); j <= cellOf(b.hi.y(), 1); ++j)
        for (std::int64_t k = cellOf(b.lo.z(), 2); k <= cellOf(b.hi.z(), 2); ++k) grid[key(i, j, k)].push_back(f);
  }
  std::vector<int> seenWith(nf, -1);  // the last face f that g was tested against
  // One candidate pair, each unordered pair once: grid pairs as (f < g); pairs with a large face
  // from the large face's side (and large–large pairs from the smaller index).
  auto test = [&](int f, int g) {
    if (only && !(*only)[f] && !(*only)[g]) return false;
    if (!overlap(boxes[f], boxes[g])) return false;
    return visit(std::min(f, g), std::max(f, g));
  };
  for (int f = 0; f < nf; ++f) {
    const Box& b = boxes[f];
    if (cellsOf(b) > kMaxCellsPerFace) continue;
    for (std::int64_t i = cellOf(b.lo.x(), 0); i <= cellOf(b.hi.x(), 0); ++i)
      for (std::int64_t j = cellOf(b.lo.y(), 1); j <= cellOf(b.hi.y(), 1); ++j)
        for (std::int64_t k = cellOf(b.lo.z(), 2); k <= cellOf(b.hi.z(), 2); ++k) {
          auto cellFaces = grid.find(key(i, j, k));
          if (cellFaces == grid.end()) continue;
          for (int g : cellFaces->second) {
            if (g <= f || seenWith[g] == f) continue;
            seenWith[g] = f;
            if (test(f, g)) return;
          }
        }
  }
  std::vector<std::uint8_t> isLarge(nf, 0);
  for (int f : large) isLarge[f] = 1;
  for (int f : large)
    for (int g = 0; g < nf; ++g)
      if (g != f && !(isLarge[g] && g < f) && test(f, g)) return;
}

}  // namespace

std::vector<int> selfIntersectingFaces(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace) {
  std::vector<std::uint8_t> hit(mesh.faces.size(), 0);
  candidatePairs(mesh, onlyFace, [&](int f, int g) {
    if (trianglesCross(mesh, mesh.faces[f], mesh.faces[g])) hit[f] = hit[g] = 1;
    return false;
  });
  std::vector<int> out;
  for (int f = 0; f < mesh.faceCount(); ++f)
    if (hit[f]) out.push_back(f);
  return out;
}

bool selfIntersects(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace) {
  bool found = false;
  candidatePairs(mesh, onlyFace, [&](int f, int g) { return found = trianglesCross(mesh, mesh.faces[f], mesh.faces[g]); });
  return found;
}

}  // namespace elastica
