// SPDX-License-Identifier: GPL-3.0-or-later
// The installed package through its front door: the curvature of a unit icosphere (H = 1, K = 1,
// E = 8π for a sphere), then fair() on a noisy one. Prints the deviations; fails beyond 1 %.
#include <elastica/elastica.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

int main() {
  const elastica::TriMesh sphere = elastica::shapes::icosphere(1.0, 3);
  const elastica::MeshCurvature c = elastica::measureCurvature(sphere);
  double worstH = 0;
  for (double h : c.H) worstH = std::max(worstH, std::fabs(h - 1.0));
  const double pi = 3.14159265358979323846, energyError = std::fabs(c.energy / (8 * pi) - 1);
  std::printf("max |H - 1| = %g, |E / 8pi - 1| = %g\n", worstH, energyError);

  elastica::TriMesh noisy = elastica::shapes::icosphere(1.0, 3);
  for (std::size_t i = 0; i < noisy.positions.size(); ++i) noisy.positions[i] *= 1 + 0.05 * std::sin(7.0 * i);
  elastica::FlowOptions opt;
  opt.scheme = elastica::Scheme::SemiImplicit;
  const elastica::FlowReport r = elastica::fair(noisy, opt);
  const double faired = r.energyFinal / (8 * pi) - 1;
  std::printf("fair: E %g -> %g (8pi = %g) in %lld steps\n", r.energyInitial, r.energyFinal, 8 * pi, r.steps);
  return worstH < 0.01 && energyError < 0.01 && std::fabs(faired) < 0.01 ? 0 : 1;
}
