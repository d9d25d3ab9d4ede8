// SPDX-License-Identifier: MIT
// formflow.Case: a case file or a dict, plus overrides, validated by the CLI's own loader.
#pragma once

#include "formflow/io/case.hpp"

#include <string>
#include <vector>

namespace formflow::python {

/// What a Python user builds a run from. It keeps what the CLI would be given
/// (a case path, or none for the paper's benchmark, and `--set` overrides in
/// order) and the case io::load_case resolved from it; every change re-runs that
/// loader, so a Python case is valid exactly when the same command line is,
/// and fails with the same InputError text.
class PythonCase {
public:
  /// The embedded benchmark with `overrides` applied (a dict's entries).
  explicit PythonCase(std::vector<io::Override> overrides = {});
  /// The case file at `path` (read now; relative mesh paths resolve from its directory).
  static PythonCase from_file(const std::string& path);

  /// `--set key=toml_text`: validated with every earlier override; on an
  /// InputError the case is left as it was.
  void set(const std::string& key, const std::string& toml_text);

  const io::Case& resolved() const { return case_; }
  const std::string& path() const { return path_; }
  const std::vector<io::Override>& overrides() const { return overrides_; }

private:
  PythonCase(std::string path, std::vector<io::Override> overrides);

  std::string path_; ///< empty: the embedded default case
  std::vector<io::Override> overrides_;
  io::Case case_;
};

} // namespace formflow::python
