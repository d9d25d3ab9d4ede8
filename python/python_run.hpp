// SPDX-License-Identifier: MIT
// formflow.run: one solve with the GIL released, Ctrl-C as a clean stop.
#pragma once

#include <pybind11/pybind11.h>

namespace formflow::python {

/// Binds formflow.run(case, on_iteration=None) -> Result.
void bind_run(pybind11::module_& module);

} // namespace formflow::python
