#include <elastica/parallel.h>
#include <elastica/tangential.h>

namespace elastica {
namespace {

// Applies the area-weighted umbrella with weights taken from positions `p` to the field `f`:
// out_i = Σ_j w_ij (f_j − f_i) at moving vertices, 0 elsewhere.
void areaUmbrella(const Topology& topo, const Geometry& g, const std::vector<Vec3>& p,
                  const std::vector<std::uint8_t>& moving, const std::vector<Vec3>& f, std::vector<Vec3>& out) {
  const int nv = topo.vertexCount();
  const double lengthFloor = 1e-12 * (g.meanEdgeLength > 0 ? g.meanEdgeLength : 1.0);
  out.resize(nv);
#pragma omp parallel for schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) {
    Vec3 sum = Vec3::Zero();
    if (moving[i]) {
      double ringArea = 0;
      for (int k = topo.cornerBegin(i); k < topo.cornerEnd(i); ++k) ringArea += g.faceArea[topo.corner(k) / 3];
      const int n = topo.valence(i);
      if (ringArea > 0 && n > 0) {
        for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k) {
          const int j = topo.ringVertex(k);
          const double len = (p[j] - p[i]).norm();
          if (len <= lengthFloor) continue;
          const auto& oc = topo.edgeOppositeCorners(topo.ringEdge(k));
          const double a = g.faceArea[oc[0] / 3] + (oc[1] >= 0 ? g.faceArea[oc[1] / 3] : 0.0);
          sum += (a / len) * (f[j] - f[i]);
        }
        sum /= 2 * ringArea * n;
      }
    }
    out[i] = sum;
  }
}

}  // namespace

void tangentialDrift(const Topology& topo, const Geometry& g, const std::vector<Vec3>& p,
                     const std::vector<std::uint8_t>& moving, std::vector<Vec3>& u, std::vector<Vec3>& t) {
  areaUmbrella(topo, g, p, moving, p, u);  // U(P); zero where not moving
  areaUmbrella(topo, g, p, moving, u, t);  // U(U(P)) = U²
  const int nv = topo.vertexCount();
#pragma omp parallel for schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) {
    const Vec3& n = g.vertexNormal[i];
    t[i] = -(t[i] - t[i].dot(n) * n);
  }
}

void uniformBiUmbrella(const Topology& topo, const std::vector<Vec3>& p, const std::vector<std::uint8_t>& moving,
                       std::vector<Vec3>& u0, std::vector<Vec3>& out) {
  const int nv = topo.vertexCount();
  auto umbrella = [&](const std::vector<Vec3>& f, int i) {
    Vec3 s = Vec3::Zero();
    const int n = topo.valence(i);
    for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k) s += f[topo.ringVertex(k)] - f[i];
    return n > 0 ? Vec3(s / n) : s;
  };
  u0.resize(nv);
  out.resize(nv);
#pragma omp parallel for schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) u0[i] = topo.isBoundaryVertex(i) ? Vec3::Zero() : umbrella(p, i);
#pragma omp parallel for schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) out[i] = moving[i] ? umbrella(u0, i) : Vec3::Zero();
}

}  // namespace elastica
