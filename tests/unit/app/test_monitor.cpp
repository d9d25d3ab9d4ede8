// SPDX-License-Identifier: MIT
// The monitor's estimate of the time left never exceeds what the iteration limit allows.
#include "formflow/app/monitor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace formflow::app {
namespace {

/// The "left[s]" column of each line the monitor printed for `changes`, one
/// iteration per second.
std::vector<std::string> time_left(const std::vector<Real>& changes, Real tolerance,
                                   int max_iterations) {
  std::FILE* out = std::tmpfile();
  Monitor monitor(out, tolerance, max_iterations);
  for (std::size_t k = 0; k < changes.size(); ++k) {
    solvers::IterationRecord record;
    record.iteration = static_cast<int>(k) + 1;
    record.relative_change = changes[k];
    record.seconds = 1.0;
    monitor(record);
  }
  std::rewind(out);
  std::string text;
  for (int c; (c = std::fgetc(out)) != EOF;) text += static_cast<char>(c);
  std::fclose(out);
  std::istringstream lines(text);
  std::vector<std::string> left;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string word, last;
    while (words >> word) last = word;
    left.push_back(last);
  }
  return left;
}

TEST(Monitor, TimeLeftIsBoundedByTheIterationLimit) {
  // A contraction of 0.999 per step needs ~9 200 more steps to reach 1e-4:
  // the estimate alone said 23 398 s at the last of 10 allowed iterations.
  std::vector<Real> changes;
  for (int k = 0; k < 10; ++k) changes.push_back(std::pow(0.999, k));
  const std::vector<std::string> left = time_left(changes, 1e-4, 10);
  ASSERT_EQ(left.size(), 10u);
  for (std::size_t k = 1; k < left.size(); ++k) {
    SCOPED_TRACE(k);
    ASSERT_NE(left[k], "-");
    // After iteration k + 1 of 10, at 1 s each, at most 10 − (k + 1) s remain.
    EXPECT_LE(std::stod(left[k]), 10.0 - static_cast<double>(k + 1) + 1e-9);
  }
  EXPECT_EQ(std::stod(left.back()), 0.0);
}

TEST(Monitor, FastConvergenceKeepsItsOwnEstimate) {
  // Contraction 0.1 per step from 1: 1e-4 is 2 steps away after the third line.
  const std::vector<std::string> left = time_left({1.0, 0.1, 0.01}, 1e-4, 500);
  EXPECT_NEAR(std::stod(left.back()), 2.0, 1e-9);
}

TEST(Monitor, EachStageIsHeadedByItsNameAndRestartsTheEstimate) {
  std::FILE* out = std::tmpfile();
  Monitor monitor(out, 1e-4, 50);
  const auto iterate = [&monitor](int iteration, Real change, const std::string& stage) {
    solvers::IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    record.seconds = 1.0;
    record.stage = stage;
    monitor(record);
  };
  iterate(1, 1e-1, "");
  iterate(2, 1e-2, "");
  iterate(1, 1e-1, "error estimate: the mesh refined once, 5042 dofs");
  iterate(2, 1e-2, "error estimate: the mesh refined once, 5042 dofs");
  iterate(1, 1e-1, "");
  std::rewind(out);
  std::vector<std::string> lines;
  std::string line;
  for (int c; (c = std::fgetc(out)) != EOF;) {
    if (c != '\n') {
      line += static_cast<char>(c);
      continue;
    }
    lines.push_back(line);
    line.clear();
  }
  std::fclose(out);
  ASSERT_EQ(lines.size(), 7u);
  EXPECT_EQ(lines[2], "  -- error estimate: the mesh refined once, 5042 dofs");
  EXPECT_EQ(lines[5], "  -- the run's solve");
  // The first line of a stage has no contraction to extrapolate from yet.
  EXPECT_EQ(lines[3].substr(lines[3].size() - 1), "-");
  EXPECT_EQ(lines[6].substr(lines[6].size() - 1), "-");
}

} // namespace
} // namespace formflow::app
