// SPDX-License-Identifier: GPL-3.0-or-later
#include "restoration/patch_measure.h"

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/geometry.h>
#include <elastica/mesh_quality.h>
#include <elastica/topology.h>

namespace elastica {

PatchMeasure measurePatch(const TriMesh& mesh, const std::vector<std::uint8_t>& patchFace) {
  PatchMeasure m;
  m.minAngleDegrees = smallestAngleDegrees(mesh, patchFace);
  const Topology topo(mesh.vertexCount(), mesh.faces);
  const Geometry geo = computeGeometry(topo, mesh.positions);
  const Curvature curv = computeCurvature(topo, geo, mesh.positions);
  std::vector<std::uint8_t> region(mesh.positions.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (patchFace[f])
      for (int v : mesh.faces[f]) region[v] = 1;
  m.energy = totalCurvatureEnergy(topo, geo, curv, &region);
  return m;
}

}  // namespace elastica
