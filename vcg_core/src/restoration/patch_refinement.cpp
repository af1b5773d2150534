// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/mesh_quality.h>
#include "mesh/edge_flips.h"
#include "restoration/patch_refinement.h"

#include <algorithm>
#include <map>
#include <utility>

namespace elastica {
namespace {

constexpr int kFlipPasses = 100;  // Delaunay relaxation converges in a handful; this only bounds it

}  // namespace

void refinePatch(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma,
                 const PatchRefinementOptions& opt) {
  sigma.resize(mesh.positions.size(), 0);
  const FlipFilter insidePatch = [&](int, int, int, int, int f0, int f1) { return patchFace[f0] && patchFace[f1]; };
  flipToDelaunay(mesh, insidePatch, kFlipPasses);

  const double alpha = opt.density;
  for (int pass = 0; pass < opt.maxPasses; ++pass) {
    bool split = false;
    const std::size_t faceCount = mesh.faces.size();
    for (std::size_t f = 0; f < faceCount; ++f) {
      if (!patchFace[f]) continue;
      const Face t = mesh.faces[f];
      const Vec3 c = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
      const double sc = (sigma[t[0]] + sigma[t[1]] + sigma[t[2]]) / 3.0;
      bool tooLarge = true;
      for (int v : t) {
        const double d = alpha * (c - mesh.positions[v]).norm();
        tooLarge = tooLarge && d > sc && d > sigma[v];
      }
      if (!tooLarge) continue;
      const int x = mesh.vertexCount();
      mesh.positions.push_back(c);
      sigma.push_back(sc);
      mesh.faces[f] = {t[0], t[1], x};
      mesh.faces.push_back({t[1], t[2], x});
      mesh.faces.push_back({t[2], t[0], x});
      patchFace.push_back(1);
      patchFace.push_back(1);
      split = true;
    }
    if (!split) break;
    flipToDelaunay(mesh, insidePatch, kFlipPasses);
  }
}

namespace {

// Lowers the `sigma` of each vertex on the patch's border (a corner of an edge with one patch
// face) to the mean length of its border edges where that is shorter, for a patch whose
// refinement asked for no vertex inside: the mean length of all the mesh edges at a border
// vertex reads long where the mesh's triangles are long across the border (CGAL's bull: border
// edges of 0.008 against 0.014), and Liepa's rule then leaves a fan of needles. Returns true if
// a `sigma` changed.
bool sizeBorderByItsOwnEdges(const TriMesh& mesh, const std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma) {
  std::map<std::pair<int, int>, int> facesOnEdge;  // ordered: the same sums on every run
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!patchFace[f]) continue;
    const Face& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) ++facesOnEdge[std::minmax(t[k], t[(k + 1) % 3])];
  }
  std::map<int, std::pair<double, int>> along;  // border vertex -> (sum of its border edges, count)
  for (const auto& [edge, count] : facesOnEdge) {
    if (count != 1) continue;
    const double length = (mesh.positions[edge.first] - mesh.positions[edge.second]).norm();
    for (int v : {edge.first, edge.second}) {
      along[v].first += length;
      ++along[v].second;
    }
  }
  bool lowered = false;
  for (const auto& [v, sum] : along) {
    const double own = sum.first / sum.second;
    if (own < sigma[v]) {
      sigma[v] = own;
      lowered = true;
    }
  }
  return lowered;
}

}  // namespace

void refinePatchOrItsFan(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma,
                         const PatchRefinementOptions& opt, double needleDegrees) {
  const int before = mesh.vertexCount();
  refinePatch(mesh, patchFace, sigma, opt);
  if (mesh.vertexCount() == before && smallestAngleDegrees(mesh, patchFace) < needleDegrees &&
      sizeBorderByItsOwnEdges(mesh, patchFace, sigma))
    refinePatch(mesh, patchFace, sigma, opt);
}

}  // namespace elastica
