// SPDX-License-Identifier: GPL-3.0-or-later
// The semi-implicit scheme's own behaviour (Scheme::SemiImplicit: the stiff fourth-order part solved
// implicitly, adaptive τ, accepted steps only): the torus all the way to the Clifford torus, the
// drift held to the step's rules, and what it refuses. Its shared tests with the explicit scheme
// are in flow_scheme_test.cpp.
#include "clifford_torus.h"
#include "shape_measures.h"

#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/shapes.h>
#include <elastica/mesh_quality.h>
#include "mesh/self_intersection.h"
#include <elastica/subdivision.h>
#include <elastica/topology.h>
#include "flow/constraints.h"
#include "flow/flow_state.h"
#include "flow/semi_implicit_integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

using namespace elastica;
using test::energyOf;

// Torus R/r = 3 to the Clifford torus R/r = √2 (E = 8π²), stopping at the plateau. The discrete
// energy underestimates at O(h²) and the flow's discrete minimum sits below the sampled Clifford
// torus: measured −3.6 % at 48×16 (768 vertices; the sampled Clifford torus of that resolution:
// −2.4 %), −1.7 % at 64×32 (2,048), −1.1 % at 96×32 (3,072; R/r 1.408, about 60 steps). This
// resolution is the coarsest that meets the 2 % (asserted: R/r within 3 % of √2, E within 2 %).
TEST(SemiImplicit, TorusReachesCliffordTorus) {
  TriMesh m;
  const FlowReport r = test::fairToCliffordTorus(Scheme::SemiImplicit, m);
  EXPECT_LT(r.steps, 1000);
  EXPECT_NEAR(r.energyFinal, energyOf(m), 1e-9 * energyOf(m));
}

// The tangential drift after an accepted step obeys the step's rules (no face turned over, E not
// above the step's allowance): on the subdivided tubular cage an unchecked drift pass once folded
// the mesh and lifted E from 523 to 10⁶ in one "accepted" step.
TEST(SemiImplicit, DriftKeepsTheStepRules) {
  TriMesh m = shapes::frameCage(2, 1);
  subdivideMidpoint(m);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.subdivisionLevels = 1;
  opt.maxSteps = 300;
  opt.remesh = false;  // remeshing and edge flips change E between steps, as subdivision does
  std::vector<std::pair<int, double>> seen;  // (level, E) after every accepted step
  opt.progress = [&](const FlowProgress& p) {
    seen.emplace_back(p.level, p.energy);
    return true;
  };
  fair(m, opt);
  ASSERT_GT(seen.size(), 20u);
  EXPECT_EQ(seen.back().first, 1);
  for (size_t k = 1; k < seen.size(); ++k) {
    if (seen[k].first != seen[k - 1].first) continue;  // subdivision changes E
    EXPECT_LE(seen[k].second, seen[k - 1].second * (1 + 1e-4) + 1e-9) << "accepted step " << k;
  }
}

TEST(SemiImplicit, BilaplacianIsExplicitOnly) {
  TriMesh m = shapes::icosphere(1.0, 1);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.flow = FlowType::Bilaplacian;
  EXPECT_THROW(fair(m, opt), InvalidInputError);
}

// A step that fails on a few vertices only is taken without them (SemiImplicitIntegrator::
// holdCulprits) instead of being halved until those few behave. Here a cap sliver (its apex at
// 0.2 % of its height above its base) on the flank of a bump: its corners' normals are tilted
// against the face, so a normal move of a fraction of the sliver's height turns it over (without
// the hold this step is rejected, and accepted at half the τ). It is accepted at full size: the
// sliver's corners (and their rings) stay where they were, the rest of the bump moves, and the
// energy falls.
TEST(SemiImplicit, AStepFailingOnAFewVerticesIsTakenWithoutThem) {
  TriMesh mesh = shapes::grid(14, 14);
  for (Vec3& p : mesh.positions) p.z() = 2 * std::exp(-((p.x() - 7) * (p.x() - 7) + (p.y() - 7) * (p.y() - 7)) / 8);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.tangentialDrift = false;  // the step alone
  const Topology topo(mesh.vertexCount(), mesh.faces);
  const VertexRoles roles = assignRoles(topo, nullptr, opt.boundary);
  // A face with three free corners on the bump's flank, about 2 from its top.
  int sliver = -1;
  for (int f = 0; f < mesh.faceCount() && sliver < 0; ++f) {
    const Face& t = mesh.faces[f];
    const Vec3 c = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3;
    if (roles.free[t[0]] && roles.free[t[1]] && roles.free[t[2]] && std::abs(std::hypot(c.x() - 7, c.y() - 7) - 2) < 0.5)
      sliver = f;
  }
  ASSERT_GE(sliver, 0);
  const Face t = mesh.faces[sliver];
  const Vec3 mid = 0.5 * (mesh.positions[t[0]] + mesh.positions[t[1]]);
  mesh.positions[t[2]] = mid + 0.002 * (mesh.positions[t[2]] - mid);
  ASSERT_LT(smallestAngleDegrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]), 0.5);

  FlowState state(mesh, {}, opt, {}, nullptr);
  const double before = state.energy();
  SemiImplicitIntegrator integrator;
  ASSERT_TRUE(integrator.tryStep(state, 0.5));
  const std::vector<Vec3>& after = state.mesh().positions;
  for (int v : t) EXPECT_EQ(after[v], mesh.positions[v]) << "sliver corner " << v;
  double moved = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v) moved = std::max(moved, (after[v] - mesh.positions[v]).norm());
  EXPECT_GT(moved, 0.01);
  EXPECT_LT(state.energy(), before);
}

// A step that would push faces through another part of the mesh holds the free corners of those
// faces (and their rings) where they were, and the rest of the step is taken: a region pressed
// against a fold of its scan at one place flows on elsewhere. Refused whole, lion-head's 1,000-face
// region spent 150 attempts at τ ≈ 10⁻⁶ ℓ⁴ on four faces at its rim (docs/decisions.md, "Regions").
TEST(SemiImplicit, AStepThatWouldMakeFacesCrossIsTakenWithoutTheContact) {
  TriMesh mesh = shapes::grid(14, 14);
  for (Vec3& p : mesh.positions) p.z() = 2 * std::exp(-((p.x() - 7) * (p.x() - 7) + (p.y() - 7) * (p.y() - 7)) / 8);
  int top = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (mesh.positions[v].z() > mesh.positions[top].z()) top = v;
  // A fixed triangle (a part of the mesh that does not move) standing upright inside the bump, its
  // apex 0.02 below the top: under the surface now (the top's faces drop 0.24 per unit of radius,
  // the triangle's edges 1.6), through the top's faces once the top comes down by more than 0.02.
  const Vec3 apex = mesh.positions[top] - Vec3(0, 0, 0.02);
  const int first = mesh.vertexCount();
  mesh.positions.push_back(apex);
  const Vec3 across(0.3 * std::cos(0.35), 0.3 * std::sin(0.35), 0);  // off the grid's lines
  mesh.positions.push_back(apex - across - Vec3(0, 0, 0.48));
  mesh.positions.push_back(apex + across - Vec3(0, 0, 0.48));
  mesh.faces.push_back({first, first + 1, first + 2});
  ASSERT_FALSE(selfIntersects(mesh));
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.tangentialDrift = false;  // the step alone
  FlowState state(mesh, {}, opt, {}, nullptr);
  const double before = state.energy();
  SemiImplicitIntegrator integrator;
  integrator.guardEmbedding(true);
  ASSERT_TRUE(integrator.tryStep(state, 0.5)) << "refused: the contact was not held";
  const std::vector<Vec3>& after = state.mesh().positions;
  EXPECT_EQ(after[top], mesh.positions[top]);
  double moved = 0;
  for (int v = 0; v < first; ++v) moved = std::max(moved, (after[v] - mesh.positions[v]).norm());
  EXPECT_GT(moved, 0.01);
  EXPECT_LT(state.energy(), before);
  EXPECT_FALSE(selfIntersects(state.mesh()));
  EXPECT_EQ(integrator.crossingRejections(), 0);
}
