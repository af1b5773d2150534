#include <elastica/subdivision.h>

#include <algorithm>
#include <unordered_map>

namespace elastica {

void subdivideMidpoint(TriMesh& mesh, std::vector<std::uint8_t>* faceFlags) {
  std::unordered_map<std::uint64_t, int> midpoint;
  midpoint.reserve(mesh.faces.size() * 2);
  auto mid = [&](int a, int b) {
    const auto [lo, hi] = std::minmax(a, b);
    const std::uint64_t key = (std::uint64_t(std::uint32_t(lo)) << 32) | std::uint32_t(hi);
    auto [it, inserted] = midpoint.try_emplace(key, mesh.vertexCount());
    if (inserted) mesh.positions.push_back(0.5 * (mesh.positions[a] + mesh.positions[b]));
    return it->second;
  };
  std::vector<Face> next;
  next.reserve(4 * mesh.faces.size());
  std::vector<std::uint8_t> flags;
  if (faceFlags) flags.reserve(4 * faceFlags->size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& t = mesh.faces[f];
    const int a = mid(t[0], t[1]), b = mid(t[1], t[2]), c = mid(t[2], t[0]);
    next.push_back({t[0], a, c});
    next.push_back({t[1], b, a});
    next.push_back({t[2], c, b});
    next.push_back({a, b, c});
    if (faceFlags) flags.insert(flags.end(), 4, (*faceFlags)[f]);
  }
  mesh.faces = std::move(next);
  if (faceFlags) *faceFlags = std::move(flags);
}

}  // namespace elastica
