// SPDX-License-Identifier: MIT
// The Result binding: attributes from post::Results, read-only numpy views of the fields.
#include "python_result.hpp"

#include "formflow/io/output_directory.hpp"
#include "formflow/io/results_writer.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <variant>
#include <vector>

namespace formflow::python {

namespace py = pybind11;

void PythonResult::write(const std::string& directory) const {
  io::check_output_directory(directory, io::result_file_names());
  const py::gil_scoped_release release;
  io::write_results(directory, case_.resolved(), simulation.mesh, simulation.results);
}

namespace {

const PythonResult& result_of(const py::object& self) {
  return self.cast<const PythonResult&>();
}

/// A read-only, C-contiguous view of `data` with `shape`, kept alive by `owner`
/// (the Result): no copy, and no way to change the run's numbers by accident.
template <typename T>
py::array read_only_view(const py::object& owner, const T* data, std::vector<py::ssize_t> shape) {
  py::array_t<T> view(shape, data, owner);
  view.attr("setflags")(py::arg("write") = false);
  return view;
}

/// A node-major field of `components` values per node as (n_nodes, components).
py::array node_field(const py::object& owner, const VectorX& field, int components) {
  return read_only_view(owner, field.data(),
                        {static_cast<py::ssize_t>(field.size() / components), components});
}

py::array scalar_field(const py::object& owner, const VectorX& field) {
  return read_only_view(owner, field.data(), {static_cast<py::ssize_t>(field.size())});
}

/// Coordinates (n_nodes, dim): Eigen stores the (dim, n_nodes) matrix column by
/// column, i.e. node by node, which is numpy's row-major (n_nodes, dim).
py::array node_coordinates(const py::object& owner) {
  return std::visit(
      [&](const auto& mesh) {
        return read_only_view(owner, mesh.nodes.data(),
                              {static_cast<py::ssize_t>(mesh.n_nodes()), mesh.dimension});
      },
      result_of(owner).simulation.mesh);
}

/// Connectivity (n_cells, nodes_per_cell), lexicographic node order (fem/lagrange.hpp).
py::array cell_connectivity(const py::object& owner) {
  return std::visit(
      [&](const auto& mesh) {
        return read_only_view(owner, mesh.cells.data(),
                              {static_cast<py::ssize_t>(mesh.n_cells()), mesh.nodes_per_cell()});
      },
      result_of(owner).simulation.mesh);
}

/// The contact profile, one array per contact.csv column (a copy: the samples
/// are stored as records).
py::dict contact_profile(const std::vector<post::ContactSample>& samples) {
  const auto n = static_cast<py::ssize_t>(samples.size());
  py::dict columns;
  const auto column = [&](const char* name, auto member) {
    using Value = std::remove_cvref_t<decltype(samples.front().*member)>;
    py::array_t<Value> values(n);
    auto out = values.template mutable_unchecked<1>();
    for (py::ssize_t k = 0; k < n; ++k) out(k) = samples[static_cast<std::size_t>(k)].*member;
    columns[name] = values;
  };
  column("arc_length", &post::ContactSample::arc_length);
  column("x", &post::ContactSample::x);
  column("y", &post::ContactSample::y);
  column("z", &post::ContactSample::z);
  column("contact_pressure", &post::ContactSample::contact_pressure);
  column("friction_stress", &post::ContactSample::friction_stress);
  column("slip_velocity", &post::ContactSample::slip_velocity);
  column("sticking", &post::ContactSample::sticking);
  column("part", &post::ContactSample::part);
  return columns;
}

void bind_values(py::module_& module) {
  py::class_<solvers::IterationRecord>(module, "Iteration",
                                       "One nonlinear iteration (a row of history.csv).")
      .def_readonly("iteration", &solvers::IterationRecord::iteration)
      .def_readonly("relative_change", &solvers::IterationRecord::relative_change,
                    "‖uⁿ⁺¹ − uⁿ‖ / ‖uⁿ⁺¹‖")
      .def_readonly("pressure", &solvers::IterationRecord::pressure,
                    "the process pressure of this iterate (ram reaction / height)")
      .def_readonly("seconds", &solvers::IterationRecord::seconds, "wall time of the iteration")
      .def_readonly("coupling", &solvers::IterationRecord::coupling,
                    "hot forming: > 0 on the record closing that coupling step (its "
                    "relative_change is the temperature's); 0 on flow iterations")
      .def_readonly("force_change", &solvers::IterationRecord::force_change,
                    "coupling records: |pᵏ − pᵏ⁻¹|/|pᵏ|")
      .def_readonly("max_temperature", &solvers::IterationRecord::max_temperature,
                    "coupling records: max T")
      .def_readonly("mixed_columns", &solvers::IterationRecord::mixed_columns,
                    "solver.acceleration = \"anderson\": the difference columns mixed into "
                    "the iterate this step started from (0: a plain step)")
      .def_readonly("stage", &solvers::IterationRecord::stage,
                    "which solve the iteration belongs to: empty for the run's own, else "
                    "e.g. \"error estimate: the mesh refined once, 5042 dofs\" (an on_iteration "
                    "callback sees the error estimate's and adaptive cycles' solves too)")
      .def("__repr__", [](const solvers::IterationRecord& record) {
        return fmt::format("Iteration({}, relative_change={:.6g}, pressure={:.6g})",
                           record.iteration, record.relative_change, record.pressure);
      });
  py::class_<post::Pressures>(module, "Pressures",
                              "The process load three ways (summary.json `pressure`).")
      .def_readonly("ram_reaction", &post::Pressures::ram_reaction)
      .def_readonly("power_balance", &post::Pressures::power_balance)
      .def_readonly("total_power", &post::Pressures::total_power)
      .def_readonly("mean_hydrostatic_near_ram", &post::Pressures::mean_hydrostatic_near_ram)
      .def("__repr__", [](const post::Pressures& pressure) {
        return fmt::format("Pressures(ram_reaction={:.6g}, power_balance={:.6g}, "
                           "total_power={:.6g}, mean_hydrostatic_near_ram={:.6g})",
                           pressure.ram_reaction, pressure.power_balance, pressure.total_power,
                           pressure.mean_hydrostatic_near_ram);
      });
  py::class_<post::PowerTerms>(module, "Powers",
                               "Powers of the discrete terms (summary.json `power`).")
      .def_readonly("plastic_dissipation", &post::PowerTerms::plastic_dissipation)
      .def_readonly("viscous_form", &post::PowerTerms::viscous_form)
      .def_readonly("volumetric_penalty", &post::PowerTerms::volumetric_penalty)
      .def_readonly("contact_penalty", &post::PowerTerms::contact_penalty)
      .def_readonly("friction", &post::PowerTerms::friction)
      .def_property_readonly("total", &post::PowerTerms::total);
}

} // namespace

void bind_result(py::module_& module) {
  bind_values(module);
  using Self = const py::object&;
  const auto results = [](Self self) -> const post::Results& {
    return result_of(self).simulation.results;
  };
  py::class_<PythonResult>(module, "Result",
                           "One run: the numbers of summary.json as attributes, the fields as "
                           "read-only numpy arrays (node-major, the mesh's node numbering).")
      .def_property_readonly("case", [](const PythonResult& result) { return result.case_; })
      .def_property_readonly(
          "converged",
          [](const PythonResult& result) { return result.simulation.results.converged(); })
      .def_property_readonly(
          "stop_reason",
          [](const PythonResult& result) {
            return std::string(solvers::stop_reason_name(result.simulation.results.stop_reason));
          })
      .def_property_readonly(
          "method", [](const PythonResult& result) { return result.simulation.results.method; })
      .def_property_readonly(
          "iterations",
          [](const PythonResult& result) { return result.simulation.results.iterations; })
      .def_property_readonly(
          "pressure", [](const PythonResult& result) { return result.simulation.results.pressure; })
      .def_property_readonly(
          "power", [](const PythonResult& result) { return result.simulation.results.power; })
      .def_property_readonly(
          "history", [](const PythonResult& result) { return result.simulation.results.history; })
      .def_property_readonly(
          "timings",
          [](const PythonResult& result) { return py::object(result.summary["timing_s"]); },
          "seconds per phase (summary.json timing_s)")
      .def_readonly("summary", &PythonResult::summary,
                    "summary.json as a dict (what result.write puts in the file)")
      .def_property_readonly(
          "dimension", [](const PythonResult& result) { return result.simulation.dimension(); })
      .def_property_readonly("nodes", node_coordinates, "node coordinates, (n_nodes, dim)")
      .def_property_readonly("cells", cell_connectivity,
                             "cell connectivity, (n_cells, nodes_per_cell), lexicographic order")
      .def_property_readonly(
          "velocity",
          [results](Self self) {
            return node_field(self, results(self).fields.velocity,
                              result_of(self).simulation.dimension());
          },
          "(n_nodes, dim)")
      .def_property_readonly(
          "equivalent_strain_rate",
          [results](Self self) {
            return scalar_field(self, results(self).fields.equivalent_strain_rate);
          },
          "ε̄̇ at the nodes, (n_nodes,)")
      .def_property_readonly(
          "hydrostatic_stress",
          [results](Self self) {
            return scalar_field(self, results(self).fields.hydrostatic_stress);
          },
          "σ_H at the nodes (tension positive), (n_nodes,)")
      .def_property_readonly(
          "contact_pressure",
          [results](Self self) {
            return scalar_field(self, results(self).fields.contact_pressure);
          },
          "−σ_N at the nodes, 0 away from Γ3, (n_nodes,)")
      .def_property_readonly(
          "friction_stress",
          [results](Self self) { return scalar_field(self, results(self).fields.friction_stress); },
          "|σ_T| at the nodes, 0 away from Γ3, (n_nodes,)")
      .def_property_readonly(
          "cell_equivalent_strain_rate",
          [results](Self self) {
            return scalar_field(self, results(self).fields.cell_equivalent_strain_rate);
          },
          "cell means of ε̄̇, (n_cells,)")
      .def_property_readonly(
          "cell_hydrostatic_stress",
          [results](Self self) {
            return scalar_field(self, results(self).fields.cell_hydrostatic_stress);
          },
          "cell means of σ_H, (n_cells,)")
      .def_property_readonly(
          "load_error",
          [](const PythonResult& result) -> py::object {
            const post::LoadErrorEstimate& estimate = result.simulation.results.load_error;
            return estimate.error ? py::object(py::float_(*estimate.error)) : py::none();
          },
          "the estimate of |p_h − p| for the load (summary.json pressure.ram_reaction_error); "
          "None when not computed, summary['pressure']['error_estimate']['unavailable'] "
          "says why")
      .def_property_readonly(
          "cell_load_error",
          [results](Self self) -> py::object {
            const VectorX& indicators = results(self).fields.cell_load_error;
            if (indicators.size() == 0) return py::none();
            return scalar_field(self, indicators);
          },
          "the load's error indicators per cell (fields.vtu load_error_indicator), (n_cells,); "
          "None without them")
      .def_property_readonly(
          "contact",
          [](const PythonResult& result) {
            return contact_profile(result.simulation.results.contact);
          },
          "the contact profile along Γ3 (contact.csv's columns), a dict of arrays")
      .def("write", &PythonResult::write, py::arg("directory"),
           "Writes what `formflow run -o directory` writes (summary.json, history.csv, "
           "contact.csv, fields.vtu, the pictures, report.html), as one set.")
      .def("__repr__", [](const PythonResult& result) {
        const post::Results& run = result.simulation.results;
        return fmt::format("<formflow.Result {} after {} iterations, ram reaction {:.6g}>",
                           run.converged()
                               ? "converged"
                               : "NOT converged (" +
                                     std::string(solvers::stop_reason_name(run.stop_reason)) + ")",
                           run.iterations, run.pressure.ram_reaction);
      });
}

} // namespace formflow::python
