// SPDX-License-Identifier: GPL-3.0-or-later
// Adapters between any vcglib triangle mesh (MeshLab's float CMeshO, our double VcgMesh) and the
// core's TriMesh. Templates, so the plugin and the CLI share them. Numerics never run on the vcg
// mesh: copy in, compute in double, write back once.
#pragma once

#include <elastica/hole_filling.h>
#include <elastica/types.h>

#include <vcg/complex/complex.h>

#include <algorithm>
#include <string>
#include <vector>

namespace elastica {

/// Copies the live (non-deleted) vertices and faces of `m` into a TriMesh, in vcg order.
/// Vertex i of the result is the i-th live vertex of m.
template <class VcgMeshT>
TriMesh toTriMesh(const VcgMeshT& m) {
  TriMesh out;
  out.positions.reserve(m.vn);
  out.faces.reserve(m.fn);
  std::vector<int> index(m.vert.size(), -1);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD()) continue;
    const auto& p = m.vert[i].cP();
    index[i] = static_cast<int>(out.positions.size());
    out.positions.emplace_back(double(p[0]), double(p[1]), double(p[2]));
  }
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    Face t;
    for (int k = 0; k < 3; ++k) t[k] = index[vcg::tri::Index(m, f.cV(k))];
    out.faces.push_back(t);
  }
  return out;
}

/// Replaces the contents of `m` by `mesh` (vertex i ↔ m.vert[i], face f ↔ m.face[f]).
template <class VcgMeshT>
void fromTriMesh(const TriMesh& mesh, VcgMeshT& m) {
  using S = typename VcgMeshT::ScalarType;
  m.Clear();
  auto vi = vcg::tri::Allocator<VcgMeshT>::AddVertices(m, mesh.positions.size());
  for (const Vec3& p : mesh.positions) (vi++)->P() = typename VcgMeshT::CoordType(S(p[0]), S(p[1]), S(p[2]));
  auto fi = vcg::tri::Allocator<VcgMeshT>::AddFaces(m, mesh.faces.size());
  for (const Face& t : mesh.faces) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
    ++fi;
  }
}

/// Appends to `m` the vertices and faces of `mesh` beyond those `m` already has, when `m`'s own
/// are `mesh`'s first ones (a fill appends, never renumbers): the old elements keep every attribute
/// they carry (colours, normals, flags). `m` must be compact (no deleted elements); positions of
/// the old vertices are not touched. Returns false, changing nothing, if `m` does not fit.
template <class VcgMeshT>
bool appendNewElements(const TriMesh& mesh, VcgMeshT& m) {
  using S = typename VcgMeshT::ScalarType;
  const size_t nv = m.vert.size(), nf = m.face.size();
  if (size_t(m.vn) != nv || size_t(m.fn) != nf || mesh.positions.size() < nv || mesh.faces.size() < nf) return false;
  if (mesh.positions.size() > nv) {
    auto vi = vcg::tri::Allocator<VcgMeshT>::AddVertices(m, mesh.positions.size() - nv);  // updates face pointers
    for (size_t i = nv; i < mesh.positions.size(); ++i, ++vi) {
      const Vec3& p = mesh.positions[i];
      vi->P() = typename VcgMeshT::CoordType(S(p[0]), S(p[1]), S(p[2]));
    }
  }
  if (mesh.faces.size() > nf) {
    auto fi = vcg::tri::Allocator<VcgMeshT>::AddFaces(m, mesh.faces.size() - nf);
    for (size_t f = nf; f < mesh.faces.size(); ++f, ++fi) {
      for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[mesh.faces[f][k]];
    }
  }
  return true;
}

/// Does to `m` what fillHoles did to a TriMesh copy of it when it welded copies of one point
/// (HoleFillReport::welds, in `m`'s vertex order): faces on each removed copy move to the kept
/// vertex, the removed copies are deleted, and `m` is compacted. Call before appendNewElements.
/// `m` must be compact.
template <class VcgMeshT>
void applyWelds(const std::vector<PinchWeld>& welds, VcgMeshT& m) {
  if (welds.empty()) return;
  std::vector<int> target(m.vert.size(), -1);
  for (const PinchWeld& w : welds) target[w.removed] = w.kept;
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    for (int k = 0; k < 3; ++k) {
      const int to = target[vcg::tri::Index(m, f.V(k))];
      if (to >= 0) f.V(k) = &m.vert[to];
    }
  }
  for (const PinchWeld& w : welds) vcg::tri::Allocator<VcgMeshT>::DeleteVertex(m, m.vert[w.removed]);
  vcg::tri::Allocator<VcgMeshT>::CompactVertexVector(m);
}

/// Writes positions back into the live vertices of `m` (same order as toTriMesh).
template <class VcgMeshT>
void writePositions(VcgMeshT& m, const std::vector<Vec3>& p) {
  using S = typename VcgMeshT::ScalarType;
  size_t k = 0;
  for (auto& v : m.vert) {
    if (v.IsD()) continue;
    v.P() = typename VcgMeshT::CoordType(S(p[k][0]), S(p[k][1]), S(p[k][2]));
    ++k;
  }
}

/// MeshLab's "Colorize by vertex quality" ramp over `values` (red = low through yellow, green,
/// cyan to blue = high), spread over their 2–98 % percentiles so a few spikes do not wash out the
/// picture: one colour per value.
inline std::vector<vcg::Color4b> qualityColorRamp(const std::vector<double>& values) {
  std::vector<vcg::Color4b> colors(values.size());
  if (values.empty()) return colors;
  std::vector<double> sorted = values;
  auto percentile = [&](double q) {
    auto it = sorted.begin() + static_cast<long>(q * double(sorted.size() - 1));
    std::nth_element(sorted.begin(), it, sorted.end());
    return *it;
  };
  const double lo = percentile(0.02), hi = percentile(0.98);
  for (size_t i = 0; i < values.size(); ++i) colors[i].SetColorRamp(float(lo), float(hi), float(values[i]));
  return colors;
}

/// Stores curvatures on the live vertices of `m`, in the reported sign convention (H = +1/r on an
/// outward sphere): per-vertex float attributes "mean_curvature" and "gaussian_curvature",
/// quality = H, and the colour ramp by H (qualityColorRamp).
/// `reportedH` is already in the reported sign (MeshCurvature::H; sign_convention.h).
template <class VcgMeshT>
void storeCurvature(VcgMeshT& m, const std::vector<double>& reportedH, const std::vector<double>& K) {
  auto hAttr = vcg::tri::Allocator<VcgMeshT>::template GetPerVertexAttribute<float>(m, "mean_curvature");
  auto kAttr = vcg::tri::Allocator<VcgMeshT>::template GetPerVertexAttribute<float>(m, "gaussian_curvature");
  size_t k = 0;
  for (auto vi = m.vert.begin(); vi != m.vert.end(); ++vi) {
    if (vi->IsD()) continue;
    hAttr[vi] = float(reportedH[k]);
    kAttr[vi] = float(K[k]);
    vi->Q() = typename VcgMeshT::VertexType::QualityType(reportedH[k]);
    ++k;
  }
  if (reportedH.empty()) return;
  const std::vector<vcg::Color4b> colors = qualityColorRamp(reportedH);
  k = 0;
  for (auto& v : m.vert)
    if (!v.IsD()) v.C() = colors[k++];
}

}  // namespace elastica
