// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/mesh_quality.h>
#include "operators/corner_angle.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace elastica {

namespace {

double smallestAngleOfFace(const TriMesh& mesh, int f) {
  const Face& t = mesh.faces[f];
  return smallestAngleDegrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
}

}  // namespace

double smallestAngleDegrees(const Vec3& a, const Vec3& b, const Vec3& c) {
  const std::array<const Vec3*, 3> p{&a, &b, &c};
  double best = 180;
  for (int k = 0; k < 3; ++k) {
    best = std::min(best, cornerAngle(*p[k], *p[(k + 1) % 3], *p[(k + 2) % 3]) * 180 / M_PI);
  }
  return best;
}

double smallestAngleDegrees(const TriMesh& mesh, int firstFace) {
  double best = 180;
  for (int f = std::max(firstFace, 0); f < mesh.faceCount(); ++f) best = std::min(best, smallestAngleOfFace(mesh, f));
  return best;
}

double smallestAngleDegrees(const TriMesh& mesh, const std::vector<std::uint8_t>& faceFlags) {
  double best = 180;
  for (int f = 0; f < mesh.faceCount(); ++f)
    if (faceFlags[f]) best = std::min(best, smallestAngleOfFace(mesh, f));
  return best;
}

}  // namespace elastica
