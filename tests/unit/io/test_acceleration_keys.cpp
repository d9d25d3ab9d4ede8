// SPDX-License-Identifier: MIT
// solver.acceleration and solver.acceleration_depth: accepted with the secant loop,
// refused (key, file, line, hint) where nothing would read them.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace formflow::io {
namespace {

namespace fs = std::filesystem;

InputError acceleration_refusal(const std::string& path, const std::vector<Override>& overrides) {
  try {
    load_case(path, overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "load_case did not throw InputError";
  return InputError("", -1, "", "");
}

bool acceleration_text_has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(AccelerationKeys, DefaultIsNoAccelerationWithDepthFive) {
  const Case case_ = load_case("", {});
  EXPECT_EQ(case_.solver.acceleration, solvers::NonlinearAcceleration::None);
  EXPECT_EQ(case_.solver.acceleration_depth, 5);
}

TEST(AccelerationKeys, AndersonWithTheSecantLoopIsAcceptedAndWrittenToTheResolvedCase) {
  const Case case_ = load_case("", {{"solver.method", "secant"},
                                    {"solver.acceleration", "anderson"},
                                    {"solver.acceleration_depth", "8"}});
  EXPECT_EQ(case_.solver.acceleration, solvers::NonlinearAcceleration::Anderson);
  EXPECT_EQ(case_.solver.acceleration_depth, 8);
  const nlohmann::json json = case_to_json(case_);
  EXPECT_EQ(json["solver"]["acceleration"], "anderson");
  EXPECT_EQ(json["solver"]["acceleration_depth"], 8);
}

TEST(AccelerationKeys, AndersonWithNewtonIsRefused) {
  const InputError error = acceleration_refusal("", {{"solver.acceleration", "anderson"}});
  EXPECT_EQ(error.key, "solver.acceleration");
  EXPECT_EQ(error.file, "--set");
  EXPECT_TRUE(acceleration_text_has(error.hint, "solver.method = \"secant\"")) << error.hint;
}

TEST(AccelerationKeys, ADepthWithoutAccelerationIsRefused) {
  const InputError error =
      acceleration_refusal("", {{"solver.method", "secant"}, {"solver.acceleration_depth", "3"}});
  EXPECT_EQ(error.key, "solver.acceleration_depth");
  EXPECT_TRUE(acceleration_text_has(error.hint, "solver.acceleration = \"anderson\""))
      << error.hint;
}

TEST(AccelerationKeys, BadValuesAreRefusedWithWhatIsValid) {
  const InputError name =
      acceleration_refusal("", {{"solver.method", "secant"}, {"solver.acceleration", "andersen"}});
  EXPECT_EQ(name.key, "solver.acceleration");
  EXPECT_TRUE(acceleration_text_has(name.what(), "\"anderson\"")) << name.what();
  for (const char* depth : {"0", "11", "2.5"}) {
    const InputError range = acceleration_refusal("", {{"solver.method", "secant"},
                                                       {"solver.acceleration", "anderson"},
                                                       {"solver.acceleration_depth", depth}});
    EXPECT_EQ(range.key, "solver.acceleration_depth") << depth;
  }
}

TEST(AccelerationKeys, RefusalInAFileNamesItsLine) {
  const fs::path path =
      fs::temp_directory_path() / ("formflow-acceleration-" + std::to_string(getpid()) + ".toml");
  std::ofstream(path) << "[solver]\nmethod = \"newton\"\n\nacceleration = \"anderson\"\n";
  const InputError error = acceleration_refusal(path.string(), {});
  fs::remove(path);
  EXPECT_EQ(error.key, "solver.acceleration");
  EXPECT_EQ(error.file, path.string());
  EXPECT_EQ(error.line, 4);
}

} // namespace
} // namespace formflow::io
