// SPDX-License-Identifier: GPL-3.0-or-later
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

#include <elastica/vertex_faces.h>
#include <elastica/vertex_fans.h>

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
  /// Asks the cache for the slot where a search for hash value `h` starts.
  void prefetch(std::uint64_t h) const { __builtin_prefetch(&slots_[h & (slots_.size() - 1)]); }
  /// The first element inserted that equals `e` (of hash value `h`), or -1 after inserting `e`.
  template <class Equal>
  int findOrInsert(int e, std::uint64_t h, Equal equal) {
    const size_t mask = slots_.size() - 1;
    for (size_t i = h & mask;; i = (i + 1) & mask) {
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

// The faces at vertex v seen from v: one spoke per edge of a face at v, packed in one integer
// (other end << 32 | face << 1 | the face runs v -> other), so that sorting the integers sorts
// by (other end, face). (A struct of these fields, built field by field and copied whole, stalled
// on every copy: the processor cannot forward several small stores into one wide load.)
using Spoke = std::uint64_t;
Spoke spoke(int other, int face, bool forward) {
  return std::uint64_t(other) << 32 | std::uint64_t(face) << 1 | std::uint64_t(forward);
}
int spokeOther(Spoke s) { return static_cast<int>(s >> 32); }
int spokeFace(Spoke s) { return static_cast<int>((s & 0xffffffffu) >> 1); }
bool spokeForward(Spoke s) { return (s & 1) != 0; }

// A vertex has about twelve spokes, where an insertion sort beats a general-purpose one; past the
// limit (a vertex of very high valence) std::sort.
void sortSpokes(std::vector<Spoke>& spokes) {
  if (spokes.size() > 32) {
    std::sort(spokes.begin(), spokes.end());
    return;
  }
  for (size_t i = 1; i < spokes.size(); ++i) {
    const Spoke s = spokes[i];
    size_t j = i;
    for (; j > 0 && s < spokes[j - 1]; --j) spokes[j] = spokes[j - 1];
    spokes[j] = s;
  }
}

// Splits vertex v, whose faces form several fans (joined across edges at v), into one vertex per
// fan: the first fan keeps v, the others get new vertices appended to `positions`, in the order
// of their first corner.
void splitFans(int v, std::vector<Tri>& faces, const VertexFaces& vf, std::vector<Vec3>& positions, FanScratch& scratch) {
  const VertexFaces::CornerRange corners = vf.corners(v);
  std::vector<int> fan;
  const int fans = fansAt(faces, corners.begin(), corners.size(), fan, scratch);
  std::vector<int> copyOf(fans, -1);  // fan → vertex index it gets
  copyOf[0] = v;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (copyOf[fan[i]] < 0) {
      copyOf[fan[i]] = static_cast<int>(positions.size());
      positions.push_back(positions[v]);
    }
    const int c = corners.begin()[i];
    faces[c / 3][c % 3] = copyOf[fan[i]];
  }
}

// One pass over the vertices, each with its spokes sorted once: refuses an edge of more than two
// faces (the first in (lo, hi) order) and edges traversed the same way by both faces (after all
// edges), then splits every bow-tie vertex into one vertex per fan (new vertices appended to
// `positions`, vertex by vertex). Returns how many were split.
int checkEdgesAndSplitFans(const std::string& path, std::vector<Tri>& faces, const VertexFaces& vf,
                           std::vector<Vec3>& positions, bool merged) {
  size_t inconsistent = 0;
  int firstLo = -1, firstHi = -1;
  std::vector<Spoke> spokes;
  std::vector<int> fan, bowTies;
  FanScratch scratch;
  const int nv = vf.builtVertexCount();
  const int nc = 3 * static_cast<int>(faces.size());
  for (int lo = 0; lo < nv; ++lo) {
    const int n = vf.offset(lo + 1) - vf.offset(lo);
    const int* corners = vf.corners(lo).begin();
    spokes.clear();
    for (int i = 0; i < n; ++i) {
      // The faces around a vertex lie anywhere in the face array: each is asked for from the
      // cache kAhead corners before it is read, so the misses overlap.
      constexpr int kAhead = 16;
      if (vf.offset(lo) + i + kAhead < nc) __builtin_prefetch(&faces[corners[i + kAhead] / 3]);
      const int c = corners[i], f = c / 3, k = c % 3;
      spokes.push_back(spoke(faces[f][(k + 1) % 3], f, true));
      spokes.push_back(spoke(faces[f][(k + 2) % 3], f, false));
    }
    sortSpokes(spokes);
    // The corners of lo are in increasing face order: a face's place among them by bisection.
    auto place = [&](int f) { return static_cast<int>(std::lower_bound(corners, corners + n, 3 * f) - corners); };
    scratch.join.reset(n);
    for (size_t i = 0; i < spokes.size();) {
      const int hi = spokeOther(spokes[i]);
      size_t j = i + 1;
      while (j < spokes.size() && spokeOther(spokes[j]) == hi) ++j;
      if (hi > lo && j - i > 2)
        fail(path, "non-manifold edge between vertices " + std::to_string(lo) + " and " + std::to_string(hi) +
                       " (shared by " + std::to_string(j - i) + " faces" + (merged ? ", after merging coincident vertices" : "") +
                       "); not repaired automatically: remove the extra faces, e.g. in MeshLab: Filters > Cleaning and "
                       "Repairing > Repair non Manifold Edges");
      if (hi > lo && j - i == 2 && spokeForward(spokes[i]) == spokeForward(spokes[i + 1])) {
        if (firstLo < 0) firstLo = lo, firstHi = hi;
        ++inconsistent;
      }
      // The faces of one edge at lo are one fan (the spokes already sorted, FanJoin joins them).
      for (size_t m = i + 1; m < j; ++m) scratch.join.join(place(spokeFace(spokes[m])), place(spokeFace(spokes[i])));
      i = j;
    }
    if (n > 1 && scratch.join.number(fan) > 1) bowTies.push_back(lo);
  }
  if (inconsistent > 0)
    fail(path, "faces are not consistently oriented (" + std::to_string(inconsistent) +
                   (inconsistent == 1 ? " edge" : " edges") + " traversed the same way by both faces, the first between vertices " +
                   std::to_string(firstLo) + " and " + std::to_string(firstHi) +
                   "); re-orient them first, e.g. in MeshLab: Filters > Normals > Re-Orient all faces coherently");
  // Splitting a vertex renames its corners only; faces joined across an edge at a later vertex
  // stay joined, so the fans found above are the fans found after the earlier splits.
  for (int v : bowTies) splitFans(v, faces, vf, positions, scratch);
  return static_cast<int>(bowTies.size());
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
    // The table is larger than the caches: each vertex's slot is asked for kAhead vertices
    // before it is searched, so the misses overlap (the hashes wait in a ring).
    constexpr int kAhead = 16;
    std::uint64_t ahead[kAhead] = {};
    for (int v = 0; v < std::min(nv, kAhead); ++v)
      if (referenced[v]) seen.prefetch(ahead[v] = hash(v));
    for (int v = 0; v < nv; ++v) {
      const std::uint64_t h = ahead[v % kAhead];
      if (v + kAhead < nv && referenced[v + kAhead]) seen.prefetch(ahead[(v + kAhead) % kAhead] = hash(v + kAhead));
      if (!referenced[v]) continue;
      const int first = seen.findOrInsert(v, h, equal);
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
    const VertexFaces vertexFaces(nv, faces);
    report.nonManifoldVerticesSplit =
        checkEdgesAndSplitFans(path, faces, vertexFaces, positions, report.duplicateVerticesMerged > 0);
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
