// SPDX-License-Identifier: MIT
// The formflow binary on bad input: exit code 2, file:line, key and hint on stderr, nothing
// written.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;
using formflow::testing::CliResult;
using formflow::testing::has_text;
using formflow::testing::quoted;
using formflow::testing::read_text;

class Validation : public ::testing::Test {
protected:
  /// Runs the binary with `arguments` (already shell-quoted), capturing both streams.
  CliResult run(const std::string& arguments) const {
    return formflow::testing::run_cli(arguments, scratch_.path());
  }

  static std::string fixture(const std::string& name) {
    return (fs::path(FORMFLOW_SOURCE_DIR) / "tests" / "data" / "cases" / name).string();
  }

  /// An output directory inside the scratch area that does not exist yet.
  fs::path fresh_output() const { return scratch_ / "results"; }

  formflow::testing::ScratchDirectory scratch_{"formflow-cli"};
};

struct BadCase {
  std::string file;
  int line;
  std::string key;
  std::string hint;
};

const BadCase bad_cases[] = {
    {"unknown-key.toml", 5, "friction.mue", "did you mean `friction.mu`?"},
    {"unknown-section.toml", 5, "frction", "did you mean `[friction]`?"},
    {"wrong-type.toml", 4, "mesh.size", "expected a real number"},
    {"negative-mu.toml", 3, "friction.mu", "must be 0 ≤ value ≤ 10"},
    {"mesh-size-unfit.toml", 4, "mesh.size", "0.3125 (= 10/32)"},
    {"mesh-too-large.toml", 5, "mesh.size", "1.5e+10 cells"},
    {"bad-element.toml", 3, "mesh.element", "valid values: \"Q1\", \"Q2\""},
    {"syntax-error.toml", 4, "syntax", "radius = 0.5 0.5"},
    {"exit-above-entry.toml", 4, "geometry.exit_half_height", "< geometry.entry_half_height"},
    {"rate-order.toml", 4, "material.rate2", "> material.rate1"},
    {"law-violates-2-11.toml", 6, "material.hs_m8", "rate exponent in (0, 1]"},
    {"bad-friction-regularization.toml", 4, "friction.regularization",
     "valid values: \"regularized\", \"none\""},
    {"zero-augmentation.toml", 5, "friction.augmentation", "must be"},
    {"zero-newton-augmentation.toml", 5, "friction.newton_augmentation", "must be"},
    // Die geometry.
    {"die-angle-90.toml", 4, "geometry.die_angle", "0 < value < 90"},
    {"die-no-reduction.toml", 5, "geometry.exit_half_height", "< geometry.entry_half_height"},
    {"die-arc-too-small.toml", 4, "geometry.die_radius",
     "≥ entry_half_height − exit_half_height = 5"},
    {"die-profile-widens.toml", 4, "geometry.die_profile", "y increases at point 3"},
    {"die-profile-wrong-end.toml", 4, "geometry.die_profile", "end the profile at y = "},
    {"die-land-unfit.toml", 4, "geometry.land_length", "not a multiple of mesh.size"},
    // Solid (3D) channels: what does not run yet (io/case_validation_3d.cpp).
    {"solid-round-square-die.toml", 6, "geometry.exit_half_width",
     "the square die's exit must lie inside the round container"},
    {"solid-rectangle-unfit-width.toml", 5, "geometry.entry_half_width",
     "half widths are cut into cells of mesh.size"},
    {"solid-axisymmetric.toml", 4, "geometry.symmetry", "geometry.symmetry = \"plane\" in 3D"},
};

TEST_F(Validation, RunOnBadInputExitsTwoAndWritesNothing) {
  for (const BadCase& bad : bad_cases) {
    SCOPED_TRACE(bad.file);
    const fs::path output = fresh_output();
    const std::string path = fixture(bad.file);
    const CliResult result = run("run " + quoted(path) + " -o " + quoted(output.string()));
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_TRUE(has_text(result.err, "error: " + path + ":" + std::to_string(bad.line) + ": "));
    EXPECT_TRUE(has_text(result.err, ": " + bad.key + ": "));
    EXPECT_TRUE(has_text(result.err, bad.hint));
    EXPECT_FALSE(fs::exists(output)) << "the output directory was created";
    fs::remove_all(output);
  }
}

TEST_F(Validation, ExistingOutputDirectoryStaysEmpty) {
  const fs::path output = fresh_output();
  fs::create_directories(output);
  const CliResult result =
      run("run " + quoted(fixture("negative-mu.toml")) + " -o " + quoted(output.string()));
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_TRUE(fs::is_empty(output)) << "files were written for a bad case";
}

TEST_F(Validation, BadOverrideExitsTwoNamingSet) {
  const fs::path output = fresh_output();
  const std::string good =
      (fs::path(FORMFLOW_SOURCE_DIR) / "cases" / "paper-q2-2x2-mesh2.toml").string();
  const CliResult result =
      run("run " + quoted(good) + " -o " + quoted(output.string()) + " --set friction.muu=0.1");
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_TRUE(has_text(result.err, "error: --set: friction.muu: unknown key"));
  EXPECT_TRUE(has_text(result.err, "did you mean `friction.mu`?"));
  EXPECT_FALSE(fs::exists(output));
}

TEST_F(Validation, MissingCaseFileExitsTwo) {
  const std::string missing = (scratch_ / "no-such-case.toml").string();
  const fs::path output = fresh_output();
  const CliResult result = run("run " + quoted(missing) + " -o " + quoted(output.string()));
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_TRUE(has_text(result.err, "error: " + missing + ": case file: no such file"));
  EXPECT_FALSE(fs::exists(output));
}

TEST_F(Validation, CheckAcceptsAGoodCaseAndRejectsABadOne) {
  const std::string good =
      (fs::path(FORMFLOW_SOURCE_DIR) / "cases" / "paper-q2-1x1-mesh1.toml").string();
  const CliResult valid = run("check " + quoted(good));
  EXPECT_EQ(valid.exit_code, 0) << valid.err;
  EXPECT_TRUE(valid.err.empty()) << valid.err;
  const CliResult invalid = run("check " + quoted(fixture("bad-element.toml")));
  EXPECT_EQ(invalid.exit_code, 2);
  EXPECT_TRUE(has_text(invalid.err, fixture("bad-element.toml") + ":3: mesh.element: "));
  const CliResult overridden = run("check " + quoted(good) + " --set mesh.element=Q3");
  EXPECT_EQ(overridden.exit_code, 2);
  EXPECT_TRUE(has_text(overridden.err, "--set: mesh.element: invalid value \"Q3\""));
}

TEST_F(Validation, CaseReferenceMatchesTheDocs) {
  const CliResult result = run("case-reference");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out, read_text(fs::path(FORMFLOW_SOURCE_DIR) / "docs" / "case-reference.md"))
      << "regenerate with `build/formflow case-reference > docs/case-reference.md`";
}

} // namespace
