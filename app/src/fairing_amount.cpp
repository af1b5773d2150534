#include <elastica/app/fairing_amount.h>

#include <algorithm>
#include <cmath>

namespace elastica::app {
namespace {

template <class F>
void forEachFaceEdge(const TriMesh& mesh, const FaceSet* region, F&& f) {
  auto face = [&](int i) {
    if (i < 0 || i >= mesh.faceCount()) return;  // the run refuses such a region with its own message
    const Face& t = mesh.faces[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) f((mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm());
  };
  if (region)
    for (int i : region->faces) face(i);
  else
    for (int i = 0; i < mesh.faceCount(); ++i) face(i);
}

}  // namespace

double autoFeatureSize(std::vector<double>& edgeLengths) {
  if (edgeLengths.empty()) return 0;
  const auto k = static_cast<std::ptrdiff_t>(std::floor(kAutoEdgeQuantile * double(edgeLengths.size() - 1)));
  std::nth_element(edgeLengths.begin(), edgeLengths.begin() + k, edgeLengths.end());
  return kAutoFeatureEdges * edgeLengths[static_cast<std::size_t>(k)];
}

double autoFeatureSize(const TriMesh& mesh, const FaceSet* region) {
  std::vector<double> lengths;
  lengths.reserve(3 * static_cast<std::size_t>(region ? region->faces.size() : mesh.faces.size()));
  forEachFaceEdge(mesh, region, [&](double l) { lengths.push_back(l); });
  return autoFeatureSize(lengths);
}

double meanFaceEdge(const TriMesh& mesh, const FaceSet* region) {
  double sum = 0;
  long long n = 0;
  forEachFaceEdge(mesh, region, [&](double l) {
    sum += l;
    ++n;
  });
  return n > 0 ? sum / double(n) : 0;
}

}  // namespace elastica::app
