// SPDX-License-Identifier: MIT
// The Newton step condensed onto exact constraints (solvers/exact_stick.hpp): the same
// step and multipliers as the saddle point [K C; Cᵀ 0], the constraints met exactly,
// the condensed matrix in the tangent's pattern.
#include "formflow/solvers/exact_stick.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace formflow::testing {
namespace {

constexpr int dim = 2;

/// Lower triangle of an SPD matrix with 2×2 node blocks on a chain of nodes (every
/// pair of neighbouring nodes coupled in full, as in a cell pattern).
assembly::SparseMatrix chain_lower(int nodes) {
  std::vector<Eigen::Triplet<Real, Index>> entries;
  const Eigen::Matrix2d coupling{{2.0, 0.5}, {0.5, 1.0}}, self{{3.0, -0.4}, {-0.4, 5.0}};
  for (int a = 0; a < nodes; ++a)
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) {
        const Index row = a * dim + i, column = a * dim + j;
        if (row >= column) entries.emplace_back(row, column, 2.0 * coupling(i, j) + self(i, j));
        if (a + 1 < nodes) entries.emplace_back((a + 1) * dim + i, a * dim + j, -coupling(i, j));
      }
  assembly::SparseMatrix lower(nodes * dim, nodes * dim);
  lower.setFromTriplets(entries.begin(), entries.end());
  lower.makeCompressed();
  return lower;
}

solvers::StepConstraint tangent_constraint(int node, Real angle, Real target) {
  return {{node * dim, node * dim + 1}, {std::cos(angle), std::sin(angle)}, target};
}

TEST(StepCondensation, GivesTheSaddlePointStepAndItsMultipliers) {
  const int nodes = 12;
  const assembly::SparseMatrix lower = chain_lower(nodes);
  const Index n = lower.rows();
  const std::vector<solvers::StepConstraint> constraints{tangent_constraint(3, 0.3, 0.7),
                                                         tangent_constraint(8, 2.1, -1.2)};
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX residual(n);
  for (Index k = 0; k < n; ++k) residual[k] = uniform(generator);

  // The condensed step: δ = g + z, (P K P + Σ α c cᵀ) z = −P (R + K g).
  const solvers::StepCondensation condensation(constraints, n);
  assembly::SparseMatrix condensed;
  condensation.condense(lower, condensed);
  EXPECT_EQ(condensed.nonZeros(), lower.nonZeros()); // the same pattern: one analysis
  const Eigen::MatrixXd full = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const Eigen::MatrixXd condensed_full = Eigen::MatrixXd(condensed).selfadjointView<Eigen::Lower>();
  const VectorX g = condensation.particular();
  const VectorX rhs = -condensation.project(residual + full * g);
  const VectorX z = condensation.project(condensed_full.llt().solve(rhs));
  const VectorX step = g + z;
  const std::vector<Real> reactions = condensation.components(residual + full * step);

  // The saddle point [K C; Cᵀ 0] [δ; μ] = [−R; g_k]: the reference, by dense LU.
  const Index m = static_cast<Index>(constraints.size());
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + m, n + m);
  kkt.topLeftCorner(n, n) = full;
  VectorX kkt_rhs(n + m);
  kkt_rhs.head(n) = -residual;
  for (Index k = 0; k < m; ++k) {
    for (std::size_t i = 0; i < constraints[k].rows.size(); ++i) {
      kkt(constraints[k].rows[i], n + k) = constraints[k].coefficients[i];
      kkt(n + k, constraints[k].rows[i]) = constraints[k].coefficients[i];
    }
    kkt_rhs[n + k] = constraints[k].target;
  }
  const VectorX reference = kkt.fullPivLu().solve(kkt_rhs);

  // Tolerance: both are direct solves of systems of condition κ (the condensed matrix's,
  // computed here), so they agree to a few κ ε relative.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(condensed_full);
  const Real kappa = spectrum.eigenvalues().maxCoeff() / spectrum.eigenvalues().minCoeff();
  const Real tolerance = 10 * kappa * std::numeric_limits<Real>::epsilon();
  EXPECT_LT((step - reference.head(n)).norm() / reference.head(n).norm(), tolerance);
  for (Index k = 0; k < m; ++k) {
    // c_k·δ = target exactly (up to round-off of the target's size).
    const Real along = condensation.components(step)[k];
    EXPECT_NEAR(along, constraints[k].target,
                4 * std::numeric_limits<Real>::epsilon() * std::abs(constraints[k].target));
    // The multiplier μ_k of the saddle point is minus the force the constraint supplies.
    EXPECT_NEAR(reactions[k], -reference[n + k], tolerance * reference.tail(m).norm());
  }
  // Off the constraints the equations hold: P (R + K δ) = 0.
  EXPECT_LT(condensation.project(residual + full * step).norm(), tolerance * residual.norm());
}

TEST(StepCondensation, KeepsTheConstrainedDirectionsAtTheirStiffness) {
  // The added α c cᵀ = (cᵀ K c) c cᵀ: the condensed matrix's quadratic form along c is
  // the tangent's, so its conditioning stays that of the tangent's unconstrained part.
  const assembly::SparseMatrix lower = chain_lower(6);
  const solvers::StepConstraint c = tangent_constraint(2, 0.9, 0.0);
  const solvers::StepCondensation condensation({c}, lower.rows());
  assembly::SparseMatrix condensed;
  condensation.condense(lower, condensed);
  const Eigen::MatrixXd full = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const Eigen::MatrixXd condensed_full = Eigen::MatrixXd(condensed).selfadjointView<Eigen::Lower>();
  VectorX along = VectorX::Zero(lower.rows());
  along[c.rows[0]] = c.coefficients[0];
  along[c.rows[1]] = c.coefficients[1];
  const Real scale = full.norm();
  EXPECT_NEAR(along.dot(condensed_full * along), along.dot(full * along),
              16 * std::numeric_limits<Real>::epsilon() * scale);
  // And c is an eigenvector: no coupling left between it and the rest.
  EXPECT_LT((condensed_full * along - along.dot(full * along) * along).norm(),
            16 * std::numeric_limits<Real>::epsilon() * scale);
}

} // namespace
} // namespace formflow::testing
