// Applying a filter to a vcglib mesh (MeshLab's float CMeshO in the plugin, the double VcgMesh in
// `elastica run`): copy into a TriMesh, run (filter_run.h), and write back only on success, so a
// failing filter leaves the mesh exactly as it was.
#pragma once

#include <elastica/filters/filter_run.h>
#include <elastica/vcg_adapter.h>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>

namespace elastica::filters {

/// The facts the defaults depend on (selected live faces).
template <class VcgMeshT>
MeshFacts meshFacts(const VcgMeshT& m) {
  MeshFacts facts;
  for (const auto& f : m.face)
    if (!f.IsD() && f.IsS()) ++facts.selectedFaces;
  return facts;
}

template <class VcgMeshT>
void updateBoxAndNormals(VcgMeshT& m) {
  vcg::tri::UpdateBounding<VcgMeshT>::Box(m);
  vcg::tri::UpdateNormal<VcgMeshT>::PerVertexNormalizedPerFaceNormalized(m);
}

/// Runs filter `id` with values `v` on `m`. Returns summary lines for the user.
/// @throws elastica::Error (and std::bad_alloc) with `m` unchanged.
template <class VcgMeshT>
std::vector<std::string> applyFilter(FilterId id, VcgMeshT& m, const ParamValues& v, const Progress& progress) {
  if (id == FilterId::Curvature) {
    CurvatureResult r = runCurvature(toTriMesh(m), v);
    storeCurvature(m, r.H, r.K);
    return std::move(r.log);
  }

  if (id == FilterId::FillHoles) {
    FillHolesResult r = runFillHoles(toTriMesh(m), v, progress);
    // Append the new vertices and faces; the original ones keep their attributes. Compacting
    // makes vcg indices the TriMesh indices (toTriMesh skips deleted elements).
    vcg::tri::Allocator<VcgMeshT>::CompactEveryVector(m);
    applyWelds(r.welds, m);
    const size_t nf = m.face.size();
    if (!appendNewElements(r.mesh, m)) throw Error("fill: the mesh changed under the filter; nothing written");
    if (v.getBool("NewFaceSelected")) {  // as MeshLab's Close Holes: only the new faces selected
      vcg::tri::UpdateSelection<VcgMeshT>::FaceClear(m);
      for (size_t f = nf; f < m.face.size(); ++f) m.face[f].SetS();
      vcg::tri::UpdateSelection<VcgMeshT>::VertexFromFaceStrict(m);
    }
    updateBoxAndNormals(m);
    return std::move(r.log);
  }

  std::vector<std::uint8_t> selection;
  if (v.getBool("Selected"))
    for (const auto& f : m.face)
      if (!f.IsD()) selection.push_back(f.IsS() ? 1 : 0);
  FairingResult r = runFairing(toTriMesh(m), std::move(selection), v, progress);

  if (!r.connectivityChanged) {
    writePositions(m, r.mesh.positions);  // keeps every other attribute of the input
  } else {
    fromTriMesh(r.mesh, m);
    for (size_t f = 0; f < r.selection.size(); ++f)
      if (r.selection[f]) m.face[f].SetS();
    vcg::tri::UpdateSelection<VcgMeshT>::VertexFromFaceStrict(m);
  }
  if (r.colorByMeanCurvature) storeCurvature(m, r.curvature.H, r.curvature.K);
  updateBoxAndNormals(m);
  return std::move(r.log);
}

}  // namespace elastica::filters
