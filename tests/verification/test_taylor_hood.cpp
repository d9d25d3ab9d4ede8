// SPDX-License-Identifier: MIT
// Taylor–Hood (Q2–Q1, continuous pressure) runs end to end (issue 5): the exact
// constraint against every Q1 pressure, the d → 0 limit, agreement with
// Q2–P1disc on the sticking ram, power balance, smooth pressure, exact contact.
#include "formflow/app/simulation.hpp"
#include "formflow/assembly/saddle_point_system.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/fem/quadrature.hpp"
#include "formflow/io/mesh_input.hpp"
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/saddle_point_iteration.hpp"
#include "support/approx.hpp"
#include "verification/checkerboard.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace formflow {
namespace {

using testing::approx;

constexpr Real slip_line_pressure = 1.0 + M_PI / 2.0; // (1 + π/2) k, SPEC §4

io::Case sticking_ram(fem::PressureSpace space, Real d, Real size) {
  io::Case case_;
  case_.process.ram = physics::RamCondition::Sticking;
  case_.mesh.size = size;
  case_.formulation.type = assembly::FormulationType::Mixed;
  case_.formulation.pressure = space;
  case_.penalty.d = d;
  return case_;
}

/// (q_i, div u) for every Q1 basis function q_i, and Σ_a |(q_i, div φ_a)| |u_a|
/// (the size of the terms that cancel), from the cell matrices of the pair.
std::pair<VectorX, VectorX> constraint_residual(const mesh::Mesh<2>& mesh, const io::Case& case_,
                                                const VectorX& u) {
  assembly::ConstraintMultipliers<2> pressure(mesh, case_.penalty, case_.formulation,
                                              fem::gauss_rule<2>(mesh.order + 1), 0);
  VectorX residual = VectorX::Zero(pressure.n_pressure_dofs());
  VectorX scale = VectorX::Zero(pressure.n_pressure_dofs());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    const MatrixX& divergence = pressure.cell_divergence(cell);
    VectorX local(divergence.cols());
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      local.segment<2>(2 * a) = u.segment<2>(fem::dof_of<2>(mesh.cells(a, cell), 0));
    const auto dofs = pressure.cell_pressure_dofs(cell);
    for (Index i = 0; i < divergence.rows(); ++i) {
      residual[dofs[i]] += divergence.row(i).dot(local);
      scale[dofs[i]] += divergence.row(i).cwiseAbs().dot(local.cwiseAbs());
    }
  }
  return {residual, scale};
}

/// The sticking-ram runs (d = 0) the benchmark checks share: Taylor–Hood at
/// h = 1 and 0.5, Q2–P1disc at h = 0.5. One test runs them once (ctest starts
/// a process per test, so a shared fixture would solve them three times).
struct StickingRamRuns {
  const app::Simulation& coarse; ///< Taylor–Hood, h = 1
  const app::Simulation& fine;   ///< Taylor–Hood, h = 0.5
  const app::Simulation& p1disc; ///< Q2–P1disc, h = 0.5
};

void check_exact_constraint(const StickingRamRuns& runs) {
  for (const app::Simulation* run : {&runs.coarse, &runs.fine}) {
    ASSERT_TRUE(run->results.converged());
    const auto [residual, scale] =
        constraint_residual(run->plane_mesh(), sticking_ram(fem::PressureSpace::Q1, 0.0, 1.0),
                            run->results.fields.velocity);
    // Round-off of the LU solve: every (q_i, div u) cancels to ~1e-12 of its terms.
    // (Q2–P1disc's velocity, constrained against another space, fails this.)
    std::printf("Taylor-Hood h = %g: max |(q_i, div u)| = %.2e of terms up to %.2e\n",
                run == &runs.coarse ? 1.0 : 0.5, residual.cwiseAbs().maxCoeff(), scale.maxCoeff());
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-9 * scale.maxCoeff());
    // The pressure term does no work; the ram reaction (with B_cᵀ p) equals the power.
    EXPECT_LT(std::abs(run->results.power.volumetric_penalty), 1e-8 * run->results.power.total());
    EXPECT_TRUE(
        approx(run->results.pressure.ram_reaction, run->results.pressure.total_power, 1e-4));
  }
  const auto [other, other_scale] =
      constraint_residual(runs.p1disc.plane_mesh(), sticking_ram(fem::PressureSpace::Q1, 0.0, 0.5),
                          runs.p1disc.results.fields.velocity);
  EXPECT_GT(other.cwiseAbs().maxCoeff(), 1e-6 * other_scale.maxCoeff());
}

void check_agreement_with_q2p1disc(const StickingRamRuns& runs) {
  const Real coarse = runs.coarse.results.pressure.ram_reaction;
  const Real fine = runs.fine.results.pressure.ram_reaction;
  const Real p1disc = runs.p1disc.results.pressure.ram_reaction;
  std::printf("ram pressure: Taylor-Hood h = 1: %.4f, h = 0.5: %.4f; Q2-P1disc h = 0.5: %.4f\n",
              coarse, fine, p1disc);
  ASSERT_TRUE(runs.p1disc.results.converged());
  // Both are upper bounds of a first-order approach to 2.5708 (docs/mixed.md):
  // Taylor–Hood's error at least halves from h = 1 to 0.5, and the two pairs
  // differ by less than Q2–P1disc's own discretisation error.
  EXPECT_GT(fine, slip_line_pressure);
  EXPECT_GT(p1disc, slip_line_pressure);
  EXPECT_LT(fine - slip_line_pressure, 0.55 * (coarse - slip_line_pressure));
  EXPECT_LT(std::abs(fine - p1disc), p1disc - slip_line_pressure);
}

void check_pressure_is_smooth(const StickingRamRuns& runs) {
  const double coarse = testing::checkerboard_share(
      runs.coarse.plane_mesh(), 1.0, runs.coarse.results.fields.cell_hydrostatic_stress, 8.0);
  const double fine = testing::checkerboard_share(
      runs.fine.plane_mesh(), 0.5, runs.fine.results.fields.cell_hydrostatic_stress, 8.0);
  std::printf("Taylor-Hood checkerboard share: h = 1: %.3e, h = 0.5: %.3e\n", coarse, fine);
  // Cell means of a smooth field: O(h²) (Q1–P0's spurious mode stays ~0.1).
  EXPECT_LT(fine, 0.5 * coarse);
  EXPECT_LT(fine, 1e-2);
  // The nodal field is the continuous Q1 pressure itself, interpolated to the
  // mid-nodes: on every cell (lexicographic Q2 nodes, vertices 0, 2, 6, 8) each
  // mid-edge value is the mean of its edge's vertices and the centre the mean of
  // all four — no averaging across cells has blurred it.
  const mesh::Mesh<2>& mesh = runs.fine.plane_mesh();
  const VectorX& nodal = runs.fine.results.fields.hydrostatic_stress;
  EXPECT_GT(nodal.cwiseAbs().maxCoeff(), 1.0);
  Real mismatch = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    auto at = [&](int local) { return nodal[mesh.cells(local, cell)]; };
    for (auto [middle, first, second] :
         {std::array{1, 0, 2}, std::array{3, 0, 6}, std::array{5, 2, 8}, std::array{7, 6, 8}})
      mismatch = std::max(mismatch, std::abs(at(middle) - 0.5 * (at(first) + at(second))));
    mismatch = std::max(mismatch, std::abs(at(4) - 0.25 * (at(0) + at(2) + at(6) + at(8))));
  }
  EXPECT_LT(mismatch, 1e-10 * nodal.cwiseAbs().maxCoeff());
}

TEST(TaylorHoodBenchmark, StickingRamAgainstQ2P1discAtH1AndH05) {
  const app::Simulation coarse = app::simulate(sticking_ram(fem::PressureSpace::Q1, 0.0, 1.0));
  const app::Simulation fine = app::simulate(sticking_ram(fem::PressureSpace::Q1, 0.0, 0.5));
  const app::Simulation p1disc = app::simulate(sticking_ram(fem::PressureSpace::P1disc, 0.0, 0.5));
  const StickingRamRuns runs{coarse, fine, p1disc};
  {
    SCOPED_TRACE("(q, div u) = 0 for every Q1 q; reaction = total power");
    check_exact_constraint(runs);
  }
  {
    SCOPED_TRACE("agreement with Q2-P1disc, approach to 2.5708");
    check_agreement_with_q2p1disc(runs);
  }
  {
    SCOPED_TRACE("no checkerboard; nodal field = Q1 pressure");
    check_pressure_is_smooth(runs);
  }
}

TEST(TaylorHood, PerturbedProblemApproachesTheExactOneLinearlyInD) {
  // Thm 3.4: ‖u_d − u‖ ≤ C d. Coarse mesh and a tight δ so that the iteration
  // error (δ-sized) stays far below the d-effect being measured.
  auto run = [](Real d) {
    io::Case case_ = sticking_ram(fem::PressureSpace::Q1, d, 2.5);
    case_.solver.tolerance = 1e-11;
    case_.solver.max_iterations = 3000;
    post::Results results = app::simulate(case_).results;
    EXPECT_TRUE(results.converged());
    return results;
  };
  const post::Results exact = run(0.0);
  const post::Results small = run(1e-6);
  const post::Results smaller = run(1e-7);
  const Real error_small = (small.fields.velocity - exact.fields.velocity).norm();
  const Real error_smaller = (smaller.fields.velocity - exact.fields.velocity).norm();
  std::printf("Taylor-Hood |u_d - u_0|: d = 1e-6: %.3e, d = 1e-7: %.3e\n", error_small,
              error_smaller);
  EXPECT_LT(error_small, 1e-3 * exact.fields.velocity.norm());
  const Real ratio = error_small / error_smaller;
  EXPECT_GT(ratio, 7.0); // O(d): ten times smaller d, ~ten times smaller error
  EXPECT_LT(ratio, 14.0);
  EXPECT_TRUE(approx(small.pressure.ram_reaction, exact.pressure.ram_reaction, 1e-4));
}

TEST(TaylorHood, ExactContactIsTheLimitOfTheContactPenalty) {
  auto run = [](Real d_n) {
    io::Case case_ = sticking_ram(fem::PressureSpace::Q1, 0.0, 2.5);
    case_.penalty.d_n = d_n;
    case_.friction.mu = 0.1;
    return app::simulate(case_).results;
  };
  const post::Results exact = run(0.0);
  const post::Results perturbed = run(1e-10);
  ASSERT_TRUE(exact.converged());
  ASSERT_TRUE(perturbed.converged());
  EXPECT_EQ(exact.method, "saddle point (umfpack) with uzawa contact around secant");
  EXPECT_TRUE(approx(exact.pressure.ram_reaction, perturbed.pressure.ram_reaction, 1e-4));
  EXPECT_TRUE(approx(exact.pressure.ram_reaction, exact.pressure.total_power, 1e-3));
  ASSERT_EQ(exact.contact.size(), perturbed.contact.size());
  Real largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < exact.contact.size(); ++k) {
    largest = std::max(largest, std::abs(perturbed.contact[k].contact_pressure));
    difference = std::max(difference, std::abs(exact.contact[k].contact_pressure -
                                               perturbed.contact[k].contact_pressure));
  }
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(difference, 1e-3 * largest);
}

TEST(TaylorHood, ConstantPressureModeIsPinnedOnlyWhenEveryBoundaryVelocityIsPrescribed) {
  // A driven cavity on a box: the velocity is prescribed on the whole boundary
  // (lid u_x = 1 at y = 1), so the pressure level is free; the benchmark channel
  // has free surfaces and needs no pin.
  const mesh::Mesh<2> mesh = mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), 4, 4, 2);
  assembly::ProblemSettings settings;
  settings.penalty.d = 0.0;
  assembly::DirichletConstraints constraints;
  constraints.prescribed.assign(mesh.n_nodes() * 2, false);
  constraints.values = VectorX::Zero(mesh.n_nodes() * 2);
  for (Index node = 0; node < mesh.n_nodes(); ++node) {
    const Point<2> x = mesh.nodes.col(node);
    const bool boundary = x[0] < 1e-12 || x[0] > 1 - 1e-12 || x[1] < 1e-12 || x[1] > 1 - 1e-12;
    if (!boundary) continue;
    constraints.prescribed[2 * node] = constraints.prescribed[2 * node + 1] = true;
    if (x[1] > 1 - 1e-12 && x[0] > 1e-12 && x[0] < 1 - 1e-12) constraints.values[2 * node] = 1.0;
  }
  constraints.driven_label = mesh::BoundaryLabel::FreeExit; // the lid: y = 1
  assembly::FormingProblem<2> problem(mesh, settings, constraints, {});
  assembly::Formulation formulation;
  formulation.type = assembly::FormulationType::Mixed;
  formulation.pressure = fem::PressureSpace::Q1;
  assembly::ConstraintMultipliers<2> multipliers(mesh, settings.penalty, formulation,
                                                 problem.full_rule(), problem.n_contact_points());
  problem.attach_multipliers(&multipliers);
  EXPECT_TRUE(assembly::SaddlePointSystem<2>(problem, multipliers).has_pinned_pressure());

  auto solver = solvers::make_umfpack_solver();
  PhaseTimes times;
  solvers::FormingNonlinearProblem<2> nonlinear(problem);
  solvers::TimedLinearStep linear(*solver, times);
  solvers::SaddlePointSolve<2> saddle(nonlinear, linear);
  const solvers::SecantOutcome outcome =
      solvers::secant_iteration(nonlinear, saddle, solvers::IterationControl{}, {});
  ASSERT_EQ(outcome.stop_reason, solvers::StopReason::Converged);
  const VectorX& pressure = multipliers.global_pressure();
  ASSERT_TRUE(pressure.allFinite());
  EXPECT_GT(pressure.cwiseAbs().maxCoeff(), 1e-2); // a real pressure, corners singular
  // Zero mean, ∫ p dx = 0 (the level fixed explicitly).
  Real integral = 0.0, magnitude = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    integral += multipliers.pressure_integral(cell, outcome.velocity);
    magnitude += std::abs(multipliers.pressure_integral(cell, outcome.velocity));
  }
  EXPECT_LT(std::abs(integral), 1e-10 * magnitude);

  const io::Case channel_case = sticking_ram(fem::PressureSpace::Q1, 0.0, 2.5);
  const mesh::Mesh<2> channel_mesh = std::get<mesh::Mesh<2>>(io::load_mesh(channel_case));
  const assembly::FormingProblem<2> channel(channel_mesh, app::problem_settings(channel_case));
  assembly::ConstraintMultipliers<2> channel_pressure(channel_mesh, channel.settings().penalty,
                                                      formulation, channel.full_rule(),
                                                      channel.n_contact_points());
  EXPECT_FALSE(assembly::SaddlePointSystem<2>(channel, channel_pressure).has_pinned_pressure());
}

} // namespace
} // namespace formflow
