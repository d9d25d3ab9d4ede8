// SPDX-License-Identifier: MIT
// The key table's consistency, its generated reference docs/case-reference.md, and cases/*.toml.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_json.hpp"
#include "formflow/io/case_keys.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

namespace formflow::io {
namespace {

namespace fs = std::filesystem;

using testing::read_text;

TEST(CaseKeys, TableIsConsistent) {
  std::set<std::string_view> names, sections_with_keys;
  for (const CaseKey& key : case_keys()) {
    EXPECT_TRUE(names.insert(key.name).second) << "duplicate key " << key.name;
    EXPECT_TRUE(is_case_section(key.section())) << key.name;
    sections_with_keys.insert(key.section());
    EXPECT_FALSE(key.doc.empty()) << key.name;
    EXPECT_FALSE(key.unit.empty()) << key.name;
    EXPECT_TRUE(key.set && key.get) << key.name;
    const bool has_choices = key.type == KeyType::Enum || key.type == KeyType::StringList ||
                             key.type == KeyType::NameMap;
    EXPECT_EQ(!key.choices.empty(), has_choices) << key.name;
    EXPECT_FALSE(check_key_value(key, key.default_value)) << key.name << ": default invalid";
    EXPECT_EQ(find_case_key(key.name), &key);
  }
  EXPECT_EQ(sections_with_keys.size(), case_sections().size()) << "a section without keys";
  // Keys are grouped by section, in case_sections() order.
  std::size_t section = 0;
  for (const CaseKey& key : case_keys()) {
    while (section < case_sections().size() && case_sections()[section].name != key.section())
      ++section;
    EXPECT_LT(section, case_sections().size()) << key.name << " is out of section order";
  }
  EXPECT_EQ(find_case_key("friction.nu"), nullptr);
}

TEST(CaseKeys, ClosestKeyForCommonSlips) {
  EXPECT_EQ(closest_case_key("friction.mue"), "friction.mu");
  EXPECT_EQ(closest_case_key("penalty.dn"), "penalty.dN");
  EXPECT_EQ(closest_case_key("speed"), "process.speed");
  EXPECT_EQ(closest_case_key("friction.speed"), "process.speed");
  EXPECT_EQ(closest_case_key("solver.max_iteration"), "solver.max_iterations");
  EXPECT_EQ(closest_case_section("frction"), "friction");
  EXPECT_EQ(closest_case_section("solvers"), "solver");
}

TEST(CaseKeys, ValuesAreFormattedAsTomlLiterals) {
  EXPECT_EQ(format_key_value(10.0), "10.0");
  EXPECT_EQ(format_key_value(1e-6), "1e-06");
  EXPECT_EQ(format_key_value(1.7320508075688772), "1.7320508075688772");
  EXPECT_EQ(format_key_value(std::int64_t{500}), "500");
  EXPECT_EQ(format_key_value(std::string("Q2")), "\"Q2\"");
  EXPECT_EQ(format_key_value(std::vector<std::string>{"container", "die"}),
            "[\"container\", \"die\"]");
  EXPECT_EQ(format_key_value(std::vector<std::string>{}), "[]");
}

TEST(CaseReference, DocsFileIsUpToDate) {
  const fs::path path = fs::path(FORMFLOW_SOURCE_DIR) / "docs" / "case-reference.md";
  ASSERT_TRUE(fs::exists(path)) << path;
  EXPECT_TRUE(read_text(path) == case_reference_markdown())
      << "docs/case-reference.md is out of date with src/formflow/io/case_keys.cpp; regenerate "
         "it with `build/formflow case-reference > docs/case-reference.md`";
}

TEST(CaseReference, EveryKeyHasARowInItsSection) {
  const std::string markdown = case_reference_markdown();
  for (const CaseKey& key : case_keys()) {
    const auto section = markdown.find("## [" + std::string(key.section()) + "]");
    ASSERT_NE(section, std::string::npos) << key.name;
    const auto next = markdown.find("\n## ", section + 1);
    const auto row = markdown.find("| `" + std::string(key.leaf()) + "` | ", section);
    EXPECT_TRUE(row != std::string::npos && row < next) << key.name;
    EXPECT_NE(markdown.find(format_key_value(key.default_value), row), std::string::npos);
  }
}

TEST(CaseReference, TheDefaultCaseBlockLoadsToTheDefaults) {
  const std::string markdown = case_reference_markdown();
  const auto begin = markdown.find("```toml\n");
  ASSERT_NE(begin, std::string::npos);
  const auto end = markdown.find("```", begin + 8);
  const fs::path path =
      fs::temp_directory_path() / ("formflow-default-" + std::to_string(getpid()) + ".toml");
  std::ofstream(path) << markdown.substr(begin + 8, end - begin - 8);
  const Case case_ = load_case(path.string(), {});
  fs::remove(path);
  nlohmann::ordered_json expected = case_to_json(load_case("", {}));
  expected["source"] = path.string();
  EXPECT_EQ(case_to_json(case_), expected);
}

TEST(ExampleCases, EveryCaseFileLoadsAndSaysHowToRunIt) {
  const fs::path directory = fs::path(FORMFLOW_SOURCE_DIR) / "cases";
  int n_cases = 0;
  for (const auto& entry : fs::directory_iterator(directory)) {
    if (entry.path().extension() != ".toml") continue;
    ++n_cases;
    const std::string name = entry.path().stem().string();
    try {
      load_case(entry.path().string(), {});
    } catch (const InputError& error) {
      ADD_FAILURE() << error.what();
    }
    const std::string text = read_text(entry.path());
    EXPECT_EQ(text.rfind("#", 0), 0u) << name << ": must open with a comment block";
    EXPECT_NE(text.find("build/formflow run cases/" + name + ".toml -o results/" + name),
              std::string::npos)
        << name << ": the comment must give the exact command";
  }
  EXPECT_GE(n_cases, 8);
}

TEST(ExampleCases, NamedCasesHaveTheirSettings) {
  const fs::path directory = fs::path(FORMFLOW_SOURCE_DIR) / "cases";
  auto load = [&directory](const std::string& name) {
    return load_case((directory / (name + ".toml")).string(), {});
  };
  nlohmann::json benchmark = case_to_json(load("paper-q2-2x2-mesh2"));
  benchmark.erase("source");
  nlohmann::json defaults = case_to_json(load_case("", {}));
  defaults.erase("source");
  // The paper's case runs the paper's method; Newton is the default (issue 6).
  EXPECT_EQ(benchmark["solver"]["method"], "secant");
  defaults["solver"]["method"] = "secant";
  EXPECT_EQ(benchmark, defaults);
  const Case locking = load("paper-q1-full-mesh2");
  EXPECT_EQ(locking.element, fem::ElementKind::Q1);
  EXPECT_EQ(locking.volumetric_points, 2);
  EXPECT_EQ(load("paper-q1-1x1-mesh2").volumetric_points, 1);
  const Case mesh_one = load("paper-q2-1x1-mesh1");
  EXPECT_EQ(mesh_one.volumetric_points, 1);
  EXPECT_EQ(mesh_one.mesh.size, 10.0 / 6.0);
  EXPECT_EQ(load("paper-q2-2x2-mesh1").mesh.size, 10.0 / 6.0);
  EXPECT_EQ(load("paper-q2-2x2-mesh2-mu0.1").friction.mu, 0.1);
  EXPECT_EQ(load("paper-q2-2x2-mesh2-mu0.2").friction.mu, 0.2);
  EXPECT_EQ(load("sticking-ram-q2").process.ram, physics::RamCondition::Sticking);
}

} // namespace
} // namespace formflow::io
