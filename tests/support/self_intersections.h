// SPDX-License-Identifier: GPL-3.0-or-later
// Counting a mesh's self-intersecting faces with vcglib (an independent check of a restored patch).
#pragma once

#include <elastica/types.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <vector>

namespace elastica::test {

/// Faces of `m` that intersect another face they share no vertex with (vcglib's SelfIntersections).
inline int selfIntersections(const TriMesh& m) {
  VcgMesh vm;
  fromTriMesh(m, vm);
  vcg::tri::UpdateBounding<VcgMesh>::Box(vm);
  std::vector<VcgFace*> hits;
  vcg::tri::Clean<VcgMesh>::SelfIntersections(vm, hits);
  return static_cast<int>(hits.size());
}

}  // namespace elastica::test
