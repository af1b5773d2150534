// SPDX-License-Identifier: GPL-3.0-or-later
// Basic value types shared by every part of the core.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <array>
#include <cstdint>
#include <vector>

namespace elastica {

/// All numerics run in double, whatever the host mesh's scalar type: an explicit fourth-order
/// step moves vertices by ~1e-6 of the model size, which float positions would lose.
using Vec3 = Eigen::Vector3d;
using Face = std::array<int, 3>;

/// A plain indexed triangle mesh: the core's exchange format with vcglib meshes (vcg_adapter.h).
struct TriMesh {
  std::vector<Vec3> positions;
  std::vector<Face> faces;

  int vertexCount() const { return static_cast<int>(positions.size()); }
  int faceCount() const { return static_cast<int>(faces.size()); }
};

}  // namespace elastica
