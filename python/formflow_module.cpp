// SPDX-License-Identifier: MIT
// The Python module `formflow`: its exceptions and warnings, Case, and the run/Result bindings.
#include "python_case.hpp"
#include "python_result.hpp"
#include "python_run.hpp"
#include "toml_literal.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/io/output_error.hpp"

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <variant>

namespace py = pybind11;
using formflow::python::PythonCase;

namespace {

/// A key's current value as a Python value (the key table's own getter).
py::object key_value(const PythonCase& case_, const std::string& name) {
  const formflow::io::CaseKey* key = formflow::io::find_case_key(name);
  if (!key)
    throw formflow::InputError("case", 0, name, "unknown key",
                               formflow::io::unknown_key_hint(name));
  return std::visit([](const auto& value) -> py::object { return py::cast(value); },
                    key->get(case_.resolved()));
}

/// Keys set away from their defaults, with where they were set ("file:line" or "--set").
py::dict non_defaults(const PythonCase& case_) {
  py::dict out;
  for (const auto& [name, where] : case_.resolved().key_locations)
    out[py::str(name)] = where.line > 0 ? fmt::format("{}:{}", where.file, where.line) : where.file;
  return out;
}

void bind_errors(py::module_& module) {
  // InputError is a ValueError whose str() is the CLI's message ("file:line: key:
  // what (hint)") and whose attributes are its parts.
  // Allocated once and never freed: a static py::object would be released after the
  // interpreter is gone.
  static const auto* input_error =
      new py::exception<formflow::InputError>(module, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const formflow::InputError& error) {
      py::object instance = py::reinterpret_borrow<py::object>(*input_error)(error.what());
      instance.attr("file") = error.file;
      instance.attr("line") = error.line;
      instance.attr("key") = error.key;
      instance.attr("message") = error.message;
      instance.attr("hint") = error.hint;
      PyErr_SetObject(input_error->ptr(), instance.ptr());
    } catch (const formflow::io::OutputError& error) {
      PyErr_SetString(PyExc_OSError, error.what());
    }
  });
  module.attr("NotConvergedWarning") = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "formflow.NotConvergedWarning",
      "A run stopped before converging: its result holds the last iterate.", PyExc_RuntimeWarning,
      nullptr));
  module.attr("CaseWarning") = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "formflow.CaseWarning", "A valid but doubtful case (what the CLI prints as warning:).",
      PyExc_UserWarning, nullptr));
}

void bind_case(py::module_& module) {
  py::class_<PythonCase>(module, "Case", R"(A validated case.

Case() is the paper's benchmark; Case(dict) applies the dict's entries to it, as
`--set` would ({"friction.mu": 0.1} or {"friction": {"mu": 0.1}});
Case.from_file(path) reads a case file. Every change is validated by the CLI's
own loader and raises formflow.InputError with the CLI's message.)")
      .def(py::init([](const py::dict& entries) {
             return PythonCase(formflow::python::dict_overrides(entries));
           }),
           py::arg("entries") = py::dict())
      .def_static("from_file", &PythonCase::from_file, py::arg("path"))
      .def(
          "set",
          [](PythonCase& case_, const std::string& key, const py::handle value) {
            case_.set(key, formflow::python::toml_literal(key, value));
            return &case_;
          },
          py::arg("key"), py::arg("value"), py::return_value_policy::reference_internal,
          "Sets one key as `--set key=value` does; returns the case (calls chain).")
      .def("get", &key_value, py::arg("key"), "The current value of a key.")
      .def_property_readonly("non_defaults", &non_defaults,
                             "{key: where it was set} for every key not at its default")
      .def_property_readonly("source",
                             [](const PythonCase& case_) { return case_.resolved().source; })
      .def_property_readonly("warnings",
                             [](const PythonCase& case_) { return case_.resolved().warnings; })
      .def("__repr__", [](const PythonCase& case_) {
        std::string text = "formflow.Case(" + case_.resolved().source;
        for (const auto& [key, value] : case_.overrides()) text += ", " + key + "=" + value;
        return text + ")";
      });
}

} // namespace

PYBIND11_MODULE(formflow, module) {
  module.doc() = "formflow: steady-state metal forming (extrusion, drawing) by the finite "
                 "element method of Angelov (2010).";
  module.attr("__version__") = FORMFLOW_VERSION;
  bind_errors(module);
  bind_case(module);
  formflow::python::bind_result(module);
  formflow::python::bind_run(module);
}
