// SPDX-License-Identifier: MIT
// solver.linear = "petsc" (issue 20): PETSc's default direct MUMPS solve gives the
// CHOLMOD (or UMFPACK) numbers on the paper's case, a mixed and a friction case and
// the Taylor–Hood saddle point; Krylov counts reach the history and the results;
// options that PETSc does not know are refused naming solver.petsc_options.
#include "formflow/app/simulation.hpp"
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace formflow {
namespace {

constexpr Real solver_delta = 1e-10; // solver.tolerance of these runs

std::vector<io::Override> with_common(std::vector<io::Override> edits) {
  edits.insert(edits.begin(), {{"mesh.size", "2.5"}, {"solver.tolerance", "1e-10"}});
  return edits;
}

app::Simulation run_petsc_case(std::vector<io::Override> edits, bool estimate_condition = false) {
  app::Simulation simulation =
      app::simulate(io::load_case("", with_common(std::move(edits))), {}, estimate_condition);
  EXPECT_TRUE(simulation.results.converged())
      << solvers::stop_reason_name(simulation.results.stop_reason);
  return simulation;
}

/// How far two runs of the same iteration with two backward-stable direct solvers
/// may differ in a reaction (relative). Each linear solve's relative forward error
/// is at most κ·ε (κ = 1/rcond of the system at the solution, ε the double
/// precision); the loop contracts, so these errors do not accumulate beyond a
/// factor 1/(1 − ρ) ≤ 10 for the contraction ρ ≤ 0.9 of these runs; and each run
/// stops within its own δ-sized last change, which the same factor bounds.
Real direct_agreement(Real reciprocal_condition) {
  constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
  return 10 * (solver_delta + epsilon / reciprocal_condition);
}

class PetscMatchesCholmod : public ::testing::TestWithParam<std::vector<io::Override>> {};

TEST_P(PetscMatchesCholmod, DirectMumpsGivesTheSameReaction) {
  std::vector<io::Override> cholmod = GetParam(), petsc = GetParam();
  petsc.emplace_back("solver.linear", "petsc");
  const app::Simulation by_cholmod = run_petsc_case(cholmod, /*estimate_condition=*/true);
  const app::Simulation by_petsc = run_petsc_case(petsc);
  ASSERT_TRUE(by_cholmod.reciprocal_condition.has_value());
  const Real tolerance = direct_agreement(*by_cholmod.reciprocal_condition);
  std::cout << "rcond " << *by_cholmod.reciprocal_condition << " tolerance " << tolerance
            << " difference "
            << std::abs(by_petsc.results.pressure.ram_reaction -
                        by_cholmod.results.pressure.ram_reaction) /
                   by_cholmod.results.pressure.ram_reaction
            << "\n";
  EXPECT_TRUE(testing::approx(by_petsc.results.pressure.ram_reaction,
                              by_cholmod.results.pressure.ram_reaction, tolerance))
      << "rcond " << *by_cholmod.reciprocal_condition;
  EXPECT_EQ(by_petsc.results.method, by_cholmod.results.method);
  // The direct KSP ("preonly") counts one iteration per solve: at least one per step.
  const post::Results& results = by_petsc.results;
  EXPECT_EQ(results.linear_algebra.solver, "petsc-preonly-cholesky"); // the default: MUMPS
  EXPECT_GE(results.linear_algebra.iterations, results.iterations);
  long per_step_total = 0;
  for (const auto& record : results.history) {
    EXPECT_GE(record.linear_iterations, 1) << "iteration " << record.iteration;
    per_step_total += record.linear_iterations;
  }
  EXPECT_LE(per_step_total, results.linear_algebra.iterations);
  EXPECT_EQ(by_cholmod.results.linear_algebra.iterations, -1);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PetscMatchesCholmod,
    ::testing::Values(std::vector<io::Override>{},                              // the paper's case
                      std::vector<io::Override>{{"friction.mu", "0.1"}},        // friction, Newton
                      std::vector<io::Override>{{"formulation.type", "mixed"}}, // mixed, condensed
                      std::vector<io::Override>{{"formulation.type", "mixed"},
                                                {"penalty.d", "0"}}));

TEST(PetscSolver, TaylorHoodSaddlePointByMumpsLu) {
  const std::vector<io::Override> taylor_hood = {{"formulation.type", "mixed"},
                                                 {"formulation.pressure", "Q1"}};
  std::vector<io::Override> umfpack = taylor_hood, petsc = taylor_hood;
  umfpack.emplace_back("solver.linear", "umfpack");
  petsc.emplace_back("solver.linear", "petsc");
  const app::Simulation by_umfpack = run_petsc_case(umfpack, /*estimate_condition=*/true);
  const app::Simulation by_petsc = run_petsc_case(petsc);
  EXPECT_EQ(by_petsc.results.method, "saddle point (petsc) around secant");
  const Real tolerance = direct_agreement(by_umfpack.reciprocal_condition.value_or(0.0));
  EXPECT_TRUE(testing::approx(by_petsc.results.pressure.ram_reaction,
                              by_umfpack.results.pressure.ram_reaction, tolerance));
}

/// The iterative saddle-point path of docs/petsc.md: FGMRES with a fieldsplit Schur
/// preconditioner (a BoomerAMG V-cycle on the velocity, LU of selfp for the Schur
/// complement), the option set the docs recommend.
TEST(PetscSolver, TaylorHoodByFieldsplitSchurGivesTheLuReaction) {
  constexpr Real krylov_tolerance = 1e-12; // -ksp_rtol below
  const std::vector<io::Override> taylor_hood = {{"formulation.type", "mixed"},
                                                 {"formulation.pressure", "Q1"}};
  std::vector<io::Override> umfpack = taylor_hood, petsc = taylor_hood;
  umfpack.emplace_back("solver.linear", "umfpack");
  petsc.emplace_back("solver.linear", "petsc");
  petsc.emplace_back("solver.petsc_options",
                     "-ksp_type fgmres -ksp_rtol 1e-12 -pc_type fieldsplit -pc_fieldsplit_type "
                     "schur -pc_fieldsplit_schur_fact_type full -pc_fieldsplit_schur_precondition "
                     "selfp -fieldsplit_u_ksp_type preonly -fieldsplit_u_pc_type hypre "
                     "-fieldsplit_p_ksp_type preonly -fieldsplit_p_pc_type lu");
  const app::Simulation by_umfpack = run_petsc_case(umfpack, /*estimate_condition=*/true);
  const app::Simulation by_petsc = run_petsc_case(petsc);
  EXPECT_EQ(by_petsc.results.linear_algebra.solver, "petsc-fgmres-fieldsplit");
  // Each solve stops at a relative residual below krylov_tolerance: its forward
  // error is at most κ times that, on top of the direct solvers' κ·ε.
  const Real rcond = by_umfpack.reciprocal_condition.value_or(0.0);
  const Real tolerance = direct_agreement(rcond) + 10 * krylov_tolerance / rcond;
  EXPECT_TRUE(testing::approx(by_petsc.results.pressure.ram_reaction,
                              by_umfpack.results.pressure.ram_reaction, tolerance))
      << "rcond " << rcond;
  std::cout << "rcond " << rcond << " tolerance " << tolerance << " difference "
            << std::abs(by_petsc.results.pressure.ram_reaction -
                        by_umfpack.results.pressure.ram_reaction) /
                   by_umfpack.results.pressure.ram_reaction
            << "\n";
  for (const auto& record : by_petsc.results.history) EXPECT_GT(record.linear_iterations, 1);
}

/// Runs the default case with `options` and returns the refusal's key and text.
InputError refusal(const std::string& options) {
  try {
    app::simulate(io::load_case(
        "", with_common({{"solver.linear", "petsc"}, {"solver.petsc_options", options}})));
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << options << " was not refused";
  return InputError("", 0, "", "");
}

TEST(PetscOptions, AnOptionNothingReadsIsRefusedByName) {
  const InputError error = refusal("-ksp_tyep cg");
  EXPECT_EQ(error.key, "solver.petsc_options");
  EXPECT_NE(error.message.find("-ksp_tyep"), std::string::npos) << error.what();
}

TEST(PetscOptions, AnUnknownTypeIsRefusedWithPetscsWords) {
  const InputError error = refusal("-ksp_type no_such_krylov");
  EXPECT_EQ(error.key, "solver.petsc_options");
  EXPECT_NE(error.message.find("no_such_krylov"), std::string::npos) << error.what();
}

TEST(PetscOptions, MalformedTextIsRefusedAtLoadTime) {
  try {
    io::load_case("", {{"solver.linear", "petsc"}, {"solver.petsc_options", "ksp_type cg"}});
    FAIL() << "a value with no option name before it";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key, "solver.petsc_options");
  }
  try {
    io::load_case("", {{"solver.petsc_options", "-ksp_type cg"}});
    FAIL() << "PETSc options without solver.linear = petsc";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key, "solver.petsc_options");
  }
}

} // namespace
} // namespace formflow
