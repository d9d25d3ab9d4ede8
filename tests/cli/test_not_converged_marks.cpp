// SPDX-License-Identifier: MIT
// Exit 3: the results are written, and every file of them says they are not a solution.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace formflow::testing {
namespace {

TEST(NotConvergedRun, EveryResultFileSaysSo) {
  const ScratchDirectory scratch("formflow-not-converged");
  const auto out = scratch / "out";
  const CliResult result =
      run_cli("run -q --set mesh.size=2.5 --set solver.max_iterations=2 -o " + quoted(out.string()),
              scratch.path());
  ASSERT_EQ(result.exit_code, 3) << result.err;
  EXPECT_TRUE(has_text(result.err, "NOT CONVERGED (max_iterations)"));
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary.at("converged"), false);
  for (const char* csv : {"history.csv", "contact.csv"})
    EXPECT_EQ(read_text(out / csv).rfind("# not converged: max_iterations\n", 0), 0u) << csv;
  const std::string vtu = read_text(out / "fields.vtu");
  EXPECT_TRUE(has_text(vtu, "<!-- NOT CONVERGED (max_iterations)"));
  EXPECT_TRUE(has_text(vtu, "Name=\"converged\" NumberOfTuples=\"1\" format=\"ascii\">0<"));
  // The pictures' red mark is checked pixel by pixel in tests/unit/io/test_plots.cpp.
  EXPECT_TRUE(std::filesystem::exists(out / "convergence.png"));
}

TEST(NotConvergedRun, TheCouplingLimitHasItsOwnReasonAndMessage) {
  // Every flow solve converges; one staggered step cannot meet a 1e-12 coupling
  // tolerance (the temperature changes by its whole rise in the first step).
  const ScratchDirectory scratch("formflow-coupling-limit");
  const auto out = scratch / "out";
  const CliResult result = run_cli("run -q --set mesh.size=2.5 --set thermal.enabled=true --set "
                                   "thermal.max_coupling_iterations=1 "
                                   "--set thermal.coupling_tolerance=1e-12 --set thermal.density=1 "
                                   "--set thermal.heat_capacity=1 "
                                   "-o " +
                                       quoted(out.string()),
                                   scratch.path());
  ASSERT_EQ(result.exit_code, 3) << result.err;
  EXPECT_TRUE(has_text(result.err, "NOT CONVERGED (max_coupling_iterations)")) << result.err;
  EXPECT_TRUE(has_text(result.err, "thermal.max_coupling_iterations = 1")) << result.err;
  EXPECT_FALSE(has_text(result.err, "(max_iterations)")) << result.err;
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary.at("converged"), false);
  EXPECT_EQ(summary.at("stop_reason"), "max_coupling_iterations");
  EXPECT_EQ(summary.at("thermal").at("coupling").at("converged"), false);
  EXPECT_EQ(summary.at("case").at("thermal").at("enabled"), true);
  EXPECT_TRUE(std::filesystem::exists(out / "temperature.png"));
}

} // namespace
} // namespace formflow::testing
