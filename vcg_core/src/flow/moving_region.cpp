// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/moving_region.h"

namespace elastica {

const Topology& MovingRegion::topology() const {
  if (!topo_) topo_.emplace(mesh_.vertexCount(), mesh_.faces);
  return *topo_;
}

const VertexRoles& MovingRegion::roles() const {
  if (!roles_) roles_ = assignRoles(topology(), &selection_, mode_);
  return *roles_;
}

MovingRegion MovingRegion::copyTakingCaches() {
  MovingRegion copy(mesh_, selection_, mode_);
  copy.deadline_ = deadline_;
  copy.topo_ = std::move(topo_);
  copy.roles_ = std::move(roles_);
  invalidate();  // a moved-from optional still holds a (moved-from) value
  return copy;
}

TriMesh MovingRegion::release() {
  invalidate();
  TriMesh mesh = std::move(mesh_);
  mesh_ = TriMesh();
  selection_.clear();
  return mesh;
}

}  // namespace elastica
