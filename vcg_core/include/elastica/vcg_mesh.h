// SPDX-License-Identifier: GPL-3.0-or-later
// The vcglib mesh type of the standalone tools (CLI, tests, benchmarks). Double precision, so a
// file read, processed and written loses nothing; MeshLab's own CMeshO is float and goes through
// the same adapter templates (vcg_adapter.h).
#pragma once

#include <vcg/complex/complex.h>

namespace elastica {

class VcgVertex;
class VcgFace;
struct VcgUsedTypes : public vcg::UsedTypes<vcg::Use<VcgVertex>::AsVertexType, vcg::Use<VcgFace>::AsFaceType> {};

class VcgVertex : public vcg::Vertex<VcgUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::Qualityd,
                                     vcg::vertex::Color4b, vcg::vertex::VFAdj, vcg::vertex::Mark,
                                     vcg::vertex::BitFlags> {};
class VcgFace : public vcg::Face<VcgUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::Qualityd,
                                 vcg::face::Color4b, vcg::face::FFAdj, vcg::face::VFAdj, vcg::face::Mark,
                                 vcg::face::BitFlags> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<VcgVertex>, std::vector<VcgFace>> {
 public:
  VcgMesh() = default;
  // This vcglib's TriMesh copy constructor copies nothing, and its implicit assignment would share
  // the named attributes' storage (freed twice below): copy with vcg::tri::Append::MeshCopy.
  VcgMesh(const VcgMesh&) = delete;
  VcgMesh& operator=(const VcgMesh&) = delete;
  // ~TriMesh frees the elements but not the named attributes (its ClearAttributes call is
  // commented out): storeCurvature's and the writers' per-vertex and per-face attributes leaked.
  ~VcgMesh() { ClearAttributes(); }
};

}  // namespace elastica
