// SPDX-License-Identifier: MIT
// The secant-modulus iteration on a small extrusion: convergence, stop reasons,
// independence of the iteration limit, the Newtonian (linear) case, and the
// reaction-equals-power identity.
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace formflow::testing {
namespace {

using solvers::StopReason;

/// Half channel 4 × 4 → 2 over 4 (50 % reduction like the benchmark), unit Q2 cells.
const mesh::Mesh<2>& small_mesh() {
  static const mesh::Mesh<2> m = mesh::make_channel_mesh(mesh::ChannelGeometry{4, 4, 2, 4}, 1.0, 2);
  return m;
}

solvers::SecantOutcome run(const assembly::FormingProblem<2>& problem,
                           const solvers::IterationControl& control, int* callbacks = nullptr,
                           PhaseTimes* phase_times = nullptr) {
  auto solver = solvers::make_cholmod_solver();
  PhaseTimes local_times;
  solvers::FormingNonlinearProblem<2> nonlinear(problem);
  return solvers::secant_iteration(
      nonlinear, *solver, control,
      [&](const solvers::IterationRecord&) {
        if (callbacks) ++*callbacks;
      },
      phase_times ? *phase_times : local_times);
}

/// The default case, solved once and shared (it is the slowest piece of the unit suite).
class SecantIteration : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    problem_ =
        std::make_unique<assembly::FormingProblem<2>>(small_mesh(), assembly::ProblemSettings{});
    outcome_ =
        std::make_unique<solvers::SecantOutcome>(run(*problem_, solvers::IterationControl{}));
  }
  static void TearDownTestSuite() {
    outcome_.reset();
    problem_.reset();
  }
  inline static std::unique_ptr<assembly::FormingProblem<2>> problem_;
  inline static std::unique_ptr<solvers::SecantOutcome> outcome_;
};

TEST_F(SecantIteration, ConvergesWithAHistoryEndingBelowTheTolerance) {
  const solvers::IterationControl control;
  ASSERT_EQ(outcome_->stop_reason, StopReason::Converged);
  const auto& history = outcome_->history;
  ASSERT_FALSE(history.empty());
  EXPECT_LT(history.back().relative_change, control.tolerance);
  // It stopped at the first iterate below δ, not later.
  for (std::size_t k = 0; k + 1 < history.size(); ++k) {
    EXPECT_EQ(history[k].iteration, static_cast<int>(k) + 1);
    EXPECT_GE(history[k].relative_change, control.tolerance) << "iteration " << k + 1;
  }
  EXPECT_EQ(history.back().iteration, static_cast<int>(history.size()));
  EXPECT_LT(static_cast<int>(history.size()), control.max_iterations);
}

TEST_F(SecantIteration, VelocityHonoursThePrescribedValues) {
  const auto& c = problem_->constraints();
  ASSERT_EQ(outcome_->velocity.size(), problem_->n_dofs());
  for (Index dof = 0; dof < problem_->n_dofs(); ++dof)
    if (c.prescribed[dof]) {
      EXPECT_EQ(outcome_->velocity[dof], c.values[dof]) << dof;
    }
  EXPECT_TRUE(outcome_->velocity.allFinite());
}

TEST_F(SecantIteration, NetBoundaryFluxVanishesUpToThePenalty) {
  // Incompressibility: ∮ u·n dΓ = ∫ ε̇_V dx = d ∫ σ_H dx. With d = 1e-3,
  // |σ_H| ≲ 3 and |Ω| = 24 that is ≲ 0.07, under 2 % of the ram flux
  // u⁰·H_in = 4. (The front flux alone need not equal the ram flux: the
  // domain is fixed, so material may cross the free surface Γ4.)
  fem::FacetValues<2> values(2, fem::gauss_rule<1>(3));
  typename fem::CellValues<2>::Gradients coordinates, velocities;
  double net = 0.0, ram = 0.0, front = 0.0, exit_surface = 0.0, contact = 0.0;
  for (const mesh::BoundaryFacet& facet : small_mesh().facets) {
    problem_->gather(facet.cell, &outcome_->velocity, coordinates, velocities);
    values.reinit(coordinates, facet.local_face);
    double flux = 0.0;
    for (int q = 0; q < values.n_points(); ++q)
      flux += values.JxW(q) * (velocities * values.shape(q)).dot(values.normal(q));
    net += flux;
    if (facet.label == mesh::BoundaryLabel::Rear) ram += flux;
    if (facet.label == mesh::BoundaryLabel::Front) front += flux;
    if (facet.label == mesh::BoundaryLabel::FreeExit) exit_surface += flux;
    if (mesh::is_contact(facet.label)) contact += flux;
  }
  const double ram_flux = problem_->settings().process.speed * 4.0;
  // Exact: u_x = u⁰ on the rear, outward normal −x.
  EXPECT_TRUE(approx(ram, -ram_flux, 1e-12));
  EXPECT_TRUE(approx(net, 0.0, 0.0, 0.02 * ram_flux))
      << "front " << front << ", free exit " << exit_surface << ", contact " << contact;
}

TEST_F(SecantIteration, PressureLiesBetweenIdealWorkAndTwiceTheSlipLineValue) {
  // Any admissible field dissipates at least the ideal plane-strain work,
  // p ≥ 2k ln(H_in/H_out) = 2 ln 2 ≈ 1.386 (k = σ_p/√3 ≈ 1). The exact
  // answer for the sliding ram is ≤ 2.5 (SPEC §4); a 4×4 Q2 mesh
  // overestimates it, but nowhere near 2 × 2.5708.
  const double pressure = outcome_->history.back().pressure;
  EXPECT_GT(pressure, 2.0 * std::log(2.0));
  EXPECT_LT(pressure, 2.0 * 2.5708);
}

TEST_F(SecantIteration, IterationLimitDoesNotChangeTheIterates) {
  const auto& full = outcome_->history;
  const int n = static_cast<int>(full.size());
  ASSERT_GT(n, 2) << "the case must need more than two iterations for this test to mean anything";

  // Stopped early: the same first two records, and the stop reason says why.
  solvers::IterationControl early;
  early.max_iterations = 2;
  int callbacks = 0;
  const solvers::SecantOutcome stopped = run(*problem_, early, &callbacks);
  EXPECT_EQ(stopped.stop_reason, StopReason::MaxIterations);
  ASSERT_EQ(stopped.history.size(), 2u);
  EXPECT_EQ(callbacks, 2);
  for (int k = 0; k < 2; ++k) {
    // Same arithmetic in the same order: identical to round-off (1e-12 relative).
    EXPECT_TRUE(approx(stopped.history[k].relative_change, full[k].relative_change, 1e-12));
    EXPECT_TRUE(approx(stopped.history[k].pressure, full[k].pressure, 1e-12));
  }

  // A limit equal to the number needed: convergence is checked first, so it
  // still converges, with the same answer.
  solvers::IterationControl exact;
  exact.max_iterations = n;
  const solvers::SecantOutcome enough = run(*problem_, exact);
  EXPECT_EQ(enough.stop_reason, StopReason::Converged);
  ASSERT_EQ(enough.history.size(), full.size());
  EXPECT_TRUE(approx((enough.velocity - outcome_->velocity).norm(), 0.0, 0.0,
                     1e-12 * outcome_->velocity.norm()));
}

TEST_F(SecantIteration, ZeroIterationsReturnsTheConstantViscositySolution) {
  solvers::IterationControl none;
  none.max_iterations = 0;
  PhaseTimes phase_times;
  const solvers::SecantOutcome outcome = run(*problem_, none, nullptr, &phase_times);
  EXPECT_EQ(outcome.stop_reason, StopReason::MaxIterations);
  EXPECT_TRUE(outcome.history.empty());
  // Not the zero-initialised vector: the first linear solve moved the free dofs.
  const auto& c = problem_->constraints();
  double free_motion = 0.0;
  for (Index dof = 0; dof < problem_->n_dofs(); ++dof)
    if (!c.prescribed[dof]) free_motion += std::abs(outcome.velocity[dof]);
  EXPECT_GT(free_motion, 1.0);
  for (const char* phase : {"assembly", "analysis", "factorization", "solve"})
    EXPECT_EQ(phase_times.all().count(phase), 1u) << phase;
}

TEST(SecantIterationNewtonian, ConstantViscosityConvergesAtOnce) {
  // α = 1 makes σ_p = A ε̄̇ on every branch: the secant viscosity is A at all
  // rates, equal to the starting viscosity σ_p(initial_rate)/initial_rate, so
  // K(u⁰) = K(·) and the first iteration (the loop's iteration 1 — the
  // starting solve is not counted) reproduces u⁰: change ≈ 0, converged.
  assembly::ProblemSettings settings;
  settings.law.as<physics::PiecewisePower>().alpha = 1.0;
  settings.law.as<physics::PiecewisePower>().A = 2.0;
  const assembly::FormingProblem<2> problem(small_mesh(), settings);
  const solvers::SecantOutcome outcome = run(problem, solvers::IterationControl{});
  EXPECT_EQ(outcome.stop_reason, StopReason::Converged);
  ASSERT_GE(outcome.history.size(), 1u);
  EXPECT_LE(outcome.history.size(), 2u);
  // Same matrix refactorised, same rhs: only round-off can differ.
  EXPECT_LT(outcome.history.front().relative_change, 1e-12);
}

TEST(SecantIterationNewtonian, RamReactionEqualsTheDiscretePower) {
  // For the linear problem K u = 0 on the free rows, uᵀKu = u_cᵀ (K_c· u):
  // the driven force times u⁰ is the total discrete power. The power is
  // summed here cell by cell from the kernels, bypassing the global assembly.
  assembly::ProblemSettings settings;
  settings.law.as<physics::PiecewisePower>().alpha = 1.0;
  const mesh::Mesh<2>& m = small_mesh();
  const assembly::FormingProblem<2> problem(m, settings);
  const solvers::SecantOutcome outcome = run(problem, solvers::IterationControl{});
  ASSERT_EQ(outcome.stop_reason, StopReason::Converged);
  const VectorX& u = outcome.velocity;

  fem::CellValues<2> full(2, fem::gauss_rule<2>(3)),
      volumetric(2, fem::gauss_rule<2>(settings.volumetric_points));
  fem::FacetValues<2> facet(2, fem::gauss_rule<1>(3));
  typename fem::CellValues<2>::Gradients coordinates, velocities;
  const std::vector<Real> viscosity(
      full.n_points(), settings.law.as<physics::PiecewisePower>().A); // Newtonian: ν = A
  double power = 0.0;
  for (Index cell = 0; cell < m.n_cells(); ++cell) {
    problem.gather(cell, &u, coordinates, velocities);
    ASSERT_TRUE(full.reinit(coordinates));
    volumetric.reinit(coordinates);
    MatrixX local = MatrixX::Zero(18, 18);
    assembly::add_viscous_term<2>(full, viscosity, settings.viscous_strain, local);
    assembly::add_volumetric_penalty<2>(volumetric, settings.penalty.d, local);
    for (const mesh::BoundaryFacet& f : m.facets)
      if (f.cell == cell && mesh::is_contact(f.label)) {
        facet.reinit(coordinates, f.local_face);
        assembly::add_contact_penalty<2>(facet, settings.penalty.d_n, local);
      }
    const Eigen::Map<const VectorX> u_local(velocities.data(), 18);
    power += u_local.dot(local * u_local);
  }
  const double reaction_power =
      outcome.history.back().pressure * problem.driven_height() * settings.process.speed;
  // The identity holds up to the solve's residual, ~ε·‖K‖·‖u‖² with
  // ‖K‖ ~ 1/d_N = 1e6 over ~240 dofs: ≲ 1e-6 absolute against a power of O(10).
  EXPECT_TRUE(approx(reaction_power, power, 1e-7, 1e-6));
  EXPECT_GT(power, 0.0);
}

} // namespace
} // namespace formflow::testing
