// SPDX-License-Identifier: GPL-3.0-or-later
// A step's system solved with an earlier step's factorisation as the preconditioner of conjugate
// gradients (SpdSolver::solveStep, the integrators' reuse across attempts and edge flips) against a
// fresh direct factorisation of the same system, on a real scan: the earlier factorisation is of
// the matrix at half the step and of the mesh before a step's move and the edge flips after it
// (another sparsity pattern).
#include "exact_compare.h"
#include "sample_meshes.h"

#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"
#include "mesh/edge_flips.h"

#include <elastica/geometry.h>
#include <elastica/topology.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace elastica;

namespace {

double meanEdge(const TriMesh& mesh) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  double sum = 0;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    sum += (mesh.positions[ev[0]] - mesh.positions[ev[1]]).norm();
  }
  return sum / topo.edgeCount();
}

// The vector scheme's step matrix M + τ/2 · C M⁻¹ C with every vertex free.
Eigen::SparseMatrix<double> stepMatrix(const TriMesh& mesh, double tau) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  const Geometry geo = computeGeometry(topo, mesh.positions);
  const int n = topo.vertexCount();
  std::vector<std::uint8_t> active(n, 1);
  std::vector<int> row(n);
  for (int v = 0; v < n; ++v) row[v] = v;
  SemiImplicitSystem system;
  system.assembleMatrix(topo, geo.edgeWeight, geo.vertexArea, active, row, n, 1.0, 0.5 * tau);
  return system.matrix();
}

// The mesh after a step's move (smooth: 0.1 ℓ times a sine of one wavelength across the mesh in
// each coordinate, ℓ the mean edge) and the Delaunay edge flips that follow it; the flips made.
int moveAndFlip(TriMesh& mesh, double edge) {
  Eigen::AlignedBox3d box;
  for (const Vec3& p : mesh.positions) box.extend(p);
  const double k = 2 * M_PI / box.diagonal().norm();
  for (Vec3& p : mesh.positions)
    p += 0.1 * edge * Vec3(std::sin(k * p.y()), std::sin(k * p.z()), std::sin(k * p.x()));
  return flipToDelaunay(mesh, std::vector<std::uint8_t>(mesh.vertexCount(), 1));
}

}  // namespace

// lion-head (8,356 vertices, its edges flipped to Delaunay as a flow keeps them), τ = 100 ℓ⁴ and
// 10⁴ ℓ⁴ (ℓ the mean edge: the vector scheme's steps on a region lie between): the factorisation of
// the step at τ on the unmoved mesh solves the next step's system (2τ, moved, 43 edges flipped)
// within SpdSolver's iteration budget, and the result equals the direct solve to 1e-3 of its
// largest entry (the reuse stops at 1e-4 of the preconditioned residual; measured: 6 iterations,
// 5e-5 at both τ). solveStep, the integrators' path after a pattern change, agrees too, twice.
TEST(ReusedFactor, PreconditionsTheNextStepAcrossAMoveAndEdgeFlips) {
  TriMesh before = test::readSample("lion-head.off");
  flipToDelaunay(before, std::vector<std::uint8_t>(before.vertexCount(), 1), 50);  // as a flow keeps it
  const double edge = meanEdge(before);
  for (double steps : {1e2, 1e4}) {
    const double tau = steps * std::pow(edge, 4);
    TriMesh after = before;
    const int flips = moveAndFlip(after, edge);
    ASSERT_GT(flips, 0) << "the flips change the pattern";
    const Eigen::SparseMatrix<double> A0 = stepMatrix(before, tau), A1 = stepMatrix(after, 2 * tau);
    ASSERT_NE(A0.nonZeros(), A1.nonZeros());
    Eigen::MatrixXd b(A1.rows(), 3);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = u(rng);

    SpdSolver fresh;
    ASSERT_TRUE(fresh.factorize(A1));
    Eigen::MatrixXd direct;
    fresh.solve(b, direct);

    SpdSolver reused;
    ASSERT_TRUE(reused.factorize(A0));
    Eigen::MatrixXd x;
    const int iterations =
        reused.solvePreconditioned(A1, b, x, SpdSolver::kPcgTolerance, SpdSolver::kMaxIterations);
    EXPECT_GE(iterations, 1) << steps;
    EXPECT_LT(test::relativeDifference(x, direct), 1e-3) << steps << " ℓ⁴, " << iterations << " iterations";

    // The path the integrators take: the pattern changed, the held factorisation is tried first.
    reused.patternChanged();
    ASSERT_TRUE(reused.solveStep(A1, b, x, 0));
    EXPECT_LT(test::relativeDifference(x, direct), 1e-3) << steps;
    ASSERT_TRUE(reused.solveStep(A1, b, x, 0));
    EXPECT_LT(test::relativeDifference(x, direct), 1e-3) << steps;
  }
}
