// SPDX-License-Identifier: MIT
// Distributed runs (issue 20, docs/petsc.md): `mpirun -np N formflow run` with each
// rank assembling its own part of the cells (PT-Scotch) into one MPIAIJ matrix gives the serial
// CHOLMOD ram reaction, for the paper's 2D case and a 3D round quarter, penalty and
// condensed mixed, with friction, by Newton (the default method: its coarse levels,
// tangent shares and GMRES on every rank) and by the secant iteration; rank 0 alone
// writes and speaks; bad input is one message and exit 2 on every rank.
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
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace formflow {
namespace {

using testing::quoted;

/// One distributed case: the case path ("" for the paper's) and its edits.
struct DistributedCase {
  std::string name;
  std::string case_path;
  std::vector<io::Override> edits;
  Real delta; ///< solver.tolerance
  /// solver.method; empty: the default (Newton, with its coarse levels).
  std::string method = {};
  /// Leave solver.linear unset on the mpirun command line: PETSc is the default on N > 1 ranks.
  bool petsc_by_default = false;
  /// The partitioner of the cells (-mat_partitioning_type; empty: the default, PT-Scotch).
  std::string partitioner = {};
};

/// gtest's name of a parameter (its bytes otherwise).
void PrintTo(const DistributedCase& c, std::ostream* out) {
  *out << c.name;
}

std::vector<io::Override> all_edits(const DistributedCase& c) {
  std::vector<io::Override> edits = c.edits;
  if (!c.method.empty()) edits.emplace_back("solver.method", c.method);
  edits.emplace_back("solver.tolerance", fmt::format("{}", c.delta));
  return edits;
}

/// `mpirun -np ranks formflow run` of the case with PETSc; its exit code, and its
/// summary.json (null when none was written) and stderr.
struct MpiRun {
  int exit_code = -1;
  nlohmann::json summary;
  std::string out, err;
};

/// Runs a launcher's `command` with its output in the scratch directory: exit code,
/// stdout and stderr (no summary).
MpiRun run_launcher(const std::string& command, const testing::ScratchDirectory& scratch) {
  const int status = std::system((command + " > " + quoted((scratch / "out.txt").string()) +
                                  " 2> " + quoted((scratch / "err.txt").string()))
                                     .c_str());
  MpiRun run;
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  run.out = testing::read_text(scratch / "out.txt");
  run.err = testing::read_text(scratch / "err.txt");
  return run;
}

MpiRun run_mpi(const DistributedCase& c, int ranks, const testing::ScratchDirectory& scratch,
               const std::string& extra = {}, bool quiet = true) {
  // OpenMPI's ranks wait for each other by spinning unless told to yield: on a machine
  // with fewer free cores than ranks (oversubscribed, or shared) that turns every
  // message into a time slice. Yielding changes no number, only the wall time. In a
  // container without ptrace rights OpenMPI's shared-memory single copy (CMA) fails:
  // plain copies instead, as OpenMPI's own FAQ advises.
  std::string command = "OMPI_MCA_mpi_yield_when_idle=1 "
                        "OMPI_MCA_btl_vader_single_copy_mechanism=none " +
                        quoted(FORMFLOW_MPIEXEC) + " -n " + std::to_string(ranks) +
                        " --oversubscribe --allow-run-as-root " + quoted(FORMFLOW_BINARY) +
                        " run " + (quiet ? "-q " : "") + "-o " +
                        quoted((scratch / "results").string());
  if (!c.case_path.empty())
    command += " " + quoted(std::string(FORMFLOW_SOURCE_DIR) + "/" + c.case_path);
  for (const auto& [key, value] : all_edits(c)) command += " --set " + quoted(key + "=" + value);
  if (!c.petsc_by_default) command += " --set solver.linear=petsc";
  if (!c.partitioner.empty()) command += " -mat_partitioning_type " + c.partitioner;
  MpiRun run = run_launcher(command + " " + extra, scratch);
  const auto summary = scratch / "results" / "summary.json";
  if (std::filesystem::exists(summary))
    run.summary = nlohmann::json::parse(testing::read_text(summary));
  return run;
}

/// The NumberOfCells of a VTU file's piece (−1 if it has none).
long cells_of_vtu(const std::filesystem::path& file) {
  const std::string text = testing::read_text(file);
  const std::string key = "NumberOfCells=\"";
  const auto at = text.find(key);
  return at == std::string::npos ? -1 : std::stol(text.substr(at + key.size()));
}

/// How far the distributed run's reaction may be from CHOLMOD's (relative), the
/// derivation of tests/petsc/test_petsc_solver.cpp: the same iteration with two
/// backward-stable direct solvers (CHOLMOD; MUMPS on the distributed matrix, whose
/// sums over ranks only reorder the additions of the serial assembly, a relative
/// perturbation of the matrix of a few ε), each solve's forward error at most κ ε,
/// not accumulating beyond 1/(1 − ρ) ≤ 10 in a loop that contracts by ρ ≤ 0.9, and
/// each run stopping within its own δ-sized last change, bounded by the same factor.
Real direct_agreement(Real delta, Real reciprocal_condition) {
  constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
  return 10 * (delta + epsilon / reciprocal_condition);
}

class DistributedMatchesCholmod : public ::testing::TestWithParam<std::pair<DistributedCase, int>> {
};

TEST_P(DistributedMatchesCholmod, RamReactionOfTheSerialRun) {
  const auto& [c, ranks] = GetParam();
  const app::Simulation serial = app::simulate(
      io::load_case(c.case_path.empty() ? std::string()
                                        : std::string(FORMFLOW_SOURCE_DIR) + "/" + c.case_path,
                    all_edits(c)),
      {}, /*estimate_condition=*/true);
  ASSERT_TRUE(serial.results.converged());
  ASSERT_TRUE(serial.reciprocal_condition.has_value());
  testing::ScratchDirectory scratch("formflow-mpi");
  const MpiRun run = run_mpi(c, ranks, scratch);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_FALSE(run.summary.is_null()) << "rank 0 wrote no summary.json";
  const Real reaction = run.summary.at("pressure").at("ram_reaction").get<Real>();
  const Real reference = serial.results.pressure.ram_reaction;
  const Real tolerance = direct_agreement(c.delta, *serial.reciprocal_condition);
  std::cout << c.name << " np " << ranks << ": rcond " << *serial.reciprocal_condition
            << " tolerance " << tolerance << " difference "
            << std::abs(reaction - reference) / std::abs(reference) << "\n";
  EXPECT_TRUE(testing::approx(reaction, reference, tolerance));
  // The integrals each rank takes over its own cells and sums over the ranks: functionals
  // of the same velocity as the reaction, so the same agreement.
  const auto& pressure = run.summary.at("pressure");
  const auto& serial_pressure = serial.results.pressure;
  EXPECT_TRUE(testing::approx(pressure.at("power_balance").get<Real>(),
                              serial_pressure.power_balance, tolerance));
  EXPECT_TRUE(testing::approx(pressure.at("total_power").get<Real>(), serial_pressure.total_power,
                              tolerance));
  EXPECT_TRUE(testing::approx(pressure.at("mean_hydrostatic_near_ram").get<Real>(),
                              serial_pressure.mean_hydrostatic_near_ram, tolerance));
  // The contact parts' measures, each rank's faces summed: every Γ3 face once (a face
  // counted twice or missed moves them by a whole face's share, far above round-off).
  const auto& contact = run.summary.at("contact");
  EXPECT_TRUE(testing::approx(contact.at("container").at("length").get<Real>(),
                              serial.results.container_zones.length, tolerance));
  EXPECT_TRUE(testing::approx(contact.at("die").at("length").get<Real>(),
                              serial.results.die_zones.length, tolerance));
  // Exact friction by Newton: the residual's power was measured over the ranks (a sum
  // over every dof of a ghosted velocity would be NaN, which the loop cannot use: the
  // default 0 would stay) and is below δ, the loop's stop condition.
  if (contact.contains("power_residual")) {
    const Real power_residual = contact.at("power_residual").get<Real>();
    EXPECT_GT(power_residual, 0.0);
    EXPECT_LT(power_residual, c.delta);
  }
  // Hot forming: the heat solve on rank 0 at the whole velocity, its T sent to every
  // rank; the temperatures are functionals of the same velocity (their T solve is a
  // well-conditioned M-matrix-like LU, far better than the flow's), so the reaction's
  // agreement bounds them too, relative to the temperature rise.
  if (run.summary.contains("thermal")) {
    const auto& thermal = run.summary.at("thermal");
    const auto& serial_thermal = serial.results.thermal;
    ASSERT_TRUE(serial_thermal.enabled);
    EXPECT_EQ(thermal.at("coupling").at("iterations").get<int>(),
              serial_thermal.coupling_iterations);
    EXPECT_TRUE(thermal.at("coupling").at("converged").get<bool>());
    const Real rise = serial_thermal.max_temperature - serial_thermal.min_temperature;
    EXPECT_NEAR(thermal.at("max_temperature").get<Real>(), serial_thermal.max_temperature,
                tolerance * rise);
    EXPECT_NEAR(thermal.at("exit_temperature").at("mean").get<Real>(), serial_thermal.exit_mean,
                tolerance * rise);
  }
  // The load's error bar (solver.load_error "refined", or "auto"'s choice): its loads on
  // the refined or coarser levels and the doubled-regularisation problem are each within
  // `tolerance` of the serial ones relative to p, and the bar, F_s|Δ|/(1 − q) (refined)
  // or F_s|Δ| q/(1 − q) (coarser) plus |Δ_ε|, combines four of them with weights at
  // most F_s/(1 − q): within 2 · (F_s/(1 − q) + 1) · tolerance · |p|, q the serial run's
  // tail ratio.
  const auto& error_bar = run.summary.at("pressure").at("ram_reaction_error");
  if (serial.results.load_error.error) {
    ASSERT_FALSE(error_bar.is_null()) << run.summary.at("pressure");
    const Real weight = 1.25 / (1.0 - serial.results.load_error.ratio);
    EXPECT_NEAR(error_bar.get<Real>(), *serial.results.load_error.error,
                2 * (weight + 1) * tolerance * std::abs(reference));
    EXPECT_EQ(run.summary.at("pressure").at("error_estimate").at("method"),
              serial.results.load_error.method);
  } else {
    EXPECT_TRUE(error_bar.is_null()) << run.summary.at("pressure");
  }
  EXPECT_EQ(run.summary.at("linear_algebra").at("ranks"), ranks);
  // The velocity is ghosted: every dof owned by one rank, and no rank holds all of them
  // (a rank holds its own cells' dofs; its ghosts are those another rank owns).
  const auto& per_rank = run.summary.at("linear_algebra").at("dofs_per_rank");
  ASSERT_EQ(static_cast<int>(per_rank.size()), ranks);
  const long dofs = run.summary.at("mesh").at("dofs").get<long>();
  long owned = 0, ghosts = 0;
  for (const auto& rank : per_rank) {
    const long held = rank.at("owned").get<long>() + rank.at("ghosts").get<long>();
    EXPECT_GT(held, 0) << per_rank;
    EXPECT_LT(held, dofs) << "a rank holds the whole velocity: " << per_rank;
    owned += rank.at("owned").get<long>();
    ghosts += rank.at("ghosts").get<long>();
  }
  EXPECT_EQ(owned, dofs) << per_rank;
  EXPECT_GT(ghosts, 0) << "the ranks' parts share no interface: " << per_rank;
  // PETSc's graph partitioner split the cells (not the slabs it falls back to).
  EXPECT_EQ(run.summary.at("linear_algebra").at("partition"),
            c.partitioner.empty() ? "ptscotch" : c.partitioner);
  // Direct MUMPS, also when solver.linear was left unset (the default on N > 1 ranks).
  EXPECT_EQ(run.summary.at("linear_algebra").at("solver"), "petsc-preonly-cholesky");
  // The fields once as fields.vtu, and as fields.pvtu with one piece per rank.
  const auto results = scratch / "results";
  EXPECT_TRUE(std::filesystem::exists(results / "fields.vtu"));
  EXPECT_TRUE(std::filesystem::exists(results / "fields.pvtu"));
  for (int rank = 0; rank <= ranks; ++rank)
    EXPECT_EQ(std::filesystem::exists(results / ("fields_" + std::to_string(rank) + ".vtu")),
              rank < ranks)
        << rank;
  // The pieces are the ranks' parts: each holds cells, and together every cell once.
  long piece_cells = 0;
  for (int rank = 0; rank < ranks; ++rank) {
    const long cells = cells_of_vtu(results / ("fields_" + std::to_string(rank) + ".vtu"));
    EXPECT_GT(cells, 0) << "piece " << rank;
    piece_cells += cells;
  }
  EXPECT_EQ(piece_cells, cells_of_vtu(results / "fields.vtu"));
  EXPECT_EQ(run.summary.at("method"), serial.results.method);
  // -q: formflow has nothing to say, from any rank (the launcher may: not checked).
  EXPECT_EQ(run.err.find("error:"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("formflow:"), std::string::npos) << run.err;
}

const DistributedCase paper_penalty{
    "paper_penalty", "", {{"mesh.size", "2.5"}, {"friction.mu", "0.1"}}, 1e-7};
const DistributedCase paper_mixed{"paper_condensed_mixed",
                                  "",
                                  {{"mesh.size", "2.5"},
                                   {"friction.mu", "0.1"},
                                   {"formulation.type", "mixed"},
                                   {"formulation.pressure", "P1disc"}},
                                  1e-7};
const DistributedCase round_penalty{
    "round_quarter_penalty", "cases/round-rod-3d.toml", {{"mesh.size", "0.5"}}, 1e-7};
const DistributedCase round_mixed{
    "round_quarter_condensed_mixed",
    "cases/round-rod-3d.toml",
    {{"mesh.size", "0.5"}, {"formulation.type", "mixed"}, {"formulation.pressure", "P1disc"}},
    1e-7};

/// Exact Coulomb friction (the augmented Lagrangian, its multipliers updated after every
/// Newton step from the replicated velocity).
const DistributedCase paper_exact_friction{
    "paper_exact_friction",
    "",
    {{"mesh.size", "2.5"},
     {"friction.mu", "0.1"},
     {"friction.regularization", "none"},
     {"friction.stick", "augmented"}}, // the serial run's default is exact stick on nodes
    1e-7};

/// Hot forming (docs/thermal.md): the AA6063 rod, axisymmetric, Sellars–Tegart law,
/// Coulomb friction on the die, flow and heat solved in turn.
const DistributedCase hot_forming{
    "aa6063_hot_extrusion", "cases/aa6063-hot-extrusion.toml", {{"mesh.size", "10"}}, 1e-7};

/// Exact constraints by Uzawa steps (session 16): incompressibility with d = 0 (the
/// condensed P1disc pressure's multipliers, each rank stepping its own cells'), and exact
/// contact with d_N = 0 (the Γ3 points' multipliers, alike on every rank).
const DistributedCase paper_uzawa{"paper_uzawa_exact_incompressibility",
                                  "",
                                  {{"mesh.size", "2.5"},
                                   {"friction.mu", "0.1"},
                                   {"formulation.type", "mixed"},
                                   {"formulation.pressure", "P1disc"},
                                   {"penalty.d", "0"}},
                                  1e-7};
const DistributedCase paper_exact_contact{
    "paper_exact_contact",
    "",
    {{"mesh.size", "2.5"}, {"friction.mu", "0.1"}, {"penalty.dN", "0"}},
    1e-7};

/// The load's error bar on two ranks: the settle on the refined mesh, the adjoint through
/// the transposed coupling (the nonlocal friction's too), the coarser level and the
/// doubled regularisations, each distributed.
const DistributedCase paper_load_error{
    "paper_load_error",
    "",
    {{"mesh.size", "2.5"}, {"friction.mu", "0.1"}, {"solver.load_error", "refined"}},
    1e-7};

/// The paper's case as it comes (μ = 0, the default error bar) at h = 0.5. On 3 ranks
/// MUMPS' distributed Cholesky ran short of work space (INFOG(1) = -9) and the run ended
/// solver_failed with a wrong load; on 5 and 6 one rank's cells held no coupling and it
/// took a direct adjoint solve while the others waited in GMRES, for ever.
const DistributedCase paper_default{"paper_default_h05", "", {{"mesh.size", "0.5"}}, 1e-7};

/// The paper's case on 4 ranks (oversubscribed) as a user types it: no solver.linear.
DistributedCase by_default(DistributedCase c) {
  c.name += "_petsc_by_default";
  c.petsc_by_default = true;
  return c;
}

/// The cells split by another of PETSc's partitioners (`average`: consecutive cell
/// numbers): only rank 0 reads the option, and the ranks must still agree on the run.
DistributedCase by_partitioner(DistributedCase c, std::string partitioner) {
  c.name += "_" + partitioner;
  c.partitioner = std::move(partitioner);
  return c;
}

/// The paper's secant iteration (the first slice's loop).
DistributedCase by_secant(DistributedCase c) {
  c.name += "_secant";
  c.method = "secant";
  return c;
}

INSTANTIATE_TEST_SUITE_P(Cases, DistributedMatchesCholmod,
                         ::testing::Values(std::pair(paper_penalty, 2), std::pair(paper_mixed, 2),
                                           std::pair(round_penalty, 2), std::pair(round_mixed, 2),
                                           // Three ranks: odd parts, dofs ghosted on two others.
                                           std::pair(round_penalty, 3), std::pair(hot_forming, 2),
                                           std::pair(paper_uzawa, 2),
                                           std::pair(paper_exact_contact, 2),
                                           std::pair(paper_load_error, 2),
                                           std::pair(paper_exact_friction, 2),
                                           std::pair(by_default(paper_penalty), 4),
                                           std::pair(by_secant(paper_penalty), 2),
                                           std::pair(by_partitioner(round_mixed, "average"), 2),
                                           std::pair(by_default(paper_default), 3),
                                           std::pair(by_default(paper_default), 5),
                                           std::pair(by_default(paper_default), 6)),
                         [](const auto& info) {
                           return info.param.first.name + "_np" + std::to_string(info.param.second);
                         });

/// Bad input on two ranks: refused before the solve, once (rank 0's message), exit 2
/// from every rank, nothing written.
void expect_refused_once(const MpiRun& run, const std::string& message,
                         const testing::ScratchDirectory& scratch) {
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const auto first = run.err.find(message);
  ASSERT_NE(first, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(message, first + 1), std::string::npos) << "said more than once:\n"
                                                                 << run.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "results"));
}

TEST(DistributedRun, TheRunSaysOnceHowManyRanksAndHowTheCellsWereSplit) {
  testing::ScratchDirectory scratch("formflow-mpi");
  const MpiRun run = run_mpi(paper_penalty, 2, scratch, {}, /*quiet=*/false);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string line = "distributed: 2 MPI ranks, the cells split by ptscotch";
  const auto first = run.out.find(line);
  ASSERT_NE(first, std::string::npos) << run.out;
  EXPECT_EQ(run.out.find(line, first + 1), std::string::npos) << "said once, by rank 0";
}

TEST(DistributedRun, ABadValueIsOneMessageAndExitTwo) {
  testing::ScratchDirectory scratch("formflow-mpi");
  DistributedCase bad = paper_penalty;
  bad.edits.emplace_back("friction.mu", "-1");
  expect_refused_once(run_mpi(bad, 2, scratch), "friction.mu", scratch);
}

/// `mpirun` of one rank with `first` and one with `second` (each: arguments after
/// `formflow run -q -o DIR`), as two hosts that see different files would start them;
/// its exit code and stderr, within a timeout so that a hang fails the test.
MpiRun run_two_cases(const std::string& first, const std::string& second,
                     const testing::ScratchDirectory& scratch) {
  const std::string rank =
      quoted(FORMFLOW_BINARY) + " run -q -o " + quoted((scratch / "results").string()) + " ";
  return run_launcher("OMPI_MCA_mpi_yield_when_idle=1 "
                      "OMPI_MCA_btl_vader_single_copy_mechanism=none timeout 120 " +
                          quoted(FORMFLOW_MPIEXEC) + " --oversubscribe --allow-run-as-root -n 1 " +
                          rank + first + " : -n 1 " + rank + second,
                      scratch);
}

TEST(DistributedRun, RanksThatReadDifferentCasesAreRefusedBeforeTheSolve) {
  // Both cases are valid; the ranks would split different meshes and wait for each
  // other in the first collective call. Refused at once (timeout: 124), nothing written.
  testing::ScratchDirectory scratch("formflow-mpi");
  const MpiRun run =
      run_two_cases("--set mesh.size=2.5", "--set mesh.size=2.5 --set friction.mu=0.1", scratch);
  expect_refused_once(run, "1 of the 2 MPI ranks read a case that differs from rank 0's", scratch);
}

TEST(DistributedRun, AnInputErrorOfAnotherRankIsItsMessageOnceAndExitTwo) {
  // A case file missing on the second rank's host: rank 0 (which read its case) says
  // the other rank's error, once, and every rank exits 2 at once.
  testing::ScratchDirectory scratch("formflow-mpi");
  const std::string missing = (scratch / "missing.toml").string();
  const MpiRun run = run_two_cases("--set mesh.size=2.5", quoted(missing), scratch);
  expect_refused_once(run, "case file: (MPI rank 1) no such file", scratch);
  EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;
}

TEST(DistributedRun, ASerialOnlySolverIsRefusedNamingTheKey) {
  testing::ScratchDirectory scratch("formflow-mpi");
  // The later --set wins: CHOLMOD has no distributed matrix.
  expect_refused_once(run_mpi(paper_penalty, 2, scratch, "--set solver.linear=cholmod"),
                      "solver.linear: on 2 MPI ranks", scratch);
}

TEST(DistributedRun, APartitionerPetscDoesNotHaveIsOneMessageAndExitTwo) {
  testing::ScratchDirectory scratch("formflow-mpi");
  expect_refused_once(run_mpi(by_partitioner(paper_penalty, "metis"), 2, scratch),
                      "-mat_partitioning_type: Unknown partitioning type metis", scratch);
}

TEST(DistributedRun, APartitionerOptionInTheCaseIsRefusedOnEveryRankAlike) {
  // The cells are split before the case's options reach PETSc's database: no rank reads
  // it, and all refuse it (one message, exit 2), none leaving the others waiting.
  testing::ScratchDirectory scratch("formflow-mpi");
  expect_refused_once(run_mpi(paper_penalty, 2, scratch,
                              "--set 'solver.petsc_options=-mat_partitioning_type average'"),
                      "solver.petsc_options: -mat_partitioning_type was read by no PETSc object",
                      scratch);
}

TEST(DistributedRun, CaseOptionsNeedNoSolverLinearOnSeveralRanks) {
  // PETSc is the default back-end on N > 1 ranks: solver.petsc_options without
  // solver.linear is read, not refused as options of a serial back-end.
  testing::ScratchDirectory scratch("formflow-mpi");
  DistributedCase c = by_default(paper_penalty);
  c.edits.emplace_back("solver.petsc_options", "-ksp_type gmres -ksp_rtol 1e-12");
  const MpiRun run = run_mpi(c, 2, scratch);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.summary.at("linear_algebra").at("solver"), "petsc-gmres-cholesky");
}

TEST(DistributedRun, ExactStickIsRefusedNamingTheKey) {
  testing::ScratchDirectory scratch("formflow-mpi");
  expect_refused_once(run_mpi(paper_exact_friction, 2, scratch,
                              "--set contact.normals=nodes --set friction.stick=exact"),
                      "friction.stick: on 2 MPI ranks", scratch);
}

TEST(DistributedRun, TheExactLawWithoutAStickChoiceRunsTheAugmentedMultipliers) {
  // A serial Newton run of the exact law defaults to exact stick on nodal points, which
  // condenses the whole tangent: on several ranks the unset key becomes "augmented"
  // (face points), said once on stderr, and the run goes through.
  testing::ScratchDirectory scratch("formflow-mpi");
  DistributedCase unset = paper_exact_friction;
  std::erase_if(unset.edits, [](const auto& edit) { return edit.first == "friction.stick"; });
  const MpiRun run = run_mpi(unset, 2, scratch);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto& contact = run.summary.at("contact");
  EXPECT_EQ(contact.at("stick"), "augmented");
  EXPECT_EQ(contact.at("points"), "faces");
  const std::string note = "note: friction.stick = \"augmented\" on 2 ranks";
  const auto first = run.err.find(note);
  ASSERT_NE(first, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(note, first + 1), std::string::npos) << "said once, by rank 0";
}

} // namespace
} // namespace formflow
