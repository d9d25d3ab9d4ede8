// SPDX-License-Identifier: MIT
// Each pair of outer loops the stage table refuses (solvers/stage_table.hpp): exit 2,
// the key to change and the stage's switch on stderr, nothing written (issue 43).
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using formflow::testing::has_text;
using formflow::testing::quoted;

struct RefusedPair {
  std::string name;
  std::vector<std::string> sets; ///< --set assignments, the outer stage's switch first
  std::string key;               ///< the key the error blames
  std::string stage_key;         ///< the outer stage's switch, named in the hint
  std::string words;             ///< the table's words
};

std::string arguments_of(const RefusedPair& pair, const fs::path& output) {
  std::string arguments = "run -o " + quoted(output.string());
  for (const std::string& assignment : pair.sets) arguments += " --set " + quoted(assignment);
  return arguments;
}

TEST(StageRefusals, EachRefusedPairExitsTwoNamingTheKeys) {
  const std::vector<RefusedPair> pairs = {
      {"adapt + manufactured",
       {"adapt.target_error=0.01", "verification.solution=\"smooth\"", "mesh.size=0.25"},
       "verification.solution",
       "adapt.target_error",
       "manufactured solution does not have"},
      {"adapt + exact friction",
       {"adapt.target_error=0.01", "friction.mu=0.1", "friction.regularization=\"none\""},
       "friction.regularization",
       "adapt.target_error",
       "exact friction has no error estimate to drive adaptivity"},
      {"adapt + exact contact",
       {"adapt.target_error=0.01", "penalty.dN=0"},
       "penalty.dN",
       "adapt.target_error",
       "exact constraints (d = 0 or dN = 0)"},
      {"adapt + secant",
       {"adapt.target_error=0.01", "solver.method=\"secant\""},
       "solver.method",
       "adapt.target_error",
       "the secant iteration has no such start"},
      {"thermal + linearised estimate",
       {"thermal.enabled=true", "thermal.max_temperature=1000", "solver.load_error=\"linearized\""},
       "solver.load_error",
       "thermal.enabled",
       "hot forming has no linearised load error estimate"},
  };
  const formflow::testing::ScratchDirectory scratch("formflow-stages");
  for (const RefusedPair& pair : pairs) {
    SCOPED_TRACE(pair.name);
    const fs::path output = scratch / "results";
    const formflow::testing::CliResult result =
        formflow::testing::run_cli(arguments_of(pair, output), scratch.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    // "--set: key = value: message" names the blamed key where it was given.
    EXPECT_TRUE(has_text(result.err, "--set"));
    EXPECT_TRUE(has_text(result.err, pair.key));
    EXPECT_TRUE(has_text(result.err, pair.words));
    EXPECT_TRUE(has_text(result.err, pair.stage_key)) << "the hint names the stage's switch";
    EXPECT_FALSE(fs::exists(output)) << "nothing written on bad input";
  }
}

} // namespace
