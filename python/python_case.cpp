// SPDX-License-Identifier: MIT
// PythonCase: the case loader re-run on every change.
#include "python_case.hpp"

#include "formflow/core/error.hpp"

#include <utility>

namespace formflow::python {

PythonCase::PythonCase(std::vector<io::Override> overrides)
    : PythonCase(std::string(), std::move(overrides)) {}

PythonCase::PythonCase(std::string path, std::vector<io::Override> overrides)
    : path_(std::move(path)), overrides_(std::move(overrides)),
      case_(io::load_case(path_, overrides_)) {}

PythonCase PythonCase::from_file(const std::string& path) {
  // An empty path would silently mean the default case, as on the command line.
  if (path.empty())
    throw InputError("case file", 0, "path",
                     "an empty path names no case file (use formflow.Case() for the paper's "
                     "benchmark)");
  return PythonCase(path, {});
}

void PythonCase::set(const std::string& key, const std::string& toml_text) {
  std::vector<io::Override> overrides = overrides_;
  overrides.emplace_back(key, toml_text);
  // Everything is re-validated: a cross-key check (a mesh size that must fit the
  // lengths) may fail only now.
  io::Case resolved = io::load_case(path_, overrides);
  case_ = std::move(resolved);
  overrides_ = std::move(overrides);
}

} // namespace formflow::python
