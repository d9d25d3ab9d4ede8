// SPDX-License-Identifier: MIT
// The binary on hostile input: unknown commands, empty paths, deep nesting, every
// numeric key at the ends of its range — exit 0, 2 or 3, never 1, never a signal.
#include "formflow/io/case_keys.hpp"
#include "support/run_cli.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;
using formflow::testing::CliResult;
using formflow::testing::has_text;
using formflow::testing::quoted;

class HostileCli : public ::testing::Test {
public:
  CliResult run(const std::string& arguments) const {
    return formflow::testing::run_cli(arguments, scratch_.path());
  }
  fs::path output() const { return scratch_ / "out"; }

  formflow::testing::ScratchDirectory scratch_{"formflow-hostile-cli"};
};

TEST_F(HostileCli, UnknownCommandIsNamed) {
  const CliResult result = run("frobnicate");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(
      has_text(result.err, "unknown command 'frobnicate'")); // was "A subcommand is required"
}

TEST_F(HostileCli, EmptyCasePathIsRefused) {
  // `check ""` validated the default case, `run ""` would have solved it.
  const CliResult check = run("check ''");
  EXPECT_EQ(check.exit_code, 2);
  EXPECT_TRUE(has_text(check.err, "an empty path names no case file"));
  const CliResult solve = run("run '' -o " + quoted(output().string()));
  EXPECT_EQ(solve.exit_code, 2);
  EXPECT_FALSE(fs::exists(output()));
}

TEST_F(HostileCli, HelpListsTheExitCodes) {
  for (const std::string command : {"--help", "run --help", "check --help"}) {
    const CliResult help = run(command);
    EXPECT_EQ(help.exit_code, 0) << command;
    EXPECT_TRUE(has_text(help.out, "Exit codes: 0 ok; 1 internal error")) << command;
    EXPECT_TRUE(has_text(help.out, "2 bad input or usage (nothing written); 3 not converged"));
  }
}

TEST_F(HostileCli, DeepNestingIsAnInputErrorNotACrash) {
  // Was SIGSEGV (no message) from a 20 KB file or a --set value.
  const fs::path path = scratch_ / "deep.toml";
  std::ofstream(path) << "[process]\nspeed = " << std::string(10000, '[') << std::string(10000, ']')
                      << "\n";
  const CliResult file = run("run " + quoted(path.string()) + " -o " + quoted(output().string()));
  EXPECT_EQ(file.exit_code, 2) << file.err;
  EXPECT_TRUE(has_text(file.err, "error: " + path.string() + ":2: syntax: line longer"));
  const CliResult set = run("run --set 'process.speed=" + std::string(500, '[') +
                            std::string(500, ']') + "' -o " + quoted(output().string()));
  EXPECT_EQ(set.exit_code, 2) << set.err;
  EXPECT_TRUE(has_text(set.err, "error: --set: process.speed: nesting deeper than 32 levels"));
  EXPECT_FALSE(fs::exists(output()));
}

TEST_F(HostileCli, CompleteRuleWithQ1IsWarnedAbout) {
  const CliResult warned =
      run("check " + quoted(FORMFLOW_SOURCE_DIR "/cases/paper-q1-full-mesh2.toml"));
  EXPECT_EQ(warned.exit_code, 0) << warned.err;
  EXPECT_TRUE(has_text(warned.err, "warning: "));
  EXPECT_TRUE(has_text(warned.err, "integration.volumetric = 2 with mesh.element = \"Q1\""));
  const CliResult quiet =
      run("check " + quoted(FORMFLOW_SOURCE_DIR "/cases/paper-q1-1x1-mesh2.toml"));
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.err, "");
}

TEST_F(HostileCli, ResolvedCaseRecordsTheReducedRuleOfQ1) {
  const CliResult result =
      run("run -q --set mesh.element=Q1 --set mesh.size=2.5 -o " + quoted(output().string()));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary =
      nlohmann::json::parse(formflow::testing::read_text(output() / "summary.json"));
  EXPECT_EQ(summary.at("case").at("integration").at("volumetric"), 1);
}

/// A value just inside the bound: the bound itself when inclusive.
double inside(const formflow::io::Bound& bound, double towards) {
  return bound.inclusive ? *bound.value : std::nextafter(*bound.value, towards);
}

/// Every real or integer key at one end of its range, on a coarse mesh with few
/// iterations (the point is how each value ends, not the answer): exit 0, 2 or 3, and
/// exit 2 writes nothing. Returns the number of runs.
int run_every_numeric_key_at_one_end(const HostileCli& fixture, bool upper) {
  const std::string base = "run -q --set mesh.size=2.5 --set solver.max_iterations=30 ";
  int n_runs = 0;
  for (const formflow::io::CaseKey& key : formflow::io::case_keys()) {
    if (key.type != formflow::io::KeyType::Real && key.type != formflow::io::KeyType::Integer)
      continue;
    const std::string name(key.name);
    // Limits on work, not on scale, only make a run long at their upper ends;
    // so do long lengths, whose cell count the memory check bounds (a 10⁶-long
    // container on this mesh is 1.6 M cells that fit in memory: a valid, slow run).
    if (upper && (name == "solver.max_iterations" || name == "formulation.uzawa_max_steps" ||
                  key.unit == "length"))
      continue;
    const double value = upper ? inside(key.upper, -INFINITY) : inside(key.lower, INFINITY);
    const std::string text = key.type == formflow::io::KeyType::Integer
                                 ? fmt::format("{}", static_cast<long long>(value))
                                 : fmt::format("{:.17g}", value);
    SCOPED_TRACE(name + "=" + text);
    const CliResult result = fixture.run(base + "--set " + quoted(name + "=" + text) + " -o " +
                                         quoted(fixture.output().string()));
    ++n_runs;
    EXPECT_TRUE(result.exit_code == 0 || result.exit_code == 2 || result.exit_code == 3)
        << "exit " << result.exit_code << ": " << result.err;
    if (result.exit_code == 2) {
      EXPECT_TRUE(has_text(result.err, "error: "));
      EXPECT_FALSE(fs::exists(fixture.output())) << "exit 2 wrote results";
    }
    fs::remove_all(fixture.output());
  }
  return n_runs;
}

// Two suites, so that ctest runs the two ends side by side (about 50 runs each).
using HostileCliLowerEnds = HostileCli;
using HostileCliUpperEnds = HostileCli;

TEST_F(HostileCliLowerEnds, EveryNumericKeyAtItsLowerEndNeverFailsInternally) {
  EXPECT_GT(run_every_numeric_key_at_one_end(*this, /*upper=*/false), 40);
}

TEST_F(HostileCliUpperEnds, EveryNumericKeyAtItsUpperEndNeverFailsInternally) {
  EXPECT_GT(run_every_numeric_key_at_one_end(*this, /*upper=*/true), 30);
}

} // namespace
