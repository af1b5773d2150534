// Whole-mesh checks after reading, on the file's own vertex numbers (so messages point into the
// file), and the repairs that change no geometry:
//   refused   non-finite coordinates, out-of-range indices, non-manifold edges (which faces to
//             drop is the user's call), inconsistent orientation, no faces left;
//   repaired  coincident vertices merged (STL stores every corner apart; exporters split seams),
//             faces with a repeated vertex and exact duplicate faces removed (no area, no shape),
//             bow-tie vertices split into one vertex per fan, unreferenced vertices dropped.
// Zero-area faces with three distinct vertices stay: the operators give them zero weight, and
// the flow refuses slivers where they would stall it.
#include "readers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace elastica::io::detail {
namespace {

// Coordinates beyond this overflow what the operators and the flow compute from them (squared
// lengths, areas², the explicit step ∝ A_min²); no physical model is that large in any unit.
constexpr double kMaxCoordinate = 1e30;

using Tri = std::array<int, 3>;

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Sorted half-edges: runs of equal (lo, hi) are the faces around one edge.
struct HalfEdge {
  int lo, hi, face;
  bool forward;
};

void checkEdges(const std::string& path, const std::vector<Tri>& faces, bool merged) {
  std::vector<HalfEdge> half;
  half.reserve(3 * faces.size());
  for (int f = 0; f < static_cast<int>(faces.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      half.push_back({std::min(a, b), std::max(a, b), f, a < b});
    }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.face < y.face);
  });
  size_t inconsistent = 0;
  const HalfEdge* firstInconsistent = nullptr;
  for (size_t i = 0; i < half.size();) {
    size_t j = i + 1;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    if (j - i > 2)
      fail(path, "non-manifold edge between vertices " + std::to_string(half[i].lo) + " and " + std::to_string(half[i].hi) +
                     " (shared by " + std::to_string(j - i) + " faces" + (merged ? ", after merging coincident vertices" : "") +
                     "); not repaired automatically: remove the extra faces, e.g. in MeshLab: Filters > Cleaning and "
                     "Repairing > Repair non Manifold Edges");
    if (j - i == 2 && half[i].forward == half[i + 1].forward) {
      if (!firstInconsistent) firstInconsistent = &half[i];
      ++inconsistent;
    }
    i = j;
  }
  if (inconsistent > 0)
    fail(path, "faces are not consistently oriented (" + std::to_string(inconsistent) +
                   (inconsistent == 1 ? " edge" : " edges") + " traversed the same way by both faces, the first between vertices " +
                   std::to_string(firstInconsistent->lo) + " and " + std::to_string(firstInconsistent->hi) +
                   "); re-orient them first, e.g. in MeshLab: Filters > Normals > Re-Orient all faces coherently");
}

// Splits every vertex whose faces form several fans (joined across edges at the vertex) into
// one vertex per fan; new vertices are appended to `positions`. Returns how many were split.
int splitBowTies(std::vector<Tri>& faces, std::vector<vcg::Point3d>& positions) {
  const int nv = static_cast<int>(positions.size());
  std::vector<int> offset(nv + 1, 0), corners(3 * faces.size());
  for (const Tri& t : faces)
    for (int v : t) ++offset[v + 1];
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<int> cursor(offset.begin(), offset.end() - 1);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f)
    for (int k = 0; k < 3; ++k) corners[cursor[faces[f][k]]++] = 3 * f + k;

  int split = 0;
  std::vector<std::pair<int, int>> spokes;  // (other vertex of an edge at v, local corner)
  std::vector<int> parent;
  for (int v = 0; v < nv; ++v) {
    const int n = offset[v + 1] - offset[v];
    if (n < 2) continue;
    spokes.clear();
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0);
    for (int i = 0; i < n; ++i) {
      const int c = corners[offset[v] + i];
      spokes.emplace_back(faces[c / 3][(c % 3 + 1) % 3], i);
      spokes.emplace_back(faces[c / 3][(c % 3 + 2) % 3], i);
    }
    std::sort(spokes.begin(), spokes.end());
    for (size_t i = 1; i < spokes.size(); ++i)
      if (spokes[i].first == spokes[i - 1].first)
        parent[findRoot(parent, spokes[i].second)] = findRoot(parent, spokes[i - 1].second);
    std::vector<int> copyOf(n, -1);  // fan root → vertex index it gets
    const int firstRoot = findRoot(parent, 0);
    copyOf[firstRoot] = v;
    bool wasSplit = false;
    for (int i = 0; i < n; ++i) {
      const int r = findRoot(parent, i);
      if (copyOf[r] < 0) {
        copyOf[r] = static_cast<int>(positions.size());
        positions.push_back(positions[v]);
        wasSplit = true;
      }
      const int c = corners[offset[v] + i];
      faces[c / 3][c % 3] = copyOf[r];
    }
    split += wasSplit;
  }
  return split;
}

}  // namespace

void checkAndRepair(const std::string& path, VcgMesh& m, ReadReport& report) {
  std::vector<vcg::Point3d> positions;
  std::vector<int> vertexIndex(m.vert.size(), -1);  // vcg slot → file vertex number
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD()) continue;
    const auto& p = m.vert[i].cP();
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(path, "vertex " + std::to_string(positions.size()) + " has a non-finite coordinate");
    if (std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}) > kMaxCoordinate)
      fail(path, "vertex " + std::to_string(positions.size()) + " has a coordinate beyond 1e30 in magnitude (lengths and "
                     "areas would overflow); rescale the model");
    vertexIndex[i] = static_cast<int>(positions.size());
    positions.push_back(p);
  }
  const int nv = static_cast<int>(positions.size());
  std::vector<Tri> faces;
  std::vector<size_t> faceSlot;  // vcg slot of each kept face, to carry its flags (selection)
  for (size_t f = 0; f < m.face.size(); ++f) {
    if (m.face[f].IsD()) continue;
    Tri t;
    for (int k = 0; k < 3; ++k) {
      const auto* v = m.face[f].cV(k);
      const std::ptrdiff_t slot = v - m.vert.data();
      if (!v || slot < 0 || slot >= static_cast<std::ptrdiff_t>(m.vert.size()) || vertexIndex[slot] < 0)
        fail(path, "face " + std::to_string(faces.size()) + " refers to a vertex the file does not have (it has " +
                       std::to_string(nv) + ")");
      t[k] = vertexIndex[slot];
    }
    faces.push_back(t);
    faceSlot.push_back(f);
  }
  if (faces.empty()) fail(path, "no triangles (" + std::to_string(nv) + " vertices, 0 faces)");

  // Coincident referenced vertices → the lowest-numbered one (a file number, for messages).
  std::vector<char> referenced(nv, 0);
  for (const Tri& t : faces)
    for (int v : t) referenced[v] = 1;
  std::vector<int> order;
  for (int v = 0; v < nv; ++v)
    if (referenced[v]) order.push_back(v);
  auto less = [&](int a, int b) {
    const auto &p = positions[a], &q = positions[b];
    if (p[0] != q[0]) return p[0] < q[0];
    if (p[1] != q[1]) return p[1] < q[1];
    if (p[2] != q[2]) return p[2] < q[2];
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> rep(nv);
  std::iota(rep.begin(), rep.end(), 0);
  for (size_t i = 1; i < order.size(); ++i) {
    if (positions[order[i]] == positions[order[i - 1]]) {
      rep[order[i]] = rep[order[i - 1]];
      ++report.duplicateVerticesMerged;
    }
  }

  // Faces that lost a corner to merging or repeat a vertex, and exact duplicates (any orientation).
  std::vector<Tri> kept;
  std::vector<size_t> keptSlot;
  std::vector<std::pair<Tri, int>> keys;
  for (size_t f = 0; f < faces.size(); ++f) {
    Tri t{rep[faces[f][0]], rep[faces[f][1]], rep[faces[f][2]]};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      ++report.degenerateFacesRemoved;
      continue;
    }
    kept.push_back(t);
    keptSlot.push_back(faceSlot[f]);
    Tri key = t;
    std::sort(key.begin(), key.end());
    keys.emplace_back(key, static_cast<int>(kept.size()) - 1);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> duplicate(kept.size(), 0);
  for (size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) duplicate[keys[i].second] = 1, ++report.duplicateFacesRemoved;
  faces.clear();
  faceSlot.clear();
  for (size_t f = 0; f < kept.size(); ++f)
    if (!duplicate[f]) faces.push_back(kept[f]), faceSlot.push_back(keptSlot[f]);
  if (faces.empty())
    fail(path, "no triangles left: every face (" + std::to_string(kept.size() + report.degenerateFacesRemoved) +
                   ") uses a vertex twice or collapses when coincident vertices are merged");

  checkEdges(path, faces, report.duplicateVerticesMerged > 0);
  report.nonManifoldVerticesSplit = splitBowTies(faces, positions);

  // Drop vertices no face uses (never referenced, or merged away), keeping the file's order.
  std::vector<int> newIndex(positions.size(), -1);
  for (const Tri& t : faces)
    for (int v : t) newIndex[v] = 0;
  int next = 0;
  for (size_t v = 0; v < positions.size(); ++v)
    if (newIndex[v] == 0) newIndex[v] = next++;
  for (int v = 0; v < nv; ++v) report.unreferencedVerticesRemoved += !referenced[v];

  const bool changed = next != static_cast<int>(m.vert.size()) || faces.size() != m.face.size() ||
                       report.nonManifoldVerticesSplit > 0 || report.duplicateVerticesMerged > 0;
  if (!changed) return;
  VcgMesh out;
  auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(out, next);
  for (size_t v = 0; v < positions.size(); ++v)
    if (newIndex[v] >= 0) out.vert[newIndex[v]].P() = positions[v];
  auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(out, faces.size());
  for (size_t f = 0; f < faces.size(); ++f, ++fi) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &out.vert[newIndex[faces[f][k]]];
    fi->Flags() = m.face[faceSlot[f]].Flags();  // keeps MeshLab's selection
  }
  (void)vi;
  m.Clear();
  vcg::tri::Append<VcgMesh, VcgMesh>::MeshCopy(m, out);
}

}  // namespace elastica::io::detail
