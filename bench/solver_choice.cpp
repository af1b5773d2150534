// SPDX-License-Identifier: GPL-3.0-or-later
// The factorisation choice for a fairing amount's system (flow/principal_part_filter.h) on a whole
// closed mesh: (M + s² K M⁻¹ K) x = b, s² = τ/2, K the cotangent stiffness, M the mixed areas, b
// the amount's right-hand side −s² K M⁻¹ K X (x, y, z). One option per process, so that the peak
// memory (printed, and what /usr/bin/time -v sees) is the option's own:
//
//   solver_choice MESH OPTION [--feature-edges 2]
//
// OPTION: two-ring-simplicial (CHOLMOD simplicial LLᵀ of the assembled two-ring matrix, its own
// ordering: today's default), two-ring-amd (the same, AMD only), two-ring-supernodal (CHOLMOD
// supernodal LLᵀ, dense work in the system's BLAS), two-ring-ldlt (Eigen SimplicialLDLT),
// block-simplicial (the quasi-definite one-ring block [[M, sK], [sK, −M]], unknowns interleaved
// per vertex, ordered on the vertex graph, CHOLMOD simplicial LDLᵀ), one-ring-pcg (conjugate
// gradients on the two-ring operator preconditioned by B⁻¹ M B⁻¹, B = M + sK one-ring, CHOLMOD
// simplicial LLᵀ), one-ring-pcg-supernodal, and incomplete-pcg / incomplete-natural-pcg
// (conjugate gradients on the two-ring matrix preconditioned by Eigen's incomplete Cholesky on
// its pattern, AMD or the vertices' order: flow/incomplete_cholesky_cg.h's choice), and
// one-ring-complex (the complex symmetric one-ring form M + i s K, our LDLᵀ: the filter's choice). τ is the default amount's step (kFeatureSteps = 4
// of the flow time 2 ln 100 (F/2π)⁴, F = --feature-edges × the lower quartile of the edges).
// Prints one Markdown row: rows, fill (nonzeros of the factor), its flops (CHOLMOD's count), analyse / factorise / one solve of
// three columns (s), PCG iterations, relative residual ‖Ax − b‖/‖b‖ (the worst column), peak MB.
#include "guarded_main.h"
#include "flow/complex_symmetric_ldlt.h"
#include "flow/semi_implicit_system.h"

#include <elastica/geometry.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/topology.h>

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <cholmod.h>
#include <sys/resource.h>
#include <xmmintrin.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace elastica;
using Sparse = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Problem {
  Topology topo;
  std::vector<double> weight, area;
  Sparse K;            // cotangent stiffness (PSD), one ring
  Eigen::VectorXd m;   // vertex areas
  Eigen::MatrixXd b;   // three right-hand sides
  double s = 0;        // √(τ/2)
  Eigen::MatrixXd apply(const Eigen::MatrixXd& x) const {  // the two-ring operator, matrix-free
    const Eigen::MatrixXd kx = K * x;
    return m.asDiagonal() * x + (s * s) * (K * (m.cwiseInverse().asDiagonal() * kx));
  }
};

Problem load(const std::string& path, double featureEdges) {
  const TriMesh mesh = io::readMesh(path).mesh;
  Problem p;
  p.topo = Topology(mesh.vertexCount(), mesh.faces);
  const Geometry g = computeGeometry(p.topo, mesh.positions);
  p.weight = g.edgeWeight;
  p.area = g.vertexArea;
  const int n = p.topo.vertexCount();
  std::vector<double> lengths;
  for (int e = 0; e < p.topo.edgeCount(); ++e) {
    const auto& ev = p.topo.edgeVertices(e);
    lengths.push_back((mesh.positions[ev[0]] - mesh.positions[ev[1]]).norm());
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 4, lengths.end());
  const double feature = featureEdges * lengths[lengths.size() / 4];
  const double tau = 2 * std::log(100.0) * std::pow(feature / (2 * M_PI), 4) / 4;
  p.s = std::sqrt(0.5 * tau);
  std::vector<Eigen::Triplet<double>> t;
  for (int e = 0; e < p.topo.edgeCount(); ++e) {
    const auto& ev = p.topo.edgeVertices(e);
    const double w = p.weight[e];
    t.emplace_back(ev[0], ev[1], -w), t.emplace_back(ev[1], ev[0], -w);
    t.emplace_back(ev[0], ev[0], w), t.emplace_back(ev[1], ev[1], w);
  }
  p.K.resize(n, n);
  p.K.setFromTriplets(t.begin(), t.end());
  p.m = Eigen::Map<const Eigen::VectorXd>(p.area.data(), n);
  Eigen::MatrixXd X(n, 3);
  for (int v = 0; v < n; ++v) X.row(v) = mesh.positions[v].transpose();
  p.b = p.apply(X) - p.m.asDiagonal() * X;  // s² K M⁻¹ K X
  p.b *= -1;
  return p;
}

// The two-ring matrix M + s² K M⁻¹ K as the flow assembles it (every vertex free).
void assembleTwoRing(const Problem& p, SemiImplicitSystem& system) {
  std::vector<std::uint8_t> active(p.topo.vertexCount(), 1);
  std::vector<int> index(p.topo.vertexCount());
  for (int v = 0; v < p.topo.vertexCount(); ++v) index[v] = v;
  system.assembleMatrix(p.topo, p.weight, p.area, active, index, p.topo.vertexCount(), 1.0, p.s * p.s);
}

struct Row {
  long fill = 0;
  double flops = 0;
  double analyse = 0, factorise = 0, solve = 0;
  int iterations = 0;
  Eigen::MatrixXd x;
};

template <class Solver>
void configure(Solver& solver, bool amdOnly) {
  if (!amdOnly) return;
  solver.cholmod().nmethods = 1;
  solver.cholmod().method[0].ordering = CHOLMOD_AMD;
  solver.cholmod().postorder = 1;
}

template <class Solver>
Row twoRing(const Problem& p, bool amdOnly) {
  Row r;
  SemiImplicitSystem system;
  assembleTwoRing(p, system);
  Solver solver;
  configure(solver, amdOnly);
  auto t = Clock::now();
  solver.analyzePattern(system.matrix());
  r.analyse = since(t);
  r.fill = static_cast<long>(solver.cholmod().lnz);
  r.flops = solver.cholmod().fl;
  t = Clock::now();
  solver.factorize(system.matrix());
  r.factorise = since(t);
  t = Clock::now();
  r.x = solver.solve(p.b);
  r.solve = since(t);
  return r;
}

Row eigenLdlt(const Problem& p) {
  Row r;
  SemiImplicitSystem system;
  assembleTwoRing(p, system);
  Eigen::SimplicialLDLT<Sparse> solver;
  auto t = Clock::now();
  solver.analyzePattern(system.matrix());
  r.analyse = since(t);
  t = Clock::now();
  solver.factorize(system.matrix());
  r.factorise = since(t);
  r.fill = static_cast<long>(solver.matrixL().nestedExpression().nonZeros());
  t = Clock::now();
  r.x = solver.solve(p.b);
  r.solve = since(t);
  return r;
}

// The vertex graph's fill-reducing ordering (CHOLMOD's choice on K's pattern).
std::vector<int> vertexOrdering(const Sparse& pattern, cholmod_common& c) {
  Sparse lower = pattern.triangularView<Eigen::Lower>();
  cholmod_sparse A = Eigen::viewAsCholmod(lower);
  A.stype = -1;
  cholmod_factor* L = cholmod_analyze(&A, &c);
  std::vector<int> perm(static_cast<int*>(L->Perm), static_cast<int*>(L->Perm) + L->n);
  cholmod_free_factor(&L, &c);
  return perm;
}

// [[M, sK], [sK, −M]] with unknowns (x_v, y_v) at rows 2v, 2v + 1, factored LDLᵀ on the vertex
// graph's ordering expanded to the 2 × 2 blocks.
Row block(const Problem& p) {
  Row r;
  const int n = p.topo.vertexCount();
  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = CHOLMOD_SIMPLICIAL;
  c.final_ll = 0;
  auto t = Clock::now();
  std::vector<Eigen::Triplet<double>> tr;
  for (int k = 0; k < p.K.outerSize(); ++k)
    for (Sparse::InnerIterator it(p.K, k); it; ++it) {
      if (it.row() < it.col()) continue;
      const int i = static_cast<int>(it.row()), j = static_cast<int>(it.col());
      tr.emplace_back(2 * i + 1, 2 * j, p.s * it.value());  // y_i row, x_j column
      if (i != j) tr.emplace_back(2 * i, 2 * j + 1, p.s * it.value());  // x_i row, y_j column
    }
  for (int v = 0; v < n; ++v) tr.emplace_back(2 * v, 2 * v, p.m[v]), tr.emplace_back(2 * v + 1, 2 * v + 1, -p.m[v]);
  Sparse A(2 * n, 2 * n);
  A.setFromTriplets(tr.begin(), tr.end());  // lower triangle
  const std::vector<int> vertexPerm = vertexOrdering(p.K, c);
  std::vector<int> perm(2 * n);
  for (int k = 0; k < n; ++k) perm[2 * k] = 2 * vertexPerm[k], perm[2 * k + 1] = 2 * vertexPerm[k] + 1;
  cholmod_sparse Ac = Eigen::viewAsCholmod(A);
  Ac.stype = -1;
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_GIVEN;
  cholmod_factor* L = cholmod_analyze_p(&Ac, perm.data(), nullptr, 0, &c);
  r.analyse = since(t);
  r.fill = static_cast<long>(c.lnz);
  r.flops = c.fl;
  t = Clock::now();
  cholmod_factorize(&Ac, L, &c);
  r.factorise = since(t);
  if (c.status != CHOLMOD_OK || L->minor != L->n) std::fprintf(stderr, "block: factorisation failed (minor %zu)\n", L->minor);
  t = Clock::now();
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(2 * n, 3);
  for (int v = 0; v < n; ++v) rhs.row(2 * v) = p.b.row(v);
  cholmod_dense B = Eigen::viewAsCholmod(rhs);
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, L, &B, &c);
  r.solve = since(t);
  Eigen::Map<Eigen::MatrixXd> solved(static_cast<double*>(X->x), 2 * n, 3);
  r.x.resize(n, 3);
  for (int v = 0; v < n; ++v) r.x.row(v) = solved.row(2 * v);
  cholmod_free_dense(&X, &c);
  cholmod_free_factor(&L, &c);
  cholmod_finish(&c);
  return r;
}

// Conjugate gradients on the two-ring operator with the preconditioner B⁻¹ M B⁻¹ ≈ A⁻¹:
// A ≤ B M⁻¹ B ≤ 2A for B = M + sK, so at most 2 for the condition number.
template <class Solver>
Row oneRingPcg(const Problem& p) {
  Row r;
  const Sparse B = Sparse(p.m.asDiagonal()) + p.s * p.K;
  Solver solver;
  auto t = Clock::now();
  solver.analyzePattern(B);
  r.analyse = since(t);
  r.fill = static_cast<long>(solver.cholmod().lnz);
  r.flops = solver.cholmod().fl;
  t = Clock::now();
  solver.factorize(B);
  r.factorise = since(t);
  t = Clock::now();
  auto precondition = [&](const Eigen::MatrixXd& v) {
    Eigen::MatrixXd w = solver.solve(v);
    w = p.m.asDiagonal() * w;
    return Eigen::MatrixXd(solver.solve(w));
  };
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(p.b.rows(), 3), res = p.b, z = precondition(res), d = z;
  Eigen::VectorXd rz = (res.cwiseProduct(z)).colwise().sum().transpose(), start = rz;
  for (int k = 1; k <= 100; ++k) {
    const Eigen::MatrixXd Ad = p.apply(d);
    for (int col = 0; col < 3; ++col) {
      const double alpha = rz[col] / d.col(col).dot(Ad.col(col));
      x.col(col) += alpha * d.col(col);
      res.col(col) -= alpha * Ad.col(col);
    }
    z = precondition(res);
    bool done = true;
    for (int col = 0; col < 3; ++col) {
      const double next = res.col(col).dot(z.col(col));
      done = done && next <= 1e-24 * start[col];
      d.col(col) = z.col(col) + (next / rz[col]) * d.col(col);
      rz[col] = next;
    }
    r.iterations = k;
    if (done) break;
  }
  r.solve = since(t);
  r.x = x;
  return r;
}

// Conjugate gradients on the assembled two-ring matrix preconditioned by Eigen's incomplete
// Cholesky (its pattern, AMD ordering, diagonal scaling, shifted until it factors).
template <class Ordering>
Row incomplete(const Problem& p) {
  Row r;
  SemiImplicitSystem system;
  assembleTwoRing(p, system);
  Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double, Eigen::Lower, Ordering>> cg;
  cg.setTolerance(1e-12);
  cg.setMaxIterations(5000);
  auto t = Clock::now();
  cg.analyzePattern(system.matrix());
  r.analyse = since(t);
  t = Clock::now();
  cg.factorize(system.matrix());
  r.factorise = since(t);
  r.fill = system.matrix().nonZeros() / 2;
  t = Clock::now();
  r.x.resize(p.b.rows(), 3);
  for (int col = 0; col < 3; ++col) {
    r.x.col(col) = cg.solve(p.b.col(col));
    r.iterations = std::max(r.iterations, static_cast<int>(cg.iterations()));
  }
  r.solve = since(t);
  return r;
}

// The one-ring complex symmetric form (DESIGN.md §5): A⁻¹ b = Re[(M + i s K)⁻¹ b] for real b, factored
// by our LDLᵀ (flow/complex_symmetric_ldlt.h: Eigen's AMD, Davis's up-looking LDL in complex
// arithmetic). fill counts the diagonal, as CHOLMOD's lnz does; flops are 8 real per complex
// multiply-add of the factorisation.
Row oneRingComplex(const Problem& p) {
  using Complex = ComplexSymmetricLdlt::Complex;
  Row r;
  auto t = Clock::now();
  ComplexSymmetricLdlt::Matrix B = Sparse(p.m.asDiagonal()).cast<Complex>() + Complex(0, p.s) * p.K.cast<Complex>();
  B.makeCompressed();
  ComplexSymmetricLdlt ldlt;
  ldlt.analyzePattern(B);
  r.analyse = since(t);
  r.fill = static_cast<long>(ldlt.factorNonZeros()) + p.topo.vertexCount();
  r.flops = 8 * ldlt.multiplyAdds();
  t = Clock::now();
  if (!ldlt.factorize(B)) std::fprintf(stderr, "one-ring-complex: zero or non-finite pivot\n");
  r.factorise = since(t);
  ComplexSymmetricLdlt::Matrix().swap(B);
  t = Clock::now();
  Eigen::MatrixXcd x = p.b.cast<Complex>();
  ldlt.solve(x, x);
  r.x = x.real();
  r.solve = since(t);
  return r;
}

}  // namespace

int run(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: solver_choice MESH OPTION [--feature-edges 2]\n");
    return 2;
  }
  const std::string option = argv[2];
  double featureEdges = 2;
  for (int i = 3; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], "--feature-edges")) featureEdges = std::atof(argv[i + 1]);
  _mm_setcsr(_mm_getcsr() | 0x8040);  // subnormals flushed, as SpdSolver does
#ifdef _OPENMP
  omp_set_max_active_levels(0);  // CHOLMOD on one thread, as SpdSolver runs it
#endif
  const Problem p = load(argv[1], featureEdges);
  Row r;
  using Simplicial = Eigen::CholmodSimplicialLLT<Sparse>;
  using Supernodal = Eigen::CholmodSupernodalLLT<Sparse>;
  if (option == "two-ring-simplicial") r = twoRing<Simplicial>(p, false);
  else if (option == "two-ring-amd") r = twoRing<Simplicial>(p, true);
  else if (option == "two-ring-supernodal") r = twoRing<Supernodal>(p, false);
  else if (option == "two-ring-ldlt") r = eigenLdlt(p);
  else if (option == "block-simplicial") r = block(p);
  else if (option == "incomplete-pcg") r = incomplete<Eigen::AMDOrdering<int>>(p);
  else if (option == "incomplete-natural-pcg") r = incomplete<Eigen::NaturalOrdering<int>>(p);
  else if (option == "one-ring-complex") r = oneRingComplex(p);
  else if (option == "one-ring-pcg") r = oneRingPcg<Simplicial>(p);
  else if (option == "one-ring-pcg-supernodal") r = oneRingPcg<Supernodal>(p);
  else {
    std::fprintf(stderr, "solver_choice: unknown option %s\n", option.c_str());
    return 2;
  }
  const Eigen::MatrixXd residual = p.apply(r.x) - p.b;
  double worst = 0;
  for (int col = 0; col < 3; ++col) worst = std::max(worst, residual.col(col).norm() / p.b.col(col).norm());
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("| %s | %d | %.2fM | %.1fG | %.2f | %.2f | %.3f | %d | %.1e | %ld |\n", option.c_str(), p.topo.vertexCount(),
              r.fill / 1e6, r.flops / 1e9, r.analyse, r.factorise, r.solve, r.iterations, worst, usage.ru_maxrss / 1024);
  return 0;
}

int main(int argc, char** argv) { return elastica::bench::guardedMain("solver_choice", run, argc, argv); }
