// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/geometry.h>
#include <elastica/topology.h>
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"
#include "restoration/biharmonic_embedding.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>

namespace elastica {
namespace {

// The bi-Laplace system of one patch: (C M⁻¹ C)_ff x_f = −(C M⁻¹ C)_fk x_k, f the free vertices,
// k the fixed ones. Its sparsity pattern and its symbolic factorisation depend on the topology
// only: both are made once and serve every solve (the iterations re-solve with new weights). On
// the armadillo's 1,978-edge hole (125,000 and 160,000 free vertices) the four solves took 12.4 s
// when each one built its matrix from 7–8 million triplets (0.75–1.23 s) and analysed it afresh
// (0.17–1.91 s).
class BiharmonicSystem {
 public:
  BiharmonicSystem(const Topology& topo, const std::vector<std::uint8_t>& free) : topo_(topo), row_(free.size(), -1) {
    const int nv = topo.vertexCount();
    for (int v = 0; v < nv; ++v)
      if (free[v]) row_[v] = n_++;
    // The vertices whose row of C reaches a free vertex: the free ones and their neighbours.
    active_.assign(row_.size(), 0);
    for (int v = 0; v < nv; ++v) {
      if (!free[v]) continue;
      active_[v] = 1;
      for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) active_[topo.ringVertex(k)] = 1;
    }
  }

  int rows() const { return n_; }

  // One solve with edge weights C_ij and vertex areas M; moves the free vertices of `positions`.
  // False (positions unchanged) if the matrix is not positive definite or x is not finite.
  bool solve(std::vector<Vec3>& positions, const std::vector<double>& weight, const std::vector<double>& area) {
    system_.assembleMatrix(topo_, weight, area, active_, row_, n_, 0.0, 1.0);
    const Eigen::SparseMatrix<double>& A = system_.matrix();
    if (!analysed_) {
      spd_.analyzePattern(A);
      analysed_ = true;
    }
    if (!spd_.factorize(A)) return false;
    const Eigen::MatrixXd rhs = rightHandSide(positions, weight, area);
    Eigen::MatrixXd x(n_, 3);
    Eigen::VectorXd column;
    for (int c = 0; c < 3; ++c) {
      spd_.solve(rhs.col(c), column);
      x.col(c) = column;
    }
    if (!x.allFinite()) return false;
    for (std::size_t v = 0; v < positions.size(); ++v)
      if (row_[v] >= 0) positions[v] = x.row(row_[v]).transpose();
    return true;
  }

 private:
  // −(C M⁻¹ C)_fk x_k as two passes over the rings: y = C x_k (at the active vertices), then
  // −C M⁻¹ y at the free ones.
  Eigen::MatrixXd rightHandSide(const std::vector<Vec3>& positions, const std::vector<double>& weight,
                                const std::vector<double>& area) const {
    const int nv = topo_.vertexCount();
    std::vector<Vec3> y(nv, Vec3::Zero());
    for (int j = 0; j < nv; ++j) {
      if (!active_[j]) continue;
      double diagonal = 0;
      for (int k = topo_.ringBegin(j); k < topo_.ringEnd(j); ++k) {
        const double w = weight[topo_.ringEdge(k)];
        diagonal -= w;
        if (row_[topo_.ringVertex(k)] < 0) y[j] += w * positions[topo_.ringVertex(k)];
      }
      if (row_[j] < 0) y[j] += diagonal * positions[j];
      y[j] = area[j] > 0 ? Vec3(y[j] / area[j]) : Vec3::Zero();  // as the matrix: no area, no product
    }
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n_, 3);
    for (int i = 0; i < nv; ++i) {
      if (row_[i] < 0) continue;
      Vec3 sum = Vec3::Zero();
      double diagonal = 0;
      for (int k = topo_.ringBegin(i); k < topo_.ringEnd(i); ++k) {
        const double w = weight[topo_.ringEdge(k)];
        diagonal -= w;
        sum += w * y[topo_.ringVertex(k)];
      }
      sum += diagonal * y[i];
      rhs.row(row_[i]) = -sum.transpose();
    }
    return rhs;
  }

  const Topology& topo_;
  std::vector<int> row_;
  std::vector<std::uint8_t> active_;
  int n_ = 0;
  SemiImplicitSystem system_;
  SpdSolver spd_;
  bool analysed_ = false;
};

}  // namespace

void solveBiharmonic(TriMesh& mesh, const std::vector<std::uint8_t>& free, int iterations) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  BiharmonicSystem system(topo, free);
  if (system.rows() == 0) return;
  const std::vector<double> ones(std::max(topo.edgeCount(), topo.vertexCount()), 1.0);
  bool solved = false;
  Geometry geo;
  for (int it = 0; it < std::max(iterations, 1); ++it) {
    computeGeometry(topo, mesh.positions, VertexArea::Mixed, geo);
    if (system.solve(mesh.positions, geo.edgeWeight, geo.vertexArea)) {
      solved = true;
      continue;
    }
    if (solved) break;  // keep the last cotangent solution
    // Uniform weights make an SPD system whatever the shape; the next iteration retries
    // cotangent weights from that smoother start.
    if (!system.solve(mesh.positions, ones, ones)) break;
    solved = true;
  }
  if (!solved) throw NumericalError("biharmonic embedding: no finite solution (is every free vertex connected to a fixed one?)");
}

}  // namespace elastica
