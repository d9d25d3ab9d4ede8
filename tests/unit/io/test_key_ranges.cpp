// SPDX-License-Identifier: MIT
// Every numeric key has a finite range with a reason; values that made the solve fail
// with "internal error" are refused at load time; errors blame a key the user set;
// integration.volumetric defaults to the element's reduced rule.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_keys.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace formflow::io {
namespace {

using testing::has_text;

InputError error_of(const std::vector<Override>& overrides, const std::string& path = "") {
  try {
    load_case(path, overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", -1, "", "");
}

TEST(KeyRanges, EveryNumericKeyIsBoundedOnBothSidesWithAReason) {
  for (const CaseKey& key : case_keys()) {
    if (key.type != KeyType::Real && key.type != KeyType::Integer) continue;
    SCOPED_TRACE(std::string(key.name));
    ASSERT_TRUE(key.lower.value.has_value());
    ASSERT_TRUE(key.upper.value.has_value());
    EXPECT_TRUE(std::isfinite(*key.lower.value) && std::isfinite(*key.upper.value));
    // The reason is in the reference, next to the range (integers and angles have
    // natural bounds that need no reason).
    if (key.type == KeyType::Real && *key.upper.value - *key.lower.value > 1000) {
      EXPECT_TRUE(has_text(valid_values_text(key), "(why: "));
    }
  }
}

TEST(KeyRanges, ValuesThatBrokeTheSolveAreRefusedAtLoad) {
  // Each of these passed `check` and ended the run in "internal error" (exit 1).
  const std::vector<Override> broken = {{"process.speed", "1e308"},
                                        {"process.speed", "1e-300"},
                                        {"friction.mu", "1e300"},
                                        {"penalty.d", "1e-308"},
                                        {"geometry.die_radius", "1e30"}};
  for (const Override& value : broken) {
    SCOPED_TRACE(value.first + " = " + value.second);
    std::vector<Override> overrides = {value};
    if (value.first == "geometry.die_radius")
      overrides.insert(overrides.begin(), {"geometry.die", "arc"});
    const InputError error = error_of(overrides);
    EXPECT_EQ(error.key, value.first);
    EXPECT_EQ(error.file, "--set");
    EXPECT_TRUE(has_text(error.message, "out of range"));
    EXPECT_TRUE(has_text(error.hint, "(why: "));
  }
  // 0 stays the exact constraint of penalty.d and penalty.dN.
  EXPECT_NO_THROW(load_case("", {{"penalty.d", "0"}, {"formulation.type", "mixed"}}));
  EXPECT_NO_THROW(load_case("", {{"penalty.dN", "0"}}));
}

TEST(KeyRanges, ALawWhoseStressIsNotFiniteIsRefused) {
  // Each parameter in range, but e^(m1 T) = e^(10 · 10⁴) overflows.
  const InputError error = error_of({{"material.law", "hensel_spittel"},
                                     {"material.hs_m1", "10"},
                                     {"material.temperature", "10000"}});
  EXPECT_EQ(error.key, "material.temperature");
  EXPECT_TRUE(has_text(error.message, "not finite and positive")) << error.what();
}

TEST(KeyRanges, CrossKeyErrorsBlameAKeyTheUserSet) {
  // die_radius keeps its default 10; the entry height set later makes it too small.
  // Before: "<default>: geometry.die_radius".
  const InputError radius =
      error_of({{"geometry.die", "arc"}, {"geometry.entry_half_height", "30"}});
  EXPECT_EQ(radius.file, "--set");
  EXPECT_EQ(radius.key, "geometry.entry_half_height");
  EXPECT_TRUE(has_text(radius.message, "with geometry.die_radius = 10.0 (its default)"));
  // A polyline die without a profile blames the die shape, not the empty default profile.
  const InputError profile = error_of({{"geometry.die", "polyline"}});
  EXPECT_EQ(profile.key, "geometry.die");
  EXPECT_TRUE(has_text(profile.message, "at least two points"));
  // A mesh too large for memory because of a length, mesh.size at its default.
  const InputError memory = error_of({{"geometry.container_length", "1000000"}});
  EXPECT_EQ(memory.key, "geometry.container_length");
  EXPECT_EQ(memory.file, "--set");
}

TEST(VolumetricRule, DefaultsToTheElementsReducedRule) {
  // Q1 with the complete 2×2 rule locks (7.87 instead of 3.05): unset, it gets 1×1.
  EXPECT_EQ(load_case("", {{"mesh.element", "Q1"}}).volumetric_points, 1);
  EXPECT_TRUE(load_case("", {{"mesh.element", "Q1"}}).warnings.empty());
  EXPECT_EQ(load_case("", {}).volumetric_points, 2); // Q2: 2×2 is already reduced
  EXPECT_TRUE(load_case("", {}).warnings.empty());
  // Asked for explicitly, the rule is kept, with a warning naming where it was set.
  const Case locking = load_case("", {{"mesh.element", "Q1"}, {"integration.volumetric", "2"}});
  EXPECT_EQ(locking.volumetric_points, 2);
  ASSERT_EQ(locking.warnings.size(), 1u);
  EXPECT_TRUE(has_text(locking.warnings.front(), "--set: integration.volumetric = 2"));
  EXPECT_TRUE(has_text(locking.warnings.front(), "locks"));
  EXPECT_TRUE(
      load_case("", {{"mesh.element", "Q1"}, {"integration.volumetric", "1"}}).warnings.empty());
}

} // namespace
} // namespace formflow::io
