// SPDX-License-Identifier: MIT
// The discontinuous pressure kept as a saddle point on several ranks (issue 20,
// docs/petsc.md "Distributed runs"): `mpirun -np N formflow run` of the mixed Q2–P1disc
// problem with FGMRES + fieldsplit Schur (BoomerAMG on the velocity, the cell blocks of
// the viscosity-scaled pressure mass on the Schur complement), each rank its own cells'
// share of [A Bᵀ; B −dM], gives the serial PETSc saddle-point run's ram reaction, for the
// paper's 2D case and the 3D round quarter (conical die: the contact frames), both with
// friction; Taylor–Hood is still refused on several ranks.
#include "formflow/app/simulation.hpp"
#include "formflow/io/case.hpp"
#include "support/approx.hpp"
#include "support/run_cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace formflow {
namespace {

/// FGMRES's relative residual in both runs, and every secant step solved to it
/// (`-formflow_inexact_steps 0`): a loose step's iterate depends on the preconditioner's
/// path (systems BoomerAMG serially, scalar BoomerAMG over two ranks), an exact one only
/// on the system, so both runs take the same iterates within the solves' errors.
constexpr Real saddle_krylov_tolerance = 1e-12;
constexpr Real saddle_delta = 1e-7; // solver.tolerance

/// One saddle-point case: the case path ("" for the paper's) and its edits.
struct DistributedSaddleCase {
  std::string name;
  std::string case_path;
  std::vector<io::Override> edits;
  /// More of solver.petsc_options (both runs).
  std::string petsc_options = {};
};

void PrintTo(const DistributedSaddleCase& c, std::ostream* out) {
  *out << c.name;
}

std::vector<io::Override> saddle_edits(const DistributedSaddleCase& c) {
  std::vector<io::Override> edits = {
      {"formulation.type", "mixed"},
      {"formulation.pressure", "P1disc"},
      {"formulation.discontinuous_pressure", "saddle_point"},
      {"solver.linear", "petsc"},
      {"solver.method", "secant"},
      {"solver.tolerance", fmt::format("{}", saddle_delta)},
      {"solver.petsc_options", fmt::format("-ksp_rtol {} -formflow_inexact_steps 0 {}",
                                           saddle_krylov_tolerance, c.petsc_options)}};
  edits.insert(edits.end(), c.edits.begin(), c.edits.end());
  return edits;
}

std::string saddle_case_path(const DistributedSaddleCase& c) {
  return c.case_path.empty() ? std::string() : std::string(FORMFLOW_SOURCE_DIR) + "/" + c.case_path;
}

struct SaddleMpiRun {
  int exit_code = -1;
  nlohmann::json summary;
  std::string err;
};

/// `mpirun -np ranks formflow run` of the case (tests/mpi/test_distributed_run.cpp says
/// why the OpenMPI settings), or with `ranks` 0 `formflow run` alone, a serial PETSc run.
/// A process of its own also for the serial run: PETSc started MPI in this process would
/// be inherited by the later mpirun's environment, which then fails.
SaddleMpiRun run_saddle_mpi(const DistributedSaddleCase& c, int ranks,
                            const testing::ScratchDirectory& scratch,
                            const std::vector<io::Override>& more = {},
                            const std::string& command_line_options = {}) {
  std::string command = "OMPI_MCA_mpi_yield_when_idle=1 "
                        "OMPI_MCA_btl_vader_single_copy_mechanism=none ";
  if (ranks > 0)
    command += testing::quoted(FORMFLOW_MPIEXEC) + " -n " + std::to_string(ranks) +
               " --oversubscribe --allow-run-as-root ";
  command += testing::quoted(FORMFLOW_BINARY) + " run -q -o " +
             testing::quoted((scratch / "results").string());
  if (!c.case_path.empty()) command += " " + testing::quoted(saddle_case_path(c));
  std::vector<io::Override> edits = saddle_edits(c);
  edits.insert(edits.end(), more.begin(), more.end());
  for (const auto& [key, value] : edits) command += " --set " + testing::quoted(key + "=" + value);
  command += " " + command_line_options + " > " + testing::quoted((scratch / "out.txt").string()) +
             " 2> " + testing::quoted((scratch / "err.txt").string());
  const int status = std::system(command.c_str());
  SaddleMpiRun run;
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  run.err = testing::read_text(scratch / "err.txt");
  const auto summary = scratch / "results" / "summary.json";
  if (std::filesystem::exists(summary))
    run.summary = nlohmann::json::parse(testing::read_text(summary));
  return run;
}

class DistributedSaddlePointMatchesSerial
    : public ::testing::TestWithParam<std::pair<DistributedSaddleCase, int>> {};

/// Both runs solve the same secant iteration's systems by FGMRES to the relative residual
/// rtol: a step's solution errs by at most rtol/r_s relative (r_s the reciprocal condition
/// of the serial run's last system, as tests/petsc/test_petsc_discontinuous_saddle_point.cpp
/// estimates it: an in-process UMFPACK run, which starts no MPI), amplified by at most 1/(1 − ρ) =
/// 10 by a loop that contracts by ρ ≤ 0.9, and each run stops within ρ/(1 − ρ) δ ≤ 10 δ of the
/// fixed point: the two reactions within 2 · 10 (δ + rtol/r_s). The ranks' sums only reorder the
/// serial assembly's additions (round-off far below rtol/r_s).
TEST_P(DistributedSaddlePointMatchesSerial, RamReactionOfTheSerialSaddlePointRun) {
  const auto& [c, ranks] = GetParam();
  // The condition estimate only needs its order of magnitude: a looser δ (1e-4) moves the
  // velocity it is taken at, not its order.
  std::vector<io::Override> umfpack = saddle_edits(c);
  umfpack.emplace_back("solver.linear", "umfpack");
  umfpack.emplace_back("solver.petsc_options", "");
  umfpack.emplace_back("solver.tolerance", "1e-4");
  const app::Simulation estimate = app::simulate(io::load_case(saddle_case_path(c), umfpack), {},
                                                 /*estimate_condition=*/true);
  ASSERT_TRUE(estimate.reciprocal_condition.has_value());
  const Real reciprocal_condition = *estimate.reciprocal_condition;
  testing::ScratchDirectory serial_scratch("formflow-mpi-saddle-serial");
  const SaddleMpiRun serial = run_saddle_mpi(c, 0, serial_scratch);
  ASSERT_EQ(serial.exit_code, 0) << serial.err;
  testing::ScratchDirectory scratch("formflow-mpi-saddle");
  const SaddleMpiRun run = run_saddle_mpi(c, ranks, scratch);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_FALSE(run.summary.is_null()) << "rank 0 wrote no summary.json";
  const Real reaction = run.summary.at("pressure").at("ram_reaction").get<Real>();
  const Real reference = serial.summary.at("pressure").at("ram_reaction").get<Real>();
  const Real tolerance = 2 * 10 * (saddle_delta + saddle_krylov_tolerance / reciprocal_condition);
  const auto& algebra = run.summary.at("linear_algebra");
  std::cout << c.name << " np " << ranks << ": rcond " << reciprocal_condition << " tolerance "
            << tolerance << " difference " << std::abs(reaction - reference) / std::abs(reference)
            << "; secant steps " << serial.summary.at("iterations") << " serial, "
            << run.summary.at("iterations") << " distributed; Krylov "
            << serial.summary.at("linear_algebra").at("iterations") << " serial, "
            << algebra.at("iterations") << " distributed\n";
  EXPECT_TRUE(testing::approx(reaction, reference, tolerance));
  EXPECT_EQ(algebra.at("ranks"), ranks);
  // The iterative block preconditioner, not a direct solve.
  EXPECT_EQ(algebra.at("solver"), "petsc-fgmres-fieldsplit");
  EXPECT_GT(algebra.at("iterations").get<long>(), run.summary.at("iterations").get<long>());
  EXPECT_EQ(run.summary.at("method"), serial.summary.at("method"));
  EXPECT_EQ(run.err.find("error:"), std::string::npos) << run.err;
}

/// The paper's case (h = 2.5, μ = 0.1: the regularised Coulomb friction).
const DistributedSaddleCase paper_saddle{
    "paper_saddle_point", "", {{"mesh.size", "2.5"}, {"friction.mu", "0.1"}}};
/// The 3D round quarter (h = 0.5, μ = 0.05 on the conical die: its Γ3 nodes solved in their
/// normal–tangent frames, each rank rotating its share).
const DistributedSaddleCase round_saddle{
    "round_quarter_saddle_point", "cases/round-rod-3d.toml", {{"mesh.size", "0.5"}}};

/// The same as one MPIAIJ matrix of the whole saddle point (each rank's whole share
/// matrix), as a direct solver would need it, instead of the default four-block MATNEST
/// (petsc::DistributedSaddleNest).
const DistributedSaddleCase round_saddle_one_matrix{"round_quarter_saddle_point_one_matrix",
                                                    "cases/round-rod-3d.toml",
                                                    {{"mesh.size", "0.5"}},
                                                    "-formflow_saddle_point_nest 0"};

/// Exact contact (d_N = 0): Uzawa steps of the Γ3 multipliers around each saddle-point
/// solve, their weights summed over the ranks (session 16).
const DistributedSaddleCase paper_saddle_exact_contact{
    "paper_saddle_point_exact_contact",
    "",
    {{"mesh.size", "2.5"}, {"friction.mu", "0.1"}, {"penalty.dN", "0"}}};

INSTANTIATE_TEST_SUITE_P(Cases, DistributedSaddlePointMatchesSerial,
                         ::testing::Values(std::pair(paper_saddle, 2), std::pair(round_saddle, 2),
                                           std::pair(paper_saddle_exact_contact, 2),
                                           std::pair(paper_saddle, 4),
                                           std::pair(round_saddle_one_matrix, 2)),
                         [](const auto& info) {
                           return info.param.first.name + "_np" + std::to_string(info.param.second);
                         });

TEST(DistributedSaddlePoint, TaylorHoodIsRefusedNamingTheKey) {
  testing::ScratchDirectory scratch("formflow-mpi-saddle");
  const SaddleMpiRun run = run_saddle_mpi(
      paper_saddle, 2, scratch,
      {{"formulation.pressure", "Q1"}, {"formulation.discontinuous_pressure", "condensed"}});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const std::string message = "formulation.pressure: on 2 MPI ranks";
  const auto first = run.err.find(message);
  ASSERT_NE(first, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(message, first + 1), std::string::npos) << "said once";
  EXPECT_FALSE(std::filesystem::exists(scratch / "results"));
}

/// A saddle-point option on the command line reaches the fine solve, not the coarse levels
/// (condensed Newton on distributed MUMPS, whose solver reads only -coarse_* options), and
/// a misspelt one is still refused (by the fine solve's check for unread options).
TEST(DistributedSaddlePoint, CommandLineOptionsAreTheFineSolvesNotTheCoarseLevels) {
  testing::ScratchDirectory scratch("formflow-mpi-saddle");
  const SaddleMpiRun run = run_saddle_mpi(paper_saddle, 2, scratch, {{"solver.tolerance", "1e-4"}},
                                          "-fieldsplit_u_pc_hypre_boomeramg_strong_threshold 0.5");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_GT(run.summary.at("coarse_iterations").size(), 0U) << "the coarse levels ran";
  testing::ScratchDirectory misspelt_scratch("formflow-mpi-saddle");
  const SaddleMpiRun misspelt =
      run_saddle_mpi(paper_saddle, 2, misspelt_scratch, {{"solver.tolerance", "1e-4"}},
                     "-fieldsplit_u_pc_hypre_boomeramg_strong_threshol 0.5");
  EXPECT_EQ(misspelt.exit_code, 2) << misspelt.err;
  EXPECT_NE(misspelt.err.find("-fieldsplit_u_pc_hypre_boomeramg_strong_threshol was read by no"),
            std::string::npos)
      << misspelt.err;
}

} // namespace
} // namespace formflow
