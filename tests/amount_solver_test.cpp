// SPDX-License-Identifier: GPL-3.0-or-later
// The fairing amount's system (flow/principal_part_filter.h), (M + τ/2 · C M⁻¹ C) δ = −τ/2 · C M⁻¹ C X
// on a whole closed mesh at the default amount's step, solved by conjugate gradients with an
// incomplete Cholesky preconditioner (flow/incomplete_cholesky_cg.h) against a fresh direct
// factorisation (flow/spd_solver.h): on a noisy icosphere and a real scan the iterations reach
// rounding in few steps and agree with the direct solve; on a scan with slivers they do not reach
// the tolerance in the filter's budget, and say so (the filter then factorises). The filter's
// direct solve on a whole closed mesh is the one-ring complex form, A⁻¹ b = Re[(M + i s C)⁻¹ b]
// (flow/complex_symmetric_ldlt.h): it equals the two-ring direct solve, slivers included.
// Also: the uniform operators a rough scan's amount uses are an equilateral mesh's cotangents.
#include "exact_compare.h"
#include "sample_meshes.h"
#include "test_meshes.h"

#include "flow/amount_operators.h"
#include "flow/complex_symmetric_ldlt.h"
#include "flow/flow_state.h"
#include "flow/incomplete_cholesky_cg.h"
#include "flow/principal_part_filter.h"
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"

#include <elastica/geometry.h>
#include <elastica/laplacian.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace elastica;

namespace {

struct AmountSystem {
  SemiImplicitSystem system;
  Eigen::MatrixXd b;
  ComplexSymmetricLdlt::Matrix oneRing;  // M + i s C, s = √(τ/2)
};

// M + i s C (both triangles) from the edges' cotangent weights and the vertex areas.
ComplexSymmetricLdlt::Matrix oneRingForm(const Topology& topo, const Geometry& geo, double s) {
  using Complex = ComplexSymmetricLdlt::Complex;
  std::vector<Eigen::Triplet<Complex>> t;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    const Complex w(0, s * geo.edgeWeight[e]);
    t.emplace_back(ev[0], ev[1], w), t.emplace_back(ev[1], ev[0], w);
    t.emplace_back(ev[0], ev[0], -w), t.emplace_back(ev[1], ev[1], -w);
  }
  for (int v = 0; v < topo.vertexCount(); ++v) t.emplace_back(v, v, Complex(geo.vertexArea[v], 0));
  ComplexSymmetricLdlt::Matrix B(topo.vertexCount(), topo.vertexCount());
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

// The default amount's step: 2 ln 100 (F/2π)⁴ / 4 with F twice the lower quartile of the edges
// (app/fairing_amount.h), every vertex free.
void buildAmountSystem(const TriMesh& mesh, AmountSystem& out) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  const Geometry geo = computeGeometry(topo, mesh.positions);
  std::vector<double> lengths;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    lengths.push_back((mesh.positions[ev[0]] - mesh.positions[ev[1]]).norm());
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 4, lengths.end());
  const double feature = 2 * lengths[lengths.size() / 4];
  const double tau = 2 * std::log(100.0) * std::pow(feature / (2 * M_PI), 4) / 4;
  const int n = topo.vertexCount();
  std::vector<std::uint8_t> active(n, 1);
  std::vector<int> row(n);
  for (int v = 0; v < n; ++v) row[v] = v;
  out.system.assembleMatrix(topo, geo.edgeWeight, geo.vertexArea, active, row, n, 1.0, 0.5 * tau);
  out.oneRing = oneRingForm(topo, geo, std::sqrt(0.5 * tau));
  std::vector<Vec3> laplacian, bilaplacian;
  cotanLaplacian(topo, geo, mesh.positions, laplacian);
  cotanLaplacian(topo, geo, laplacian, bilaplacian);
  out.b.resize(n, 3);
  for (int v = 0; v < n; ++v) out.b.row(v) = (-0.5 * tau * geo.vertexArea[v]) * bilaplacian[v].transpose();
}

Eigen::MatrixXd directSolve(const AmountSystem& s) {
  SpdSolver spd;
  EXPECT_TRUE(spd.factorize(s.system.matrix()));
  Eigen::MatrixXd x;
  spd.solve(s.b, x);
  return x;
}

// Re[(M + i s C)⁻¹ b], column by column, with our complex symmetric LDLᵀ (which must factorise).
Eigen::MatrixXd oneRingSolve(const AmountSystem& s) {
  ComplexSymmetricLdlt ldlt;
  EXPECT_TRUE(ldlt.factorize(s.oneRing));
  Eigen::MatrixXcd x = s.b.cast<ComplexSymmetricLdlt::Complex>();
  ldlt.solve(x, x);
  return x.real();
}

// The worst column's ‖A x − b‖ / ‖b‖ with the two-ring matrix A.
double twoRingResidual(const AmountSystem& s, const Eigen::MatrixXd& x) {
  const Eigen::SparseMatrix<double>& A = s.system.matrix();
  const Eigen::MatrixXd r = A * x - s.b;
  double worst = 0;
  for (Eigen::Index c = 0; c < x.cols(); ++c) worst = std::max(worst, r.col(c).norm() / s.b.col(c).norm());
  return worst;
}

// The filter's budget (principal_part_filter.cpp) and its tolerance on the residual.
constexpr int kBudget = 40;
constexpr double kTolerance = 1e-12;

// The filter's solve of a mesh's system: the system, its solution, the iterations taken (-1: the
// tolerance not reached within the budget).
struct FilterRun {
  AmountSystem s;
  Eigen::MatrixXd x;
  int iterations = 0;
};

// Builds `mesh`'s system, factorizes it with the filter's preconditioner (which must succeed) and
// solves it within the budget.
void solveLikeTheFilter(const TriMesh& mesh, FilterRun& r) {
  buildAmountSystem(mesh, r.s);
  IncompleteCholeskyCg cg;
  ASSERT_TRUE(cg.compute(r.s.system.matrix()));
  r.iterations = cg.solve(r.s.b, r.x, kTolerance, kBudget);
}

// A converged run, equal to the direct solve to 1e-9 of its largest entry.
void expectMatchesDirect(const FilterRun& r) {
  EXPECT_GE(r.iterations, 1);
  EXPECT_LT(test::relativeDifference(r.x, directSolve(r.s)), 1e-9);
}

}  // namespace

// A 10,242-vertex icosphere with 3-D noise of half an edge (the scale benchmark's input, smaller):
// within 20 iterations, and equal to the direct solve to 1e-9 of its largest entry (the residual
// is 1e-12 of b; the matrix's condition number, from the noise's slivers, is what separates them).
TEST(AmountSolver, IncompleteCholeskyMatchesDirectOnANoisyIcosphere) {
  const TriMesh sphere = shapes::icosphere(1.0, 5);
  const double edge = 2 * std::sin(0.5 * 1.107 / 32);  // about the level-5 edge
  FilterRun r;
  ASSERT_NO_FATAL_FAILURE(solveLikeTheFilter(test::ballJittered(sphere, 0.5 * edge, 1), r));
  expectMatchesDirect(r);
  EXPECT_LE(r.iterations, 20);
}

// A real scan (lion-head, 8,356 vertices): within the budget, equal to the direct solve to 1e-9.
TEST(AmountSolver, IncompleteCholeskyMatchesDirectOnAScan) {
  FilterRun r;
  ASSERT_NO_FATAL_FAILURE(solveLikeTheFilter(test::readSample("lion-head.off"), r));
  expectMatchesDirect(r);
}

// mannequin-devil's slivers (edges down to 0.6 % of the median) put the matrix far from its
// diagonal: the filter's budget does not reach the tolerance (about 390 iterations would), and
// solve() says so instead of returning an unconverged X.
TEST(AmountSolver, IncompleteCholeskyReportsSliversItCannotSolveInBudget) {
  FilterRun r;
  ASSERT_NO_FATAL_FAILURE(solveLikeTheFilter(test::readSample("mannequin-devil.off"), r));
  EXPECT_EQ(r.iterations, -1);
}

// The one-ring form against a fresh two-ring direct solve, on the noisy icosphere: equal to 1e-10
// of the largest entry, and the two-ring residual at rounding's order.
TEST(AmountSolver, OneRingComplexFormMatchesTwoRingOnANoisyIcosphere) {
  const TriMesh sphere = shapes::icosphere(1.0, 5);
  const double edge = 2 * std::sin(0.5 * 1.107 / 32);
  AmountSystem s;
  buildAmountSystem(test::ballJittered(sphere, 0.5 * edge, 1), s);
  const Eigen::MatrixXd x = oneRingSolve(s);
  EXPECT_LT(test::relativeDifference(x, directSolve(s)), 1e-10);
  EXPECT_LT(twoRingResidual(s, x), 1e-12);
}

// The same on mannequin-devil, whose slivers' clamped cotangents make C indefinite (M + s C is not
// positive definite there): M + i s C still factorises without pivoting (its real part is), and
// the solve equals the two-ring one to 1e-10.
TEST(AmountSolver, OneRingComplexFormMatchesTwoRingOnSlivers) {
  AmountSystem s;
  buildAmountSystem(test::readSample("mannequin-devil.off"), s);
  const Eigen::MatrixXd x = oneRingSolve(s);
  EXPECT_LT(test::relativeDifference(x, directSolve(s)), 1e-10);
  EXPECT_LT(twoRingResidual(s, x), 1e-12);
}

// The filter's solve of real right-hand sides (solveRealPart: no complex copy of them) is the
// complex solve's real part, bit for bit, on mannequin-devil's slivers; and the imaginary part it
// drops is not zero there (the two are different numbers, not one copied).
TEST(AmountSolver, RealPartSolveIsTheComplexSolvesRealPart) {
  AmountSystem s;
  buildAmountSystem(test::readSample("mannequin-devil.off"), s);
  ComplexSymmetricLdlt ldlt;
  ASSERT_TRUE(ldlt.factorize(s.oneRing));
  Eigen::MatrixXcd complexX = s.b.cast<ComplexSymmetricLdlt::Complex>();
  ldlt.solve(complexX, complexX);
  Eigen::MatrixXd realX;
  ldlt.solveRealPart(s.b, realX);
  const Eigen::MatrixXd expected = complexX.real();
  ASSERT_EQ(realX.rows(), expected.rows());
  ASSERT_EQ(realX.cols(), expected.cols());
  EXPECT_EQ(std::memcmp(realX.data(), expected.data(), sizeof(double) * realX.size()), 0);
  EXPECT_GT(complexX.imag().norm(), 0.0);
}

// A zero pivot is a failure, not a division by zero: [[0, 1], [1, 0]] has none without pivoting.
TEST(AmountSolver, ComplexSymmetricLdltReportsAZeroPivot) {
  ComplexSymmetricLdlt::Matrix A(2, 2);
  A.insert(0, 1) = 1.0;
  A.insert(1, 0) = 1.0;
  A.makeCompressed();
  ComplexSymmetricLdlt ldlt;
  EXPECT_FALSE(ldlt.factorize(A));
}

// The filter on a whole closed mesh (every vertex free: the one-ring form) against its steps done
// by hand with the two-ring matrix and a fresh direct factorisation, four steps on the noisy
// icosphere: the positions agree to 1e-10 of the radius.
TEST(AmountSolver, FilterOnAClosedMeshMatchesTheTwoRingSteps) {
  const TriMesh sphere = shapes::icosphere(1.0, 4);
  const double edge = 2 * std::sin(0.5 * 1.107 / 16);
  FlowState state(test::ballJittered(sphere, 0.5 * edge, 2), {}, FlowOptions{}, InternalFlowOptions{}, nullptr);
  const Topology& topo = state.topology();
  const Geometry geo = state.geometryOnly();
  const int n = topo.vertexCount();
  ASSERT_EQ(state.roles().freeCount, n);
  const double tau = 0.05 * std::pow(geo.meanEdgeLength, 4);
  const std::vector<Vec3> start = state.positions();
  std::vector<Vec3> byHand = start;
  PrincipalPartFilter filter;
  ASSERT_TRUE(filter.prepare(state, tau));
  SemiImplicitSystem system;
  std::vector<std::uint8_t> active(n, 1);
  std::vector<int> row(n);
  for (int v = 0; v < n; ++v) row[v] = v;
  system.assembleMatrix(topo, geo.edgeWeight, geo.vertexArea, active, row, n, 1.0, 0.5 * tau);
  SpdSolver spd;
  ASSERT_TRUE(spd.factorize(system.matrix()));
  std::vector<Vec3> laplacian, bilaplacian;
  for (int k = 0; k < 4; ++k) {
    ASSERT_TRUE(filter.step(state));
    cotanLaplacian(topo, geo.edgeWeight, geo.vertexArea, byHand, laplacian);
    cotanLaplacian(topo, geo.edgeWeight, geo.vertexArea, laplacian, bilaplacian);
    Eigen::MatrixXd b(n, 3), x;
    for (int v = 0; v < n; ++v) b.row(v) = (-0.5 * tau * geo.vertexArea[v]) * bilaplacian[v].transpose();
    spd.solve(b, x);
    for (int v = 0; v < n; ++v) byHand[v] += x.row(v).transpose();
  }
  double worst = 0, moved = 0, radius = 0;
  for (int v = 0; v < n; ++v) {
    worst = std::max(worst, (state.positions()[v] - byHand[v]).norm());
    moved = std::max(moved, (byHand[v] - start[v]).norm());
    radius = std::max(radius, start[v].norm());
  }
  EXPECT_GT(moved, 0.01 * geo.meanEdgeLength);
  EXPECT_LT(worst, 1e-10 * radius);
}

// AmountOperators::Graph (flow/amount_operators.h) is an equilateral mesh's own cotangent
// operators: on a flat lattice of equilateral triangles of edge 0.7 (the mean edge exactly) every
// weight, inner and boundary, and every inner vertex's mixed area agree to rounding.
TEST(AmountSolver, GraphOperatorsAreAnEquilateralLatticesCotangents) {
  const int n = 8;
  const double h = 0.7;
  TriMesh lattice;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) lattice.positions.emplace_back(h * (i + 0.5 * j), h * std::sqrt(3.0) / 2 * j, 0.0);
  auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      lattice.faces.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      lattice.faces.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  const Topology topo(lattice.vertexCount(), lattice.faces);
  const Geometry geo = computeGeometry(topo, lattice.positions);
  std::vector<double> weight, area;
  graphAmountOperators(topo, lattice.positions, weight, area);
  ASSERT_EQ(weight.size(), geo.edgeWeight.size());
  for (int e = 0; e < topo.edgeCount(); ++e) EXPECT_NEAR(weight[e], geo.edgeWeight[e], 1e-12) << e;
  int inner = 0;
  for (int v = 0; v < topo.vertexCount(); ++v) {
    if (topo.isBoundaryVertex(v)) continue;
    EXPECT_NEAR(area[v], geo.vertexArea[v], 1e-12) << v;
    ++inner;
  }
  EXPECT_EQ(inner, (n - 1) * (n - 1));
}
