// SPDX-License-Identifier: GPL-3.0-or-later
// Applying a filter to a vcglib mesh (MeshLab's float CMeshO in the plugin, the double VcgMesh in
// `elastica run`): copy into a TriMesh, run (filter_run.h), and write back only on success, so a
// failing filter leaves the mesh exactly as it was.
#pragma once

#include <elastica/app/filter_run.h>
#include <elastica/vcg_adapter.h>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>

namespace elastica::app {

template <class VcgMeshT>
void updateBoxAndNormals(VcgMeshT& m) {
  vcg::tri::UpdateBounding<VcgMeshT>::Box(m);
  vcg::tri::UpdateNormal<VcgMeshT>::PerVertexNormalizedPerFaceNormalized(m);
}

/// The selected live faces of `m`, numbered as toTriMesh numbers them (deleted faces skipped).
template <class VcgMeshT>
FaceSet faceSelection(const VcgMeshT& m) {
  std::vector<int> selected;
  int index = 0;
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    if (f.IsS()) selected.push_back(index);
    ++index;
  }
  return FaceSet(std::move(selected));
}

/// The facts the defaults depend on (selected live faces, the live vertices' bounding box).
template <class VcgMeshT>
MeshFacts meshFacts(const VcgMeshT& m) {
  MeshFacts facts;
  for (const auto& f : m.face)
    if (!f.IsD() && f.IsS()) ++facts.selectedFaces;
  vcg::Box3<typename VcgMeshT::ScalarType> box;
  for (const auto& v : m.vert)
    if (!v.IsD()) box.Add(v.cP());
  facts.diagonal = box.IsNull() ? 0.0 : double(box.Diag());
  // The amount "auto" stands for (autoFeatureSize): over the selected faces if any, else all.
  const FaceSet selection = faceSelection(m);
  facts.featureSize = autoFeatureSize(toTriMesh(m), facts.selectedFaces > 0 ? &selection : nullptr);
  return facts;
}

/// Writes a fairing result back into `m`, the mesh it was copied from: only the positions when the
/// connectivity is unchanged (every other attribute of the input stays), else the whole mesh with
/// the refined selection. (The curvature, if the result carries it, is the caller's to store:
/// storeCurvature for MeshLab's attributes, or a file writer.)
template <class VcgMeshT>
void writeBack(const FairingResult& r, VcgMeshT& m) {
  if (!r.connectivityChanged) {
    writePositions(m, r.mesh.positions);
  } else {
    fromTriMesh(r.mesh, m);
    // The face selection is the faired region as remeshed; no vertex is selected (MeshLab's face
    // selection tools select none either).
    if (r.region)
      for (int f : r.region->faces) m.face[static_cast<std::size_t>(f)].SetS();
  }
  updateBoxAndNormals(m);
}

/// Writes a hole-filling result back into `m`, the mesh it was copied from: the new vertices and
/// faces are appended and the original ones keep their attributes (copies of a point merged as
/// the report says). With `selectNew`, only the new faces are selected afterwards, as MeshLab's
/// Close Holes does. When no hole was filled, `m` is left exactly as it was, selection included.
/// (The curvature, if the result carries it, is the caller's to store.)
template <class VcgMeshT>
void writeBack(const FillHolesResult& r, VcgMeshT& m, bool selectNew) {
  if (r.report.filledCount() == 0 && r.report.welds.empty()) return;
  // Compacting makes vcg indices the TriMesh indices (toTriMesh skips deleted elements).
  vcg::tri::Allocator<VcgMeshT>::CompactEveryVector(m);
  applyWelds(r.report.welds, m);
  if (!appendNewElements(r.mesh, m)) throw Error("fill: the mesh changed under the filter; nothing written");
  if (selectNew) {
    vcg::tri::UpdateSelection<VcgMeshT>::FaceClear(m);
    for (size_t f = 0; f < m.face.size(); ++f)
      if (r.report.isNewFace(static_cast<int>(f))) m.face[f].SetS();
    vcg::tri::UpdateSelection<VcgMeshT>::VertexFromFaceStrict(m);
  }
  updateBoxAndNormals(m);
}

/// What applying a filter changed in the mesh (for a host that must be told, as MeshLab's
/// post-conditions; all false when nothing changed).
struct MeshChanges {
  bool positions = false;     ///< vertex positions (and so normals and the bounding box)
  bool connectivity = false;  ///< vertices or faces added, removed or rewired (all else reset)
  bool selection = false;     ///< the face (and vertex) selection
  bool curvature = false;     ///< vertex quality and colour, mean/gaussian_curvature attributes
  bool any() const { return positions || connectivity || selection || curvature; }
};

/// A filter applied: its summary lines for the user and what it changed.
struct AppliedFilter {
  std::vector<LogLine> log;
  MeshChanges changed;
};

/// Runs filter `id` with values `v` on `m`.
/// @throws elastica::Error (and std::bad_alloc) with `m` unchanged.
template <class VcgMeshT>
AppliedFilter applyFilter(FilterId id, VcgMeshT& m, const ParamValues& v, const Progress& progress) {
  AppliedFilter a;
  if (id == FilterId::Curvature) {
    CurvatureResult r = runCurvature(toTriMesh(m), v);
    storeCurvature(m, r.outputH(), r.curvature.K);
    a.changed.curvature = true;
    a.log = std::move(r.log);
    return a;
  }
  if (id == FilterId::FillHoles) {
    const bool selectNew = readJob(filterSpec(id, {}), v, Caller::MeshLab).selectNewFaces;
    FillHolesResult r = runFillHoles(toTriMesh(m), v, progress);
    writeBack(r, m, selectNew);
    const bool changed = r.report.filledCount() > 0 || !r.report.welds.empty();
    a.changed.positions = a.changed.connectivity = changed;
    a.changed.selection = changed && selectNew;
    a.log = std::move(r.log);
    return a;
  }
  const bool selected = readJob(filterSpec(id, {}), v, Caller::MeshLab).selected;
  FairingResult r = runFairing(toTriMesh(m), selected ? std::optional<FaceSet>(faceSelection(m)) : std::nullopt, v, progress);
  writeBack(r, m);
  if (r.outputCurvature) storeCurvature(m, r.curvature.H, r.curvature.K);
  a.changed.positions = true;
  a.changed.connectivity = a.changed.selection = r.connectivityChanged;
  a.changed.curvature = r.outputCurvature;
  a.log = std::move(r.log);
  return a;
}

}  // namespace elastica::app
