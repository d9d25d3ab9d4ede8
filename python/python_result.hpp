// SPDX-License-Identifier: MIT
// formflow.Result: one run's numbers as Python values and its fields as numpy arrays.
#pragma once

#include "python_case.hpp"

#include "formflow/app/simulation.hpp"

#include <pybind11/pybind11.h>

#include <string>

namespace formflow::python {

/// What formflow.run returns: the case that ran and the simulation (mesh and
/// results), and summary.json's document as a dict, rendered once by the same
/// code that writes the file (so a Python run and a CLI run can be compared
/// number by number).
struct PythonResult {
  PythonCase case_;
  app::Simulation simulation;
  pybind11::dict summary;

  /// Writes the CLI's result set into `directory` (io::write_results), after
  /// the CLI's check of the directory. The GIL is released while the files are
  /// drawn and written.
  void write(const std::string& directory) const;
};

/// Binds Result and the value types it hands out (Iteration, Pressures, Powers).
void bind_result(pybind11::module_& module);

} // namespace formflow::python
