// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/app/fairing_amount.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace elastica::app {
namespace {

template <class F>
void forEachFace(const TriMesh& mesh, const FaceSet* region, F&& f) {
  auto face = [&](int i) {
    if (i < 0 || i >= mesh.faceCount()) return;  // the run refuses such a region with its own message
    f(mesh.faces[static_cast<std::size_t>(i)]);
  };
  if (region)
    for (int i : region->faces) face(i);
  else
    for (int i = 0; i < mesh.faceCount(); ++i) face(i);
}

template <class F>
void forEachFaceEdge(const TriMesh& mesh, const FaceSet* region, F&& f) {
  forEachFace(mesh, region, [&](const Face& t) {
    for (int k = 0; k < 3; ++k) f((mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm());
  });
}

double median(std::vector<double>& x) {
  if (x.empty()) return 0;
  const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

// A vertex's neighbours' mean of `value`, over the faces' edges (an inner edge counted twice,
// from both its faces, which weighs every inner neighbour alike). `count` 0: not a vertex of them.
// `zero` explicitly: an Eigen vector's default is uninitialised.
template <class T>
std::vector<T> neighbourMean(const TriMesh& mesh, const FaceSet* region, const std::vector<T>& value, const T& zero,
                             std::vector<int>& count) {
  std::vector<T> sum(value.size(), zero);
  count.assign(value.size(), 0);
  forEachFace(mesh, region, [&](const Face& t) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      sum[a] += value[b];
      sum[b] += value[a];
      count[a] += 1;
      count[b] += 1;
    }
  });
  for (std::size_t v = 0; v < sum.size(); ++v)
    if (count[v] > 0) sum[v] /= double(count[v]);
  return sum;
}

}  // namespace

AutoAmount autoAmount(std::vector<double>& edgeLengths, double roughness) {
  AutoAmount a;
  a.roughness = roughness;
  if (edgeLengths.empty()) return a;
  double sum = 0;
  for (double l : edgeLengths) sum += l;
  const double mean = sum / double(edgeLengths.size());
  const auto k = static_cast<std::ptrdiff_t>(std::floor(kAutoEdgeQuantile * double(edgeLengths.size() - 1)));
  std::nth_element(edgeLengths.begin(), edgeLengths.begin() + k, edgeLengths.end());
  const double quantile = edgeLengths[static_cast<std::size_t>(k)];
  a.operators = amountOperatorsFor(roughness, mean, quantile);
  a.featureSize = roundedAmount(a.operators == AmountOperators::Graph ? graphAmountEdges(roughness) * mean
                                                                      : amountEdges(roughness) * quantile);
  return a;
}

double graphAmountEdges(double roughness) {
  return kGraphEdges + kGraphEdgesPerRoughness * (std::max(roughness, kGraphRoughness) - kCleanRoughness);
}

AmountOperators amountOperatorsFor(double roughness, double meanEdge, double quantileEdge) {
  const bool rough = roughness > kGraphRoughness;
  return rough && meanEdge <= kGraphMaxEdgeRatio * quantileEdge ? AmountOperators::Graph : AmountOperators::Cotangent;
}

double amountEdges(double roughness) {
  const double r = std::max(roughness - kCleanRoughness, 0.0);
  return kAutoFeatureEdges + kEdgesPerRoughness * r;
}

double surfaceRoughness(const TriMesh& mesh, const FaceSet* region) {
  const std::size_t n = mesh.positions.size();
  std::vector<Vec3> normal(n, Vec3::Zero());
  forEachFace(mesh, region, [&](const Face& t) {
    const Vec3& a = mesh.positions[t[0]];
    const Vec3 areaNormal = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    for (int k = 0; k < 3; ++k) normal[t[k]] += areaNormal;
  });
  std::vector<int> count;
  const std::vector<Vec3> centre = neighbourMean(mesh, region, mesh.positions, Vec3(Vec3::Zero()), count);
  // The height of each vertex over its neighbours' centre, along its normal: curvature makes it
  // vary smoothly, noise from one vertex to the next; so the height less its neighbours' mean.
  std::vector<double> height(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    const double len = normal[v].norm();
    if (count[v] > 0 && len > 0) height[v] = normal[v].dot(centre[v] - mesh.positions[v]) / len;
  }
  std::vector<int> unused;
  const std::vector<double> around = neighbourMean(mesh, region, height, 0.0, unused);
  std::vector<double> rough, edges;
  for (std::size_t v = 0; v < n; ++v)
    if (count[v] > 0) rough.push_back(std::abs(height[v] - around[v]));
  forEachFaceEdge(mesh, region, [&](double l) { edges.push_back(l); });
  const double edge = median(edges);
  return edge > 0 ? median(rough) / edge : 0;
}

AutoAmount autoAmount(const TriMesh& mesh, const FaceSet* region) {
  std::vector<double> lengths;
  lengths.reserve(3 * static_cast<std::size_t>(region ? region->faces.size() : mesh.faces.size()));
  forEachFaceEdge(mesh, region, [&](double l) { lengths.push_back(l); });
  return autoAmount(lengths, surfaceRoughness(mesh, region));
}

double autoFeatureSize(const TriMesh& mesh, const FaceSet* region) { return autoAmount(mesh, region).featureSize; }

double roundedAmount(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return std::strtod(text, nullptr);
}

std::string exactDecimal(double x) {
  char text[32];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  return text;
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
