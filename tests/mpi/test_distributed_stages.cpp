// SPDX-License-Identifier: MIT
// The distributed run composed with the adaptive stage (issue 43): `mpirun -np 2 formflow
// run` of an adaptive case, isothermal or hot, runs the serial run's cycles, on the same
// meshes, to the serial loads. (With the thermal coupling, the estimate and the coarse start it is
// tests/mpi/test_distributed_run.cpp's hot_forming, paper_load_error and default cases.)
#include "formflow/app/simulation.hpp"
#include "formflow/io/case.hpp"
#include "support/approx.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace formflow {
namespace {

using testing::quoted;

/// The sticking ram on Q1 at h = 1/2 with two cycles and an unreachable target (both
/// cycles run; the second on a Gmsh mesh refined where the first one's indicators were
/// largest), the estimate the cycles use.
const std::vector<io::Override> adaptive_edits = {{"process.ram", "\"sticking\""},
                                                  {"mesh.element", "\"Q1\""},
                                                  {"mesh.size", "0.5"},
                                                  {"adapt.target_error", "1e-9"},
                                                  {"adapt.max_cycles", "2"},
                                                  {"solver.load_error", "\"refined\""}};

/// summary.json of `mpirun -n ranks formflow run` with `edits` (null if none was written).
nlohmann::json summary_on_ranks(const std::vector<io::Override>& edits, int ranks,
                                const testing::ScratchDirectory& scratch, int& exit_code,
                                std::string& err) {
  // As tests/mpi/test_distributed_run.cpp: ranks that yield, plain shared-memory copies.
  std::string command = "OMPI_MCA_mpi_yield_when_idle=1 "
                        "OMPI_MCA_btl_vader_single_copy_mechanism=none " +
                        quoted(FORMFLOW_MPIEXEC) + " -n " + std::to_string(ranks) +
                        " --oversubscribe --allow-run-as-root " + quoted(FORMFLOW_BINARY) +
                        " run -q -o " + quoted((scratch / "results").string());
  for (const auto& [key, value] : edits) command += " --set " + quoted(key + "=" + value);
  command += " > /dev/null 2> " + quoted((scratch / "err.txt").string());
  const int status = std::system(command.c_str());
  exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  err = testing::read_text(scratch / "err.txt");
  const auto summary = scratch / "results" / "summary.json";
  return std::filesystem::exists(summary) ? nlohmann::json::parse(testing::read_text(summary))
                                          : nlohmann::json();
}

/// `mpirun -np 2` of the adaptive case with `edits` runs the serial run's cycles.
void expect_the_serial_cycles(const std::vector<io::Override>& edits) {
  const io::Case case_ = io::load_case("", edits);
  const app::Simulation serial = app::simulate(case_);
  ASSERT_TRUE(serial.results.converged());
  const post::AdaptRecord& record = serial.results.adapt;
  ASSERT_EQ(record.cycles.size(), 2u);
  // The agreement of tests/mpi/test_distributed_run.cpp (direct_agreement): two
  // backward-stable direct solvers, each run stopping within its δ-sized last change,
  // bounded by 1/(1 − ρ) ≤ 10; κ from CHOLMOD's rcond on the last cycle's mesh, the
  // finest, whose κ is the largest of the cycles'.
  io::Case plain = case_;
  plain.adapt.target_error = 0;
  const app::Simulation last_mesh = app::simulate_on<2>(plain, serial.plane_mesh(), {}, true);
  ASSERT_TRUE(last_mesh.reciprocal_condition.has_value());
  const Real tolerance = 10 * (case_.solver.tolerance + std::numeric_limits<Real>::epsilon() /
                                                            *last_mesh.reciprocal_condition);
  testing::ScratchDirectory scratch("formflow-mpi-stages");
  int exit_code = -1;
  std::string err;
  std::vector<io::Override> distributed = edits;
  distributed.emplace_back("solver.linear", "\"petsc\""); // the serial run: CHOLMOD
  const nlohmann::json summary = summary_on_ranks(distributed, 2, scratch, exit_code, err);
  ASSERT_EQ(exit_code, 0) << err;
  ASSERT_FALSE(summary.is_null()) << "rank 0 wrote no summary.json";
  const auto& cycles = summary.at("adapt").at("cycles");
  ASSERT_EQ(cycles.size(), record.cycles.size());
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    SCOPED_TRACE("cycle " + std::to_string(k));
    // The same marking, so the same Gmsh mesh: a cell marked differently changes the dofs.
    EXPECT_EQ(cycles[k].at("dofs").get<Index>(), record.cycles[k].dofs);
    EXPECT_TRUE(
        testing::approx(cycles[k].at("load").get<Real>(), record.cycles[k].load, tolerance));
  }
  EXPECT_EQ(summary.at("adapt").at("stop").get<std::string>(), record.stop);
}

TEST(DistributedStages, AdaptiveCyclesOfTheSerialRun) {
  expect_the_serial_cycles(adaptive_edits);
}

TEST(DistributedStages, HotAdaptiveCyclesOfTheSerialRun) {
  // The adiabatic-tools fixture of tests/verification/test_thermal_balance.cpp: every
  // cycle a hot run, every level of its estimate too (the heat solve on rank 0).
  std::vector<io::Override> hot = adaptive_edits;
  hot.insert(hot.end(), {{"thermal.enabled", "true"},
                         {"thermal.billet_temperature", "0"},
                         {"thermal.tool_temperature", "0"},
                         {"thermal.max_temperature", "1000"},
                         {"thermal.conductivity", "1e-3"},
                         {"thermal.heat_transfer", "0"},
                         {"thermal.max_coupling_iterations", "100"}});
  expect_the_serial_cycles(hot);
}

} // namespace
} // namespace formflow
