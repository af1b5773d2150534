// Mean curvature of a unit icosphere through the installed package: prints the largest deviation
// of the reported H from 1 and fails if it exceeds 1 %.
#include <elastica/curvature.h>
#include <elastica/shapes.h>
#include <elastica/sign_convention.h>

#include <cmath>
#include <cstdio>

int main() {
  const elastica::TriMesh m = elastica::shapes::icosphere(1.0, 3);
  const elastica::Topology topo(m.vertexCount(), m.faces);
  const elastica::Geometry geo = elastica::computeGeometry(topo, m.positions);
  const elastica::Curvature c = elastica::computeCurvature(topo, geo, m.positions);
  double worst = 0;
  for (double h : c.H) worst = std::fmax(worst, std::fabs(elastica::reportedMeanCurvature(h) - 1.0));
  std::printf("max |H - 1| = %g\n", worst);
  return worst < 0.01 ? 0 : 1;
}
