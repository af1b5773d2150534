#include <elastica/mesh_quality.h>

#include <algorithm>
#include <cmath>

namespace elastica {

namespace {

double smallestAngleOfFace(const TriMesh& mesh, int f) {
  double best = 180;
  for (int k = 0; k < 3; ++k) {
    const Vec3& a = mesh.positions[mesh.faces[f][k]];
    const Vec3 u = mesh.positions[mesh.faces[f][(k + 1) % 3]] - a;
    const Vec3 w = mesh.positions[mesh.faces[f][(k + 2) % 3]] - a;
    best = std::min(best, std::atan2(u.cross(w).norm(), u.dot(w)) * 180 / M_PI);
  }
  return best;
}

}  // namespace

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
