// SPDX-License-Identifier: MIT
// Cost of refusing hostile case files (tests/unit/io/test_hostile_case_text.cpp
// checks what is refused; how fast lives here): a file of many unknown sections
// (2 000 and 8 000: linearithmic ordering makes the second about 4 times the
// first; the old per-comparison line count made it 17 times) and a 5 000-point
// die profile on one line (refused by the line-length limit before toml11 parses
// it; it once took toml11 25 s). docs/benchmarks.md, section "Case files".
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace {

using namespace formflow;
namespace fs = std::filesystem;

/// Writes `text` to a fresh file in a private directory (mkdtemp: no predictable
/// name another user could link) and removes both when done.
class CaseText {
public:
  explicit CaseText(const std::string& text) {
    std::string pattern = (fs::temp_directory_path() / "formflow-bench-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    directory_ = pattern;
    path_ = (directory_ / "case.toml").string();
    std::ofstream(path_, std::ios::binary) << text;
  }
  ~CaseText() {
    std::error_code ignored;
    fs::remove_all(directory_, ignored);
  }
  CaseText(const CaseText&) = delete;
  CaseText& operator=(const CaseText&) = delete;
  const std::string& path() const { return path_; }

private:
  fs::path directory_;
  std::string path_;
};

/// Loads a case that must be refused; the refusal is what is timed.
void refuse(const std::string& path, benchmark::State& state) {
  try {
    io::load_case(path, {});
  } catch (const InputError&) {
    return;
  }
  state.SkipWithError("the hostile case was accepted");
}

void many_unknown_sections(benchmark::State& state) {
  std::string text = "[process]\nspeed = 1\n";
  for (int k = 0; k < state.range(0); ++k) text += "[s" + std::to_string(k) + "]\n";
  const CaseText file(text);
  for (auto _ : state) refuse(file.path(), state);
}
BENCHMARK(many_unknown_sections)->Arg(2000)->Arg(8000)->Unit(benchmark::kMillisecond);

void long_die_profile_line(benchmark::State& state) {
  std::string text = "[geometry]\ndie = \"polyline\"\ndie_profile = [[0, 10]";
  for (int k = 1; k < 5000; ++k) text += ", [" + std::to_string(k) + ", 5]";
  const CaseText file(text + "]\n");
  for (auto _ : state) refuse(file.path(), state);
}
BENCHMARK(long_die_profile_line)->Unit(benchmark::kMillisecond);

} // namespace
