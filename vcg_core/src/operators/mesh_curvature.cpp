#include <elastica/energy.h>
#include <elastica/mesh_curvature.h>
#include <elastica/sign_convention.h>
#include <elastica/topology.h>

namespace elastica {

MeshCurvature measureCurvature(const TriMesh& mesh, const CurvatureMeasureOptions& opt) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  const Geometry geo = computeGeometry(topo, mesh.positions, opt.area);
  const Curvature c = computeCurvature(topo, geo, mesh.positions, opt.curvature);
  MeshCurvature out;
  out.energy = totalCurvatureEnergy(topo, geo, c);
  // Values leave the core here: the reported sign (+1/r on an outward sphere).
  out.H.resize(c.H.size());
  for (std::size_t i = 0; i < c.H.size(); ++i) out.H[i] = reportedMeanCurvature(c.H[i]);
  if (opt.curvature.h2k == H2KTreatment::PaperLambda) {
    out.Hlambda.resize(c.Hflow.size());
    for (std::size_t i = 0; i < c.Hflow.size(); ++i) out.Hlambda[i] = reportedMeanCurvature(c.Hflow[i]);
  }
  out.K = c.K;
  out.lambda = c.lambda;
  out.lambdaVertices = c.lambdaVertices;
  out.degenerate = geo.degenerate;
  out.eulerCharacteristic = topo.eulerCharacteristic();
  out.boundaryEdges = static_cast<std::size_t>(topo.boundaryEdgeCount());
  return out;
}

}  // namespace elastica
