// SPDX-License-Identifier: MIT
// formflow.run: app::simulate without the GIL; the iteration callback is the safe point
// where Python's own signals (Ctrl-C) and the user's callback get their turn.
#include "python_run.hpp"

#include "python_result.hpp"

#include "formflow/core/stop_request.hpp"
#include "formflow/io/results_writer.hpp"

#include <fmt/format.h>

#include <optional>
#include <utility>

namespace formflow::python {

namespace py = pybind11;

namespace {

/// The Python error that ended a solve at an iteration: KeyboardInterrupt from
/// Python's SIGINT handler, or whatever the user's callback raised.
struct PendingError {
  std::optional<py::error_already_set> error;
};

/// The iteration callback of a Python run. SIGINT stays Python's: its C handler
/// only records the signal (also while the GIL is released), and running the
/// Python-level handler here (PyErr_CheckSignals) raises KeyboardInterrupt, or
/// whatever handler the user installed. A Python error then unwinds the solve as
/// the CLI's stop does (formflow::Stopped, thrown at the same safe point) and is
/// raised again once the GIL is back.
app::IterationCallback python_callback(const py::object& on_iteration, PendingError& pending) {
  return [&on_iteration, &pending](const solvers::IterationRecord& record) {
    const py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!on_iteration.is_none()) on_iteration(record);
    } catch (py::error_already_set& error) {
      pending.error.emplace(std::move(error));
      throw Stopped("stopped by a Python exception at iteration " +
                    std::to_string(record.iteration));
    }
  };
}

void warn(const char* category, const std::string& message) {
  const py::object type = py::module_::import("formflow").attr(category);
  if (PyErr_WarnEx(type.ptr(), message.c_str(), 2) != 0) throw py::error_already_set();
}

PythonResult run(const PythonCase& case_, const py::object& on_iteration) {
  if (!on_iteration.is_none() && !PyCallable_Check(on_iteration.ptr()))
    throw py::type_error("on_iteration must be callable (it receives a formflow.Iteration)");
  for (const std::string& warning : case_.resolved().warnings) warn("CaseWarning", warning);
  PendingError pending;
  std::optional<app::Simulation> simulation;
  try {
    const py::gil_scoped_release release;
    simulation.emplace(app::simulate(case_.resolved(), python_callback(on_iteration, pending)));
  } catch (const Stopped&) {
    if (!pending.error) throw;
  }
  if (pending.error) throw std::move(*pending.error);

  PythonResult result{case_, std::move(*simulation), {}};
  const py::object json = py::module_::import("json");
  result.summary = json.attr("loads")(io::summary_json(case_.resolved(), result.simulation.results))
                       .cast<py::dict>();
  const post::Results& results = result.simulation.results;
  if (!results.converged())
    warn("NotConvergedWarning",
         fmt::format("formflow: NOT CONVERGED ({}) after {} iterations: the result holds the last "
                     "iterate (result.converged is False)",
                     solvers::stop_reason_name(results.stop_reason), results.iterations));
  return result;
}

} // namespace

void bind_run(py::module_& module) {
  module.def("run", &run, py::arg("case"), py::arg("on_iteration") = py::none(),
             R"(Solves `case` and returns a Result.

The GIL is released while solving; `on_iteration(formflow.Iteration)` is called
after every nonlinear iteration (with the GIL). Ctrl-C stops the solve at the
next iteration and raises KeyboardInterrupt; an exception raised by the callback
stops it the same way and propagates. A run that does not converge is a result
(result.converged is False) and a formflow.NotConvergedWarning, not an exception.)");
}

} // namespace formflow::python
