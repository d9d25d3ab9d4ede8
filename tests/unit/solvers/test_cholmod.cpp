// SPDX-License-Identifier: MIT
// The CHOLMOD wrapper (residuals, failure by return value) and the SPD systems FormingProblem
// assembles.
#include "formflow/solvers/linear_solver.hpp"

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "support/approx.hpp"
#include "support/random_vector.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <random>
#include <vector>

namespace formflow::testing {
namespace {

using assembly::SparseMatrix;

/// Lower triangle of a sparse symmetric matrix given by triplets of its lower part.
SparseMatrix lower_from(Index n, const std::vector<Eigen::Triplet<Real, Index>>& lower) {
  SparseMatrix matrix(n, n);
  matrix.setFromTriplets(lower.begin(), lower.end());
  matrix.makeCompressed();
  return matrix;
}

/// 5-point Laplacian on an m×m grid (Dirichlet), plus a random SPD coupling
/// term BᵀB with one random off-diagonal per row, lower triangle only.
SparseMatrix spd_test_matrix(int m) {
  const Index n = m * m;
  MatrixX dense = MatrixX::Zero(n, n);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const Index k = j * m + i;
      dense(k, k) = 4.0;
      if (i > 0) dense(k, k - 1) = dense(k - 1, k) = -1.0;
      if (j > 0) dense(k, k - m) = dense(k - m, k) = -1.0;
    }
  std::mt19937 generator(5);
  std::uniform_int_distribution<Index> column(0, n - 1);
  std::uniform_real_distribution<double> value(-0.5, 0.5);
  MatrixX b = MatrixX::Zero(n, n);
  for (Index r = 0; r < n; ++r) {
    b(r, r) = 1.0;
    b(r, column(generator)) += value(generator);
  }
  dense += b.transpose() * b;
  std::vector<Eigen::Triplet<Real, Index>> lower;
  for (Index c = 0; c < n; ++c)
    for (Index r = c; r < n; ++r)
      if (dense(r, c) != 0.0) lower.emplace_back(r, c, dense(r, c));
  return lower_from(n, lower);
}

TEST(Cholmod, SolvesAnSpdSystemToSmallResidual) {
  const SparseMatrix lower = spd_test_matrix(15);
  const VectorX rhs = random_vector(lower.rows(), 11);
  auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(lower));
  ASSERT_TRUE(solver->factorize(lower));
  VectorX x;
  ASSERT_TRUE(solver->solve(rhs, x));
  ASSERT_EQ(x.size(), rhs.size());
  // Condition number ≲ 1e3 here: a backward-stable Cholesky leaves a
  // residual of ~ε·cond ≈ 1e-13; 1e-10 is the brief's requirement.
  const VectorX residual = lower.selfadjointView<Eigen::Lower>() * x - rhs;
  EXPECT_LT(residual.norm() / rhs.norm(), 1e-10);
}

TEST(Cholmod, ReadsOnlyTheLowerTriangle) {
  // The interface takes the lower triangle; junk above the diagonal must not matter.
  const SparseMatrix lower = spd_test_matrix(6);
  MatrixX with_junk = MatrixX(lower);
  for (Index c = 1; c < with_junk.cols(); ++c) with_junk(c - 1, c) = 123.0; // superdiagonal junk
  const SparseMatrix junk_sparse = with_junk.sparseView();
  const VectorX rhs = random_vector(lower.rows(), 3);
  VectorX clean, dirty;
  auto a = solvers::make_cholmod_solver(), b = solvers::make_cholmod_solver();
  ASSERT_TRUE(a->analyze(lower) && a->factorize(lower) && a->solve(rhs, clean));
  ASSERT_TRUE(b->analyze(junk_sparse) && b->factorize(junk_sparse) && b->solve(rhs, dirty));
  // Same matrix, possibly another fill-reducing ordering: two backward-stable
  // solves differ by their forward errors, ≲ ε·κ each; κ from the dense eigenvalues,
  // 10 for the growth of the sums in the factor of a 36×36 matrix.
  const VectorX lambda =
      Eigen::SelfAdjointEigenSolver<MatrixX>(
          MatrixX(SparseMatrix(lower.selfadjointView<Eigen::Lower>())), Eigen::EigenvaluesOnly)
          .eigenvalues();
  const double condition = lambda.maxCoeff() / lambda.minCoeff();
  EXPECT_TRUE(approx((clean - dirty).norm(), 0.0, 0.0,
                     10 * std::numeric_limits<double>::epsilon() * condition * clean.norm()));
}

TEST(Cholmod, RefactorisesWithTheAnalysedPattern) {
  // Analyse once, factorise twice with different values (as the secant loop does).
  const SparseMatrix first = spd_test_matrix(8);
  SparseMatrix second = first;
  second.diagonal().array() += 3.0; // same pattern, different values
  const VectorX rhs = random_vector(first.rows(), 9);
  auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(first));
  VectorX x;
  ASSERT_TRUE(solver->factorize(first));
  ASSERT_TRUE(solver->factorize(second));
  ASSERT_TRUE(solver->solve(rhs, x));
  const VectorX residual = second.selfadjointView<Eigen::Lower>() * x - rhs;
  EXPECT_LT(residual.norm() / rhs.norm(), 1e-10); // as above
}

TEST(Cholmod, ANewSolverTakesAPatternsKeptAnalysisAndSolvesTheSame) {
  // A pattern analysed once is not analysed again by a later solver: it takes the kept
  // order and symbolic factor, so its factor, and every solve, is the same to the bit
  // as that of a solver analysing afresh (same order, same operations).
  const SparseMatrix first = spd_test_matrix(17); // sizes no other test analyses
  SparseMatrix second = first;                    // the same pattern, other values (still SPD: +I)
  for (Index k = 0; k < second.outerSize(); ++k)
    for (SparseMatrix::InnerIterator entry(second, k); entry; ++entry)
      if (entry.row() == entry.col()) entry.valueRef() += 1.0;
  const VectorX rhs = VectorX::LinSpaced(first.rows(), -1.0, 2.0);
  auto analysing = solvers::make_cholmod_solver();
  ASSERT_TRUE(analysing->analyze(first) && analysing->factorize(second));
  VectorX fresh;
  ASSERT_TRUE(analysing->solve(rhs, fresh));
  const std::size_t reused_before = solvers::cholmod_analyses_reused();
  auto reusing = solvers::make_cholmod_solver();
  ASSERT_TRUE(reusing->analyze(second));
  EXPECT_EQ(solvers::cholmod_analyses_reused(), reused_before + 1);
  EXPECT_EQ(reusing->factor_size().factor_nonzeros, analysing->factor_size().factor_nonzeros);
  ASSERT_TRUE(reusing->factorize(second));
  VectorX kept;
  ASSERT_TRUE(reusing->solve(rhs, kept));
  EXPECT_EQ(kept, fresh);
  // Another pattern is analysed, and solved, on its own.
  const SparseMatrix other = spd_test_matrix(19);
  auto third = solvers::make_cholmod_solver();
  ASSERT_TRUE(third->analyze(other) && third->factorize(other));
  EXPECT_EQ(solvers::cholmod_analyses_reused(), reused_before + 1);
  VectorX x;
  const VectorX b = VectorX::Ones(other.rows());
  ASSERT_TRUE(third->solve(b, x));
  // As in SolvesAnSpdSystemToSmallResidual: condition ≲ 1e3, residual ≈ ε·cond.
  const VectorX residual = other.selfadjointView<Eigen::Lower>() * x - b;
  EXPECT_LT(residual.norm() / b.norm(), 1e-10);
}

TEST(Cholmod, NonPositiveDefiniteMatricesAreReportedNotThrown) {
  // [[1, 2], [2, 1]] has eigenvalues 3 and −1; diag(−1, −2) is negative definite;
  // a zero diagonal entry is singular.
  const std::vector<SparseMatrix> bad = {
      lower_from(2, {{0, 0, 1.0}, {1, 0, 2.0}, {1, 1, 1.0}}),
      lower_from(2, {{0, 0, -1.0}, {1, 1, -2.0}}),
      lower_from(3, {{0, 0, 1.0}, {1, 1, 0.0}, {2, 2, 1.0}, {2, 1, 0.0}}),
  };
  for (const SparseMatrix& matrix : bad) {
    auto solver = solvers::make_cholmod_solver();
    bool analysed = false, factorised = true;
    EXPECT_NO_THROW({
      analysed = solver->analyze(matrix);
      factorised = solver->factorize(matrix);
    });
    EXPECT_TRUE(analysed);
    EXPECT_FALSE(factorised) << MatrixX(matrix);
  }
}

TEST(Cholmod, RecoversAfterAFailedFactorisation) {
  const SparseMatrix indefinite = lower_from(2, {{0, 0, 1.0}, {1, 0, 2.0}, {1, 1, 1.0}});
  const SparseMatrix definite = lower_from(2, {{0, 0, 5.0}, {1, 0, 2.0}, {1, 1, 1.0}});
  auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(indefinite));
  EXPECT_FALSE(solver->factorize(indefinite));
  ASSERT_TRUE(solver->factorize(definite));
  VectorX x;
  ASSERT_TRUE(solver->solve(VectorX::Ones(2), x));
  // [[5, 2], [2, 1]] x = (1, 1): det 1, x = (1 − 2, 5 − 2)·1 = (−1, 3). Forward
  // error ≲ ε·κ, κ = λ_max/λ_min = (3 + √8)² ≈ 34; 10 for the few operations.
  const double round_off =
      10 * std::numeric_limits<double>::epsilon() * std::pow(3 + std::sqrt(8.0), 2);
  EXPECT_TRUE(approx(x[0], -1.0, round_off));
  EXPECT_TRUE(approx(x[1], 3.0, round_off));
}

TEST(Cholmod, SolveAfterAFailedFactorisationReportsFailure) {
  // "Solves with the last factorisation. False on failure."
  const SparseMatrix indefinite = lower_from(2, {{0, 0, 1.0}, {1, 0, 2.0}, {1, 1, 1.0}});
  auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(indefinite));
  ASSERT_FALSE(solver->factorize(indefinite));
  VectorX x;
  EXPECT_FALSE(solver->solve(VectorX::Ones(2), x));
}

TEST(Cholmod, HasAName) {
  EXPECT_EQ(solvers::make_cholmod_solver()->name(), "cholmod-supernodal");
}

// ---- FormingProblem: the assembled secant systems are SPD --------------------------

struct SystemCase {
  int order;
  int volumetric_points;
  physics::ViscousStrain strain;
};

void PrintTo(const SystemCase& c, std::ostream* os) {
  *os << "Q" << c.order << ", volumetric " << c.volumetric_points << "^2"
      << (c.strain == physics::ViscousStrain::Full ? ", full" : ", deviatoric");
}

class FormingSystem : public ::testing::TestWithParam<SystemCase> {};

TEST_P(FormingSystem, AssembledMatrixIsPositiveDefinite) {
  const SystemCase& param = GetParam();
  const mesh::Mesh<2> m =
      mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 1.0, param.order);
  assembly::ProblemSettings settings;
  settings.volumetric_points = param.volumetric_points;
  settings.viscous_strain = param.strain;
  settings.friction.mu = 0.1; // exercised in the second assembly below
  const assembly::FormingProblem<2> problem(m, settings);
  assembly::LinearSystem system = problem.plan().make_system();

  // Independent of CHOLMOD: the smallest eigenvalue of the dense free block,
  // relative to the largest, must be clearly positive (penalties 1/d_N = 1e6
  // against viscosities ≈ 1e-3 of the linear branch keep cond below ~1e12).
  auto check = [&](const char* what) {
    const MatrixX dense = MatrixX(SparseMatrix(system.matrix.selfadjointView<Eigen::Lower>()));
    const VectorX lambda =
        Eigen::SelfAdjointEigenSolver<MatrixX>(dense, Eigen::EigenvaluesOnly).eigenvalues();
    EXPECT_GT(lambda.minCoeff(), 1e-14 * lambda.maxCoeff()) << what;
    auto solver = solvers::make_cholmod_solver();
    VectorX x;
    const bool solved = solver->analyze(system.matrix) && solver->factorize(system.matrix) &&
                        solver->solve(system.rhs, x);
    EXPECT_TRUE(solved) << what;
    if (!solved) return VectorX(problem.constraints().values);
    // Backward stability: residual small against ‖K‖‖x‖ (‖b‖ may be far smaller).
    const VectorX residual = dense * x - system.rhs;
    EXPECT_LT(residual.norm(), 1e-12 * dense.norm() * x.norm()) << what;
    return problem.plan().expand(x, problem.constraints().values);
  };
  problem.assemble(nullptr, system);
  const VectorX u = check("constant viscosity");
  // The secant system at that velocity, with friction on Γ3.
  problem.assemble(&u, system);
  check("secant viscosity and friction");
}

INSTANTIATE_TEST_SUITE_P(ElementKinds, FormingSystem,
                         ::testing::Values(SystemCase{1, 1, physics::ViscousStrain::Full},
                                           SystemCase{1, 2, physics::ViscousStrain::Full},
                                           SystemCase{2, 2, physics::ViscousStrain::Full},
                                           SystemCase{2, 3, physics::ViscousStrain::Deviatoric},
                                           SystemCase{2, 1, physics::ViscousStrain::Deviatoric}),
                         [](const auto& info) {
                           return std::string(info.param.order == 1 ? "Q1" : "Q2") + "_vol" +
                                  std::to_string(info.param.volumetric_points) +
                                  (info.param.strain == physics::ViscousStrain::Full ? "_full"
                                                                                     : "_dev");
                         });

TEST(FormingProblem, DrivenHeightIsTheRamOrTheExitHeight) {
  const mesh::Mesh<2> m = mesh::make_channel_mesh(mesh::ChannelGeometry{4, 4, 2, 4}, 1.0, 2);
  assembly::ProblemSettings extrusion;
  EXPECT_TRUE(approx(assembly::FormingProblem<2>(m, extrusion).driven_height(), 4.0, 1e-14));
  assembly::ProblemSettings drawing;
  drawing.process.type = physics::ProcessType::Drawing;
  EXPECT_TRUE(approx(assembly::FormingProblem<2>(m, drawing).driven_height(), 2.0, 1e-14));
}

TEST(FormingProblem, ContactStateOfAUniformVelocityByHand) {
  // Tiny channel: Γ3 = container y = 2 (x ∈ [0, 2]) and die x = 2 (y ∈ [1, 2]).
  // u = (0.5, 0.2) everywhere: on the container u_N = 0.2, u_T = (0.5, 0);
  // on the die u_N = 0.5, u_T = (0, 0.2). −σ_N = u_N/d_N.
  const mesh::Mesh<2> m = mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 1.0, 2);
  assembly::ProblemSettings settings;
  settings.penalty.d_n = 1e-2;
  settings.friction.mu = 0.3;
  settings.friction.radius = 100.0; // every Γ3 point averages over all of Γ3
  settings.friction.on_die = false;
  settings.friction.d_t = 0.1;
  const assembly::FormingProblem<2> problem(m, settings);
  VectorX u(problem.n_dofs());
  for (Index node = 0; node < m.n_nodes(); ++node) u.segment<2>(2 * node) = Point<2>(0.5, 0.2);
  const auto state = problem.contact_state(u);
  ASSERT_EQ(state.size(), 3u * 3u); // 2 container + 1 die faces, 3 points each
  double container_length = 0.0, die_length = 0.0;
  // Mean pressure over Γ3: (2·0.2 + 1·0.5)/3 / d_N = 30.
  const double mean = (2 * 0.2 + 1 * 0.5) / 3.0 / 1e-2;
  for (const auto& point : state) {
    const bool die = m.facets[point.facet].label == mesh::BoundaryLabel::Die;
    (die ? die_length : container_length) += point.weight;
    const Point<2> normal = die ? Point<2>(1.0, 0.0) : Point<2>(0.0, 1.0);
    const double u_n = die ? 0.5 : 0.2;
    const Point<2> u_t = die ? Point<2>(0, 0.2) : Point<2>(0.5, 0);
    // Unit-cell geometry and O(1) velocities: round-off 1e-13.
    EXPECT_TRUE(approx((point.normal - normal).norm(), 0.0, 0.0, 1e-13));
    EXPECT_TRUE(approx(point.normal_velocity, u_n, 1e-13));
    EXPECT_TRUE(approx((point.tangential_velocity - u_t).norm(), 0.0, 0.0, 1e-13));
    EXPECT_TRUE(approx(point.contact_pressure, u_n / 1e-2, 1e-12));
    EXPECT_TRUE(approx(point.mean_contact_pressure, mean, 1e-12));
    if (die) {
      EXPECT_EQ(point.friction_threshold, 0.0) << "friction is off on the die";
      EXPECT_EQ(point.friction_weight, 0.0);
      EXPECT_TRUE(approx(point.position.x(), 2.0, 0.0, 1e-13));
    } else {
      EXPECT_TRUE(approx(point.friction_threshold, 0.3 * mean, 1e-12));
      // τ_f / √(|u_T|² + d_T²) = 9 / √(0.25 + 0.01).
      EXPECT_TRUE(approx(point.friction_weight, 0.3 * mean / std::sqrt(0.26), 1e-12));
      EXPECT_TRUE(approx(point.position.y(), 2.0, 0.0, 1e-13));
    }
  }
  EXPECT_TRUE(approx(container_length, 2.0, 1e-13));
  EXPECT_TRUE(approx(die_length, 1.0, 1e-13));
}

TEST(FormingProblem, StartingViscosityIsTheSecantViscosityAtTheInitialRate) {
  // Without w the viscosity is σ_p(r0)/r0. Simple shear w = (γ y, 0) has
  // ε̄̇ = γ/√3 everywhere (SPEC §1), so with γ = √3 r0 the secant system K(w)
  // must be the very same matrix. A rate-sensitive law (α = 0.5) makes any
  // other starting rate, or a wrong ε̄̇ of w, change the viscosity.
  const mesh::Mesh<2> m = mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 1.0, 2);
  assembly::ProblemSettings settings;
  settings.law.as<physics::PiecewisePower>().alpha = 0.5;
  settings.initial_rate = 0.04;
  const assembly::FormingProblem<2> problem(m, settings);
  VectorX w(problem.n_dofs());
  const double gamma = std::sqrt(3.0) * settings.initial_rate;
  for (Index node = 0; node < m.n_nodes(); ++node)
    w.segment<2>(2 * node) = Point<2>(gamma * m.nodes(1, node), 0.0);
  assembly::LinearSystem start = problem.plan().make_system(), shear = problem.plan().make_system();
  problem.assemble(nullptr, start);
  problem.assemble(&w, shear);
  const MatrixX difference = MatrixX(start.matrix) - MatrixX(shear.matrix);
  // pow() of the same argument reached two ways: 1e-12 relative to ‖K‖ is round-off.
  EXPECT_TRUE(approx(difference.norm(), 0.0, 0.0, 1e-12 * MatrixX(start.matrix).norm()));
  // And a different rate does change the matrix (the check above can fail).
  w *= 3.0;
  problem.assemble(&w, shear);
  EXPECT_GT((MatrixX(start.matrix) - MatrixX(shear.matrix)).norm(),
            1e-6 * MatrixX(start.matrix).norm());
}

TEST(FormingProblem, FrictionAddsItsPointwiseSecantTermToTheSystem) {
  // K(w) with μ_f > 0 minus K(w) with μ_f = 0 is the friction term alone:
  // vᵀ ΔK v = Σ_Γ3 points κ_q |v_T(x_q)|² JxW_q, with κ_q the friction weight
  // that contact_state reports at x_q. w is the constant-viscosity solution,
  // so u_N, u_T and hence κ vary from point to point.
  const mesh::Mesh<2> m = mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 1.0, 2);
  assembly::ProblemSettings frictionless, with_friction;
  with_friction.friction.mu = 0.2;
  with_friction.friction.d_t = 1e-2;
  const assembly::FormingProblem<2> plain(m, frictionless), rough(m, with_friction);

  assembly::LinearSystem system = plain.plan().make_system();
  plain.assemble(nullptr, system);
  auto solver = solvers::make_cholmod_solver();
  VectorX free_w;
  ASSERT_TRUE(solver->analyze(system.matrix) && solver->factorize(system.matrix) &&
              solver->solve(system.rhs, free_w));
  const VectorX w = plain.plan().expand(free_w, plain.constraints().values);

  assembly::LinearSystem k0 = plain.plan().make_system(), k1 = rough.plan().make_system();
  plain.assemble(&w, k0);
  rough.assemble(&w, k1);
  std::mt19937 generator(17);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX v_free(plain.plan().n_free());
  for (Index k = 0; k < v_free.size(); ++k) v_free[k] = uniform(generator);
  const SparseMatrix difference = SparseMatrix(k1.matrix.selfadjointView<Eigen::Lower>()) -
                                  SparseMatrix(k0.matrix.selfadjointView<Eigen::Lower>());
  const double energy = v_free.dot(difference * v_free);
  const VectorX v = plain.plan().expand(v_free, VectorX::Zero(plain.n_dofs()));

  const auto state = rough.contact_state(w);
  fem::FacetValues<2> values(2, fem::gauss_rule<1>(3));
  typename fem::CellValues<2>::Gradients coordinates, velocities;
  double expected = 0.0, largest = 0.0, smallest = 1e300;
  std::size_t matched = 0;
  for (Index f = 0; f < static_cast<Index>(m.facets.size()); ++f) {
    if (!mesh::is_contact(m.facets[f].label)) continue;
    rough.gather(m.facets[f].cell, &v, coordinates, velocities);
    values.reinit(coordinates, m.facets[f].local_face);
    for (int q = 0; q < values.n_points(); ++q) {
      // Find the state entry of this face point by facet and position.
      const assembly::ContactPoint<2>* point = nullptr;
      for (const auto& candidate : state)
        if (candidate.facet == f && (candidate.position - values.point(q)).norm() < 1e-12)
          point = &candidate;
      ASSERT_NE(point, nullptr) << "facet " << f << " point " << q;
      ++matched;
      const Point<2> v_q = velocities * values.shape(q);
      const Point<2> v_t = v_q - v_q.dot(values.normal(q)) * values.normal(q);
      expected += point->friction_weight * v_t.squaredNorm() * values.JxW(q);
      largest = std::max(largest, point->friction_weight);
      smallest = std::min(smallest, point->friction_weight);
    }
  }
  EXPECT_EQ(matched, state.size());
  ASSERT_GT(largest, 1.01 * smallest) << "weights must differ between points for this test to bite";
  // Sums of a few dozen terms of mixed size: 1e-10 relative is round-off.
  EXPECT_TRUE(approx(energy, expected, 1e-10));
  EXPECT_GT(expected, 0.0);
}

} // namespace
} // namespace formflow::testing
