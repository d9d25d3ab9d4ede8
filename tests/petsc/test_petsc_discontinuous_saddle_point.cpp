// SPDX-License-Identifier: MIT
// formulation.discontinuous_pressure = "saddle_point" (issue 20): the P1disc pressure
// kept as global unknowns gives the condensed run's load, by UMFPACK and by PETSc's
// default FGMRES + fieldsplit Schur preconditioner (velocity AMG, viscosity-scaled
// pressure mass), whose Krylov counts stay bounded when the mesh is refined.
#include "formflow/app/simulation.hpp"
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "support/approx.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace formflow {
namespace {

constexpr Real delta = 1e-10; // solver.tolerance of these runs

/// The secant run of a case file at δ = `tolerance` with `edits`.
app::Simulation run_case(const std::string& path, Real tolerance, std::vector<io::Override> edits,
                         bool estimate_condition = false) {
  edits.insert(edits.begin(), {{"formulation.type", "mixed"},
                               {"solver.method", "secant"},
                               // the plain loop: the same iterates as the condensed one
                               {"solver.acceleration", "none"},
                               {"solver.tolerance", fmt::format("{}", tolerance)}});
  app::Simulation simulation =
      app::simulate(io::load_case(path, std::move(edits)), {}, estimate_condition);
  EXPECT_TRUE(simulation.results.converged())
      << solvers::stop_reason_name(simulation.results.stop_reason);
  return simulation;
}

app::Simulation run(std::vector<io::Override> edits, bool estimate_condition = false) {
  edits.insert(edits.begin(), {{"formulation.type", "mixed"},
                               {"friction.mu", "0.1"},
                               {"solver.method", "secant"},
                               // the plain loop: the same iterates as the condensed one
                               {"solver.acceleration", "none"},
                               {"solver.tolerance", "1e-10"}});
  app::Simulation simulation =
      app::simulate(io::load_case("", std::move(edits)), {}, estimate_condition);
  EXPECT_TRUE(simulation.results.converged())
      << solvers::stop_reason_name(simulation.results.stop_reason);
  return simulation;
}

Real relative_difference(const app::Simulation& a, const app::Simulation& b) {
  return std::abs(a.results.pressure.ram_reaction - b.results.pressure.ram_reaction) /
         std::abs(b.results.pressure.ram_reaction);
}

/// Condensing the saddle point cell by cell (p = (1/d) M⁻¹ B u) gives the condensed
/// system exactly, so both loops take the same secant iterates and differ only by
/// their solves' errors. A backward-stable direct solve of a system of reciprocal
/// condition r errs by at most ε/r relative; a Krylov solve stopped at the relative
/// residual rtol by at most rtol/r; the contracting loop (ρ ≤ 0.9) amplifies a
/// step's error by at most 1/(1 − ρ) = 10, and each run stops within δ.
Real agreement(Real solve_error) {
  return 10 * (delta + solve_error);
}

TEST(DiscontinuousSaddlePoint, GivesTheCondensedLoadByUmfpackAndByPetsc) {
  constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
  constexpr Real krylov_tolerance = 1e-12; // -ksp_rtol below
  const app::Simulation condensed = run({{"mesh.size", "2.5"}}, /*estimate_condition=*/true);
  // The saddle point's loop without its coarse start, the condensed secant loop's
  // start (test_petsc_saddle_point_sequencing.cpp checks the sequenced one).
  const app::Simulation by_umfpack = run({{"mesh.size", "2.5"},
                                          {"formulation.discontinuous_pressure", "saddle_point"},
                                          {"solver.coarse_levels", "0"}},
                                         /*estimate_condition=*/true);
  const app::Simulation by_petsc = run({{"mesh.size", "2.5"},
                                        {"formulation.discontinuous_pressure", "saddle_point"},
                                        {"solver.coarse_levels", "0"},
                                        {"solver.linear", "petsc"},
                                        {"solver.petsc_options", "-ksp_rtol 1e-12"}});
  ASSERT_TRUE(condensed.reciprocal_condition && by_umfpack.reciprocal_condition);
  const Real r_condensed = *condensed.reciprocal_condition;
  const Real r_saddle = *by_umfpack.reciprocal_condition;
  const Real direct = agreement(epsilon / r_condensed + epsilon / r_saddle);
  const Real iterative = agreement(epsilon / r_condensed + krylov_tolerance / r_saddle);
  std::cout << "rcond condensed " << r_condensed << " saddle " << r_saddle << "; UMFPACK "
            << relative_difference(by_umfpack, condensed) << " (tolerance " << direct << "), PETSc "
            << relative_difference(by_petsc, condensed) << " (tolerance " << iterative << ")\n";
  EXPECT_LE(relative_difference(by_umfpack, condensed), direct);
  EXPECT_LE(relative_difference(by_petsc, condensed), iterative);
  EXPECT_EQ(by_umfpack.results.method, "saddle point (umfpack) around secant");
  EXPECT_EQ(by_petsc.results.linear_algebra.solver, "petsc-fgmres-fieldsplit");
  // The same iterates: the same number of them (the last change may cross δ one step
  // apart when the solves' errors reach δ).
  EXPECT_NEAR(by_petsc.results.iterations, condensed.results.iterations, 1);
  EXPECT_NEAR(by_umfpack.results.iterations, condensed.results.iterations, 1);
}

/// The largest Krylov count of the secant steps of a default PETSc saddle-point run.
long largest_krylov_count(const std::string& size) {
  // δ = 1e-4: the counts are the solves', not the loop's (the later override wins).
  const app::Simulation simulation = run({{"mesh.size", size},
                                          {"formulation.discontinuous_pressure", "saddle_point"},
                                          {"solver.linear", "petsc"},
                                          {"solver.tolerance", "1e-4"}});
  long largest = 0;
  for (const auto& record : simulation.results.history)
    largest = std::max<long>(largest, record.linear_iterations);
  std::cout << "h = " << size << ": " << simulation.results.iterations
            << " secant steps, largest Krylov count " << largest << "\n";
  return largest;
}

/// The preconditioner's blocks are spectrally equivalent to the velocity block (one
/// BoomerAMG V-cycle, the default) and to the Schur complement (the
/// viscosity-scaled mass, whose constants are the inf-sup constant's, bounded in h:
/// docs/mixed.md), so the FGMRES count to a fixed rtol is bounded independently of
/// h. The target for that is "within 2× over refinements": one halving of h
/// may at most double the worst step's count.
TEST(DiscontinuousSaddlePoint, KrylovCountsStayBoundedUnderRefinement) {
  const long coarse = largest_krylov_count("2.5");
  const long fine = largest_krylov_count("1.25");
  EXPECT_GT(coarse, 1); // an iterative solve, not the direct default
  EXPECT_LE(fine, 2 * coarse);
}

constexpr Real same_iterates_rtol = 1e-12; // FGMRES's -ksp_rtol of both runs compared

/// The paper case at h = 2.5 on the iterative saddle-point path, every step solved to
/// same_iterates_rtol, with formflow's PETSc `options` added: two such runs that differ
/// only in how the same system reaches PETSc take the same secant iterates.
app::Simulation exact_steps_saddle_run(const std::string& options) {
  return run(
      {{"mesh.size", "2.5"},
       {"formulation.discontinuous_pressure", "saddle_point"},
       {"solver.linear", "petsc"},
       {"solver.petsc_options",
        fmt::format("-ksp_rtol {} -formflow_inexact_steps 0", same_iterates_rtol) + options}},
      /*estimate_condition=*/true);
}

/// The velocity block laid out node by node (systems BoomerAMG, the default on this
/// path) or in the free numbering (`-formflow_velocity_node_blocks 0`, scalar BoomerAMG)
/// is the same system renumbered plus decoupled rows: the same secant iterates, so the
/// same load within the Krylov solves' error (agreement() with rtol/r_s for each run).
/// Every step is solved to rtol (`-formflow_inexact_steps 0`): a loose step's iterate
/// depends on the preconditioner's path, so only exact steps make the same iterates.
TEST(DiscontinuousSaddlePoint, TheNodeLayoutIsARenumberingAndCanBeSwitchedOff) {
  const app::Simulation laid_out = exact_steps_saddle_run("");
  const app::Simulation free_numbering =
      exact_steps_saddle_run(" -formflow_velocity_node_blocks 0");
  ASSERT_TRUE(laid_out.reciprocal_condition.has_value());
  // Both runs err by at most rtol/r_s each (r_s the saddle point's reciprocal condition).
  const Real tolerance = agreement(2 * same_iterates_rtol / *laid_out.reciprocal_condition);
  std::cout << "node layout against free numbering: "
            << relative_difference(laid_out, free_numbering) << " (tolerance " << tolerance
            << ")\n";
  EXPECT_LE(relative_difference(laid_out, free_numbering), tolerance);
  EXPECT_NEAR(laid_out.results.iterations, free_numbering.results.iterations, 1);
}

/// The saddle point goes to PETSc as four blocks (MATNEST, so that fieldsplit takes the
/// velocity block without a copy) unless -formflow_saddle_point_nest 0 asks for one AIJ
/// matrix: the same operator and preconditioner, so the same iterates up to the order
/// of the products' additions.
TEST(DiscontinuousSaddlePoint, TheFourBlocksAreTheWholeMatrix) {
  const app::Simulation blocks = exact_steps_saddle_run("");
  const app::Simulation whole = exact_steps_saddle_run(" -formflow_saddle_point_nest 0");
  ASSERT_TRUE(blocks.reciprocal_condition.has_value());
  // Both runs err by at most rtol/r_s each (r_s the saddle point's reciprocal condition).
  const Real tolerance = agreement(2 * same_iterates_rtol / *blocks.reciprocal_condition);
  std::cout << "four blocks against the whole matrix: " << relative_difference(blocks, whole)
            << " (tolerance " << tolerance << ")\n";
  EXPECT_LE(relative_difference(blocks, whole), tolerance);
  EXPECT_NEAR(blocks.results.iterations, whole.results.iterations, 1);
}

/// The largest Krylov count of the secant steps of `simulation`.
long largest_step_count(const app::Simulation& simulation) {
  long largest = 0;
  for (const auto& record : simulation.results.history)
    largest = std::max<long>(largest, record.linear_iterations);
  return largest;
}

/// The 3D round quarter (cases/round-rod-3d.toml: conical die, nodal normals, μ = 0.05
/// on the die) at h = 0.5. Its contact penalty 1/d_N = 10⁶ on the inclined die couples
/// the Cartesian components of each Γ3 node 10⁶ times more stiffly than the viscous
/// term along a direction no coordinate axis follows; the PETSc path solves with those
/// nodes' dofs in their normal–tangent frame (assembly::contact_frames), where the
/// penalty is one diagonal entry per node. Without the frames the steps took 1 600–7 000
/// Krylov iterations (docs/petsc.md).
TEST(DiscontinuousSaddlePoint, RoundQuarterConvergesInOneRestartCycleWithTheCondensedLoad) {
  constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
  constexpr Real krylov_tolerance = 1e-12; // -ksp_rtol below
  // δ: the agreement below is dominated by rtol/r_saddle (≈ 5e-6); a smaller δ only
  // adds secant steps (about 17 per decade here).
  constexpr Real round_delta = 1e-7;
  const std::string round = std::string(FORMFLOW_SOURCE_DIR) + "/cases/round-rod-3d.toml";
  const io::Override size{"mesh.size", "0.5"};
  const io::Override saddle_point{"formulation.discontinuous_pressure", "saddle_point"};
  const app::Simulation condensed =
      run_case(round, round_delta, {size}, /*estimate_condition=*/true);
  const app::Simulation by_umfpack =
      run_case(round, round_delta, {size, saddle_point}, /*estimate_condition=*/true);
  const app::Simulation by_petsc = run_case(round, round_delta,
                                            {size,
                                             saddle_point,
                                             {"solver.linear", "petsc"},
                                             {"solver.petsc_options", "-ksp_rtol 1e-12"}});
  ASSERT_TRUE(condensed.reciprocal_condition && by_umfpack.reciprocal_condition);
  const Real r_condensed = *condensed.reciprocal_condition;
  const Real r_saddle = *by_umfpack.reciprocal_condition;
  // agreement()'s derivation (above), at this run's δ.
  const Real iterative = 10 * (round_delta + epsilon / r_condensed + krylov_tolerance / r_saddle);
  const long largest = largest_step_count(by_petsc);
  std::cout << "round quarter h = 0.5: rcond condensed " << r_condensed << " saddle " << r_saddle
            << "; PETSc " << relative_difference(by_petsc, condensed) << " (tolerance " << iterative
            << "), UMFPACK " << relative_difference(by_umfpack, condensed)
            << "; largest Krylov count " << largest << " over " << by_petsc.results.iterations
            << " secant steps\n";
  EXPECT_LE(relative_difference(by_petsc, condensed), iterative);
  EXPECT_EQ(by_petsc.results.linear_algebra.solver, "petsc-fgmres-fieldsplit");
  // The bound: FGMRES keeps 100 directions (the default restart). A preconditioner
  // whose blocks are spectrally equivalent to the velocity block and to the Schur
  // complement, whatever 1/d_N, converges within one restart cycle to a fixed rtol; a
  // step that needs a restart has eigenvalues the preconditioner leaves uncontrolled,
  // which is what the penalty along the inclined normals did (1 600–7 000 per step at
  // rtol 1e-10). Asserted at rtol 1e-12, stricter than the default.
  EXPECT_GT(largest, 1); // iterative, not the direct default
  EXPECT_LE(largest, 100);
}

/// The combinations that cannot work are refused at load time by the key set last.
TEST(DiscontinuousSaddlePoint, CombinationsThatCannotWorkAreRefusedByKey) {
  const auto refused_key = [](std::vector<io::Override> edits) -> std::string {
    edits.emplace_back("formulation.discontinuous_pressure", "saddle_point");
    try {
      io::load_case("", std::move(edits));
    } catch (const InputError& error) {
      return error.key;
    }
    return "";
  };
  EXPECT_EQ(refused_key({}), "formulation.discontinuous_pressure"); // penalty formulation
  EXPECT_EQ(refused_key({{"formulation.type", "mixed"}, {"formulation.pressure", "Q1"}}),
            "formulation.discontinuous_pressure"); // continuous: set in vain
  EXPECT_EQ(refused_key({{"formulation.type", "mixed"}, {"solver.linear", "cholmod"}}),
            "formulation.discontinuous_pressure"); // Cholesky cannot factorise it
  EXPECT_EQ(refused_key({{"formulation.type", "mixed"}}), "");
}

} // namespace
} // namespace formflow
