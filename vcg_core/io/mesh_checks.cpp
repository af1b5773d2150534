// Whole-mesh checks after reading, on the file's own vertex numbers (so messages point into the
// file), and the repairs that change no geometry:
//   refused   non-finite coordinates, out-of-range indices, non-manifold edges (which faces to
//             drop is the user's call), inconsistent orientation, no faces left;
//   repaired  coincident vertices merged (STL stores every corner apart; exporters split seams),
//             faces with a repeated vertex and exact duplicate faces removed (no area, no shape),
//             bow-tie vertices split into one vertex per fan, unreferenced vertices dropped.
// Zero-area faces with three distinct vertices stay: the operators give them zero weight, and
// the flow refuses slivers where they would stall it.
// Cost: about linear in the mesh (a hash table for coincident vertices; faces grouped by vertex,
// with small sorts per group, for duplicate faces, edges and fans), in place on the mesh as read:
// no second copy of it.
#include "readers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
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

std::uint64_t mix(std::uint64_t h) {  // splitmix64's finaliser
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

// An open-addressing table of element numbers (no deletions), for finding the first element
// equal to a given one in expected O(1): `hash` and `equal` look at the elements themselves.
class FirstOccurrence {
 public:
  explicit FirstOccurrence(size_t count) {
    size_t n = 16;
    while (n < 2 * count) n *= 2;
    slots_.assign(n, -1);
  }
  /// The first element inserted that equals `e`, or -1 after inserting `e`.
  template <class Hash, class Equal>
  int findOrInsert(int e, Hash hash, Equal equal) {
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash(e) & mask;; i = (i + 1) & mask) {
      if (slots_[i] < 0) {
        slots_[i] = e;
        return -1;
      }
      if (equal(slots_[i], e)) return slots_[i];
    }
  }

 private:
  std::vector<int> slots_;
};

// The faces around each vertex: corners 3f + k of vertex v are corners[offset[v] .. offset[v+1]),
// in increasing order.
struct VertexCorners {
  std::vector<int> offset, corners;
  VertexCorners(const std::vector<Tri>& faces, int nv) : offset(nv + 1, 0), corners(3 * faces.size()) {
    for (const Tri& t : faces)
      for (int v : t) ++offset[v + 1];
    std::partial_sum(offset.begin(), offset.end(), offset.begin());
    std::vector<int> cursor(offset.begin(), offset.end() - 1);
    for (int f = 0; f < static_cast<int>(faces.size()); ++f)
      for (int k = 0; k < 3; ++k) corners[cursor[faces[f][k]]++] = 3 * f + k;
  }
};

// The edges from each vertex lo to higher-numbered ones, with the faces on each: runs of equal hi
// are the faces around one edge (lo, hi), visited in increasing (lo, hi).
struct EdgeAtLo {
  int hi, face;
  bool forward;  // the face runs lo -> hi
};

void checkEdges(const std::string& path, const std::vector<Tri>& faces, const VertexCorners& vc, bool merged) {
  size_t inconsistent = 0;
  int firstLo = -1, firstHi = -1;
  std::vector<EdgeAtLo> edges;
  const int nv = static_cast<int>(vc.offset.size()) - 1;
  for (int lo = 0; lo < nv; ++lo) {
    edges.clear();
    for (int i = vc.offset[lo]; i < vc.offset[lo + 1]; ++i) {
      const int c = vc.corners[i], f = c / 3, k = c % 3;
      const int next = faces[f][(k + 1) % 3], prev = faces[f][(k + 2) % 3];
      if (next > lo) edges.push_back({next, f, true});
      if (prev > lo) edges.push_back({prev, f, false});
    }
    std::sort(edges.begin(), edges.end(),
              [](const EdgeAtLo& x, const EdgeAtLo& y) { return x.hi != y.hi ? x.hi < y.hi : x.face < y.face; });
    for (size_t i = 0; i < edges.size();) {
      size_t j = i + 1;
      while (j < edges.size() && edges[j].hi == edges[i].hi) ++j;
      if (j - i > 2)
        fail(path, "non-manifold edge between vertices " + std::to_string(lo) + " and " + std::to_string(edges[i].hi) +
                       " (shared by " + std::to_string(j - i) + " faces" + (merged ? ", after merging coincident vertices" : "") +
                       "); not repaired automatically: remove the extra faces, e.g. in MeshLab: Filters > Cleaning and "
                       "Repairing > Repair non Manifold Edges");
      if (j - i == 2 && edges[i].forward == edges[i + 1].forward) {
        if (firstLo < 0) firstLo = lo, firstHi = edges[i].hi;
        ++inconsistent;
      }
      i = j;
    }
  }
  if (inconsistent > 0)
    fail(path, "faces are not consistently oriented (" + std::to_string(inconsistent) +
                   (inconsistent == 1 ? " edge" : " edges") + " traversed the same way by both faces, the first between vertices " +
                   std::to_string(firstLo) + " and " + std::to_string(firstHi) +
                   "); re-orient them first, e.g. in MeshLab: Filters > Normals > Re-Orient all faces coherently");
}

// Splits every vertex whose faces form several fans (joined across edges at the vertex) into
// one vertex per fan; new vertices are appended to `positions`. Returns how many were split.
int splitBowTies(std::vector<Tri>& faces, const VertexCorners& vc, std::vector<Vec3>& positions) {
  const int nv = static_cast<int>(positions.size());
  const std::vector<int>& offset = vc.offset;
  const std::vector<int>& corners = vc.corners;
  int split = 0;
  std::vector<std::pair<int, int>> spokes;  // (other vertex of an edge at v, local corner)
  std::vector<int> parent, copyOf;
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
    copyOf.assign(n, -1);  // fan root → vertex index it gets
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

void checkAndRepair(const std::string& path, TriMesh& mesh, std::vector<std::uint8_t>& selection, ReadReport& report) {
  std::vector<Vec3>& positions = mesh.positions;
  std::vector<Tri>& faces = mesh.faces;
  const bool haveSelection = !selection.empty();
  const int nv = static_cast<int>(positions.size());
  for (int v = 0; v < nv; ++v) {
    const Vec3& p = positions[v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate");
    if (std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}) > kMaxCoordinate)
      fail(path, "vertex " + std::to_string(v) + " has a coordinate beyond 1e30 in magnitude (lengths and "
                     "areas would overflow); rescale the model");
  }
  for (size_t f = 0; f < faces.size(); ++f)
    for (int v : faces[f])
      if (v < 0 || v >= nv)
        fail(path, "face " + std::to_string(f) + " refers to a vertex the file does not have (it has " +
                       std::to_string(nv) + ")");
  if (faces.empty()) fail(path, "no triangles (" + std::to_string(nv) + " vertices, 0 faces)");

  // Coincident referenced vertices → the lowest-numbered one (a file number, for messages).
  // -0.0 == 0.0, so zeros hash alike.
  std::vector<char> referenced(nv, 0);
  int referencedCount = 0;
  for (const Tri& t : faces)
    for (int v : t) {
      referencedCount += !referenced[v];
      referenced[v] = 1;
    }
  std::vector<int> rep(nv);
  std::iota(rep.begin(), rep.end(), 0);
  {
    FirstOccurrence seen(static_cast<size_t>(referencedCount));
    auto hash = [&](int v) {
      std::uint64_t h = 0;
      for (int k = 0; k < 3; ++k) {
        const double x = positions[v][k] == 0 ? 0.0 : positions[v][k];
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        h = mix(h ^ bits);
      }
      return h;
    };
    auto equal = [&](int a, int b) { return positions[a] == positions[b]; };
    for (int v = 0; v < nv; ++v) {
      if (!referenced[v]) continue;
      const int first = seen.findOrInsert(v, hash, equal);
      if (first >= 0) rep[v] = first, ++report.duplicateVerticesMerged;
    }
  }

  // Faces that lost a corner to merging or repeat a vertex, and exact duplicates (any
  // orientation; the first copy stays): removed in place, the selection following its faces.
  size_t kept = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const Tri t{rep[faces[f][0]], rep[faces[f][1]], rep[faces[f][2]]};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      ++report.degenerateFacesRemoved;
      continue;
    }
    if (haveSelection) selection[kept] = selection[f];
    faces[kept++] = t;
  }
  faces.resize(kept);
  {
    // Faces grouped by their lowest vertex (counting sort, in face order): copies of a face are in
    // one group, where a small sort by the other two vertices finds them.
    std::vector<int> offset(nv + 1, 0), order(kept);
    auto lowest = [&](size_t f) { return std::min({faces[f][0], faces[f][1], faces[f][2]}); };
    for (size_t f = 0; f < kept; ++f) ++offset[lowest(f) + 1];
    std::partial_sum(offset.begin(), offset.end(), offset.begin());
    {
      std::vector<int> cursor(offset.begin(), offset.end() - 1);
      for (size_t f = 0; f < kept; ++f) order[cursor[lowest(f)]++] = static_cast<int>(f);
    }
    std::vector<char> duplicate(kept, 0);
    std::vector<std::array<int, 3>> group;  // (middle vertex, highest vertex, face)
    for (int v = 0; v < nv; ++v) {
      if (offset[v + 1] - offset[v] < 2) continue;
      group.clear();
      for (int i = offset[v]; i < offset[v + 1]; ++i) {
        Tri k = faces[order[i]];
        std::sort(k.begin(), k.end());
        group.push_back({k[1], k[2], order[i]});
      }
      std::sort(group.begin(), group.end());
      for (size_t i = 1; i < group.size(); ++i)
        if (group[i][0] == group[i - 1][0] && group[i][1] == group[i - 1][1]) duplicate[group[i][2]] = 1;
    }
    size_t out = 0;
    for (size_t f = 0; f < kept; ++f) {
      if (duplicate[f]) {
        ++report.duplicateFacesRemoved;
        continue;
      }
      if (haveSelection) selection[out] = selection[f];
      faces[out++] = faces[f];
    }
    faces.resize(out);
    if (haveSelection) selection.resize(out);
  }
  if (faces.empty())
    fail(path, "no triangles left: every face (" + std::to_string(kept + report.degenerateFacesRemoved) +
                   ") uses a vertex twice or collapses when coincident vertices are merged");

  {
    const VertexCorners corners(faces, nv);
    checkEdges(path, faces, corners, report.duplicateVerticesMerged > 0);
    report.nonManifoldVerticesSplit = splitBowTies(faces, corners, positions);
  }

  // Drop vertices no face uses (never referenced, or merged away), keeping the file's order.
  for (int v = 0; v < nv; ++v) report.unreferencedVerticesRemoved += !referenced[v];
  std::vector<int> newIndex(positions.size(), -1);
  for (const Tri& t : faces)
    for (int v : t) newIndex[v] = 0;
  int next = 0;
  for (size_t v = 0; v < positions.size(); ++v)
    if (newIndex[v] == 0) {
      positions[next] = positions[v];  // next <= v: moves down, in order
      newIndex[v] = next++;
    }
  if (next == static_cast<int>(positions.size())) return;
  positions.resize(static_cast<size_t>(next));
  positions.shrink_to_fit();
  for (Tri& t : faces)
    for (int& v : t) v = newIndex[v];
}

}  // namespace elastica::io::detail
