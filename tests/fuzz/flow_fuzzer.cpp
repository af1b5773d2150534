// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the fairing flow on small meshes the input shapes. The first bytes choose a
// base mesh and the flow's options; the rest move vertices (by small or huge amounts, or onto
// another vertex, making slivers and zero-length edges). A run is at most a few hundred steps and 5 s of flow.
// Expected outcomes: a report, or an elastica::Error (invalid input, divergence). A crash, a
// sanitizer report, another exception, or a "successful" run that leaves a non-finite position
// is a bug.
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/shapes.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace {

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  bool empty() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_, pos_ = 0;
};

elastica::TriMesh baseMesh(std::uint8_t pick) {
  using namespace elastica::shapes;
  switch (pick % 5) {
    case 0: return icosphere(1.0, 0);
    case 1: return icosphere(1.0, 1);
    case 2: return grid(4, 4, 0.5);
    case 3: return torus(3, 1, 8, 5);
    default: return frameCage(1, 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace elastica;
  Bytes in(data, size);
  TriMesh mesh = baseMesh(in.next());
  FlowOptions opt;
  const std::uint8_t o = in.next();
  opt.flow = static_cast<FlowType>(o % 3);
  opt.scheme = (o / 3) % 2 && opt.flow != FlowType::Bilaplacian ? Scheme::SemiImplicit : Scheme::Explicit;
  opt.boundary = (o / 6) % 2 ? BoundaryMode::Slide : BoundaryMode::Fixed;
  opt.curvature.h2k = (o / 12) % 2 ? H2KTreatment::PaperLambda : H2KTreatment::Clamp;
  opt.area = (o / 24) % 2 ? VertexArea::Barycentric : VertexArea::Mixed;
  opt.flipEdges = (o / 48) % 2;
  opt.tangentialDrift = (o / 96) % 2 == 0;
  const std::uint8_t s = in.next();
  opt.subdivisionLevels = s % 2;
  opt.stepFactor = (s / 2) % 4 == 3 ? 1.0 : 1.0 / 150;  // sometimes far past the stable step
  opt.maxSteps = 50 + in.next();
  // A bound on the run's wall time well below libFuzzer's -timeout (scripts/fuzz.sh): under ASan and
  // coverage a semi-implicit step with remeshing runs ~40x slower than in Release, and a slow flow
  // is not what this target looks for (an endless one would still show: remeshing and the step loop
  // are bounded separately). 5 s, not more: the phases the limit does not cut (a remeshing before
  // the first step, a reflow's remeshing begun before the limit) run ~30-40x slower here too, and
  // the time they need must fit in the rest: a torus with a vertex thrown far, remeshed on its
  // surface (remeshOnSurface), spends 0.7 s of a 1.2 s Release run there and 33 s in all here.
  opt.maxSeconds = 5;
  opt.checkInterval = 1 + in.next() % 50;

  // Each group of 4 bytes: a vertex, then how to move it.
  const int n = mesh.vertexCount();
  while (!in.empty()) {
    const int v = in.next() % n;
    const std::uint8_t how = in.next(), a = in.next(), b = in.next();
    Vec3& p = mesh.positions[v];
    switch (how % 4) {
      case 0: p += 0.01 * Vec3(a - 128, b - 128, (a ^ b) - 128); break;  // noise
      case 1: p = mesh.positions[a % n]; break;                          // onto another vertex
      case 2: p *= std::ldexp(1.0, (a % 64) - 32); break;                // huge or tiny
      default: p = 0.5 * (mesh.positions[a % n] + mesh.positions[b % n]); break;  // onto an edge
    }
  }

  try {
    fair(mesh, opt);
  } catch (const Error&) {
    return 0;
  }
  for (const Vec3& p : mesh.positions)
    if (!p.allFinite()) std::abort();
  return 0;
}
