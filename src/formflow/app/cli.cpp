// SPDX-License-Identifier: MIT
// Command-line parsing (CLI11) and the run/check subcommands.
#include "formflow/app/cli.hpp"
#include "formflow/app/distributed_run.hpp"
#include "formflow/app/rank_agreement.hpp"

#include "formflow/app/monitor.hpp"
#include "formflow/app/simulation.hpp"
#include "formflow/app/stop_signals.hpp"
#include "formflow/app/study.hpp"
#include "formflow/core/error.hpp"
#include "formflow/core/printable_text.hpp"
#include "formflow/io/case_json.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/io/mesh_input.hpp"
#include "formflow/io/output_directory.hpp"
#include "formflow/io/output_error.hpp"
#include "formflow/io/results_writer.hpp"
#include "formflow/solvers/blas_runtime.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <optional>
#include <utility>
#include <variant>

namespace formflow::app {

namespace {

struct Options {
  std::string case_path;
  std::string output_directory = "results";
  std::vector<std::string> assignments;
  bool quiet = false;
  bool json = false;
};

std::vector<io::Override> parse_assignments(const std::vector<std::string>& assignments) {
  std::vector<io::Override> overrides;
  for (const std::string& text : assignments) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
      throw InputError("--set", 0, text, "expected key=value", "e.g. --set friction.mu=0.1");
    overrides.emplace_back(text.substr(0, equals), text.substr(equals + 1));
  }
  return overrides;
}

/// A signal that came while the results were being moved into place: the
/// commit was finished rather than broken, so the new set is complete.
int report_late_signal(const std::string& directory) {
  fmt::print(stderr, "formflow: stopped by a signal; the results in {} are complete\n", directory);
  return signal_exit_code(stop_signal());
}

void print_warnings(const io::Case& case_) {
  for (const std::string& warning : case_.warnings) fmt::print(stderr, "warning: {}\n", warning);
}

/// Refuses an empty case path, which would otherwise silently mean the default case.
std::string non_empty_path(const std::string& path) {
  return path.empty() ? "an empty path names no case file (omit it for the paper's benchmark)" : "";
}

constexpr const char* exit_codes = "Exit codes: 0 ok; 1 internal error (a bug: please report); "
                                   "2 bad input or usage (nothing written); 3 not converged "
                                   "(results written, marked converged: false); 130/143 stopped by "
                                   "SIGINT/SIGTERM (the old results intact, or the new set "
                                   "complete).";

/// A first argument that is neither an option nor a subcommand: CLI11 would
/// only say that a subcommand is required.
std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return std::nullopt;
  for (const CLI::App* command : app.get_subcommands({}))
    if (command->check_name(argv[1])) return std::nullopt;
  return std::string(argv[1]);
}

int run_case(const Options& options) {
  // On several MPI ranks solver.linear defaults to PETSc (app/distributed_run.hpp).
  // On several ranks they agree that each read the same case and none refused its input
  // before anything collective (app/rank_agreement.hpp).
  io::Case case_;
  agree_on_input([&options, &case_] {
    case_ = load_run_case(options.case_path, parse_assignments(options.assignments));
    check_distributed(case_); // several ranks: what they cannot serve yet, before output
    // Before the solve: a -o that cannot take the results costs nothing (exit 2).
    // A distributed run writes once, from rank 0 (the others' output is muted by main).
    if (is_output_rank())
      io::check_output_directory(options.output_directory, io::result_file_names());
    // The ranks compare the resolved keys (summary.json's "case").
    return ReadInput{case_.source, io::case_to_json(case_).dump()};
  });
  print_warnings(case_);
  Monitor monitor(stdout, case_.solver.tolerance, case_.solver.max_iterations,
                  case_.solver.linear == solvers::LinearSolverKind::Petsc);
  const bool show = !options.quiet && !options.json;
  if (show) {
    std::string mesh_text = case_.mesh.source == mesh::MeshSource::File
                                ? "mesh " + case_.mesh.file
                                : fmt::format("mesh h = {:.6g}", case_.mesh.size);
    if (case_.mesh.dimension == 3) {
      const mesh::SolidChannel& solid = case_.mesh.solid;
      if (case_.manufactured != physics::ManufacturedSolution::None)
        mesh_text += " (3D unit cube)";
      else if (case_.mesh.source == mesh::MeshSource::File)
        mesh_text += " (3D hexahedra)";
      else if (solid.section == mesh::ChannelSection::Slab)
        mesh_text += fmt::format(" (3D slab, thickness {:.6g})", solid.thickness);
      else if (solid.section == mesh::ChannelSection::Rectangle)
        mesh_text += fmt::format(" (3D rectangle quarter, half widths {:.6g} → {:.6g})",
                                 solid.entry_half_width, solid.exit_half_width);
      else if (solid.section == mesh::ChannelSection::Profile)
        mesh_text += fmt::format(
            " (3D profile of {} edges through a flat die, {} model, bearing cells {:.6g})",
            solid.profile.outline.size(),
            solid.profile.symmetry == mesh::ProfileSymmetry::None ? "whole"
            : solid.profile.symmetry == mesh::ProfileSymmetry::Y  ? "half"
                                                                  : "quarter",
            case_.mesh.bearing_cell());
      else
        mesh_text += " (3D round quarter)";
    }
    if (case_.mesh.dimension == 3 && mesh::shape_of(case_.mesh.cell) == mesh::CellShape::Simplex)
      mesh_text += ", tetrahedra";
    fmt::print("formflow {}: {} {} {}, volumetric rule {}x{}, mu = {:.6g}\n", FORMFLOW_VERSION,
               case_.source, fem::element_name(case_.element), mesh_text, case_.volumetric_points,
               case_.volumetric_points, case_.friction.mu);
    monitor.header();
  }
  // Every iteration is a safe point to stop at after SIGINT/SIGTERM (app/stop_signals.hpp).
  const IterationCallback callback = [&monitor, show](const solvers::IterationRecord& record) {
    stop_if_signalled(); // on several ranks: all of them at the same iteration
    if (show) monitor(record);
  };
  const Simulation simulation = simulate(case_, callback);
  const post::Results& results = simulation.results;
  if (is_output_rank())
    io::write_results(options.output_directory, case_, simulation.mesh, results,
                      signal_stop_request());
  if (stop_signal() != 0) return report_late_signal(options.output_directory);

  if (options.json) fmt::print("{}\n", io::summary_json(case_, results));
  const std::string reason(solvers::stop_reason_name(results.stop_reason));
  if (results.stop_reason == solvers::StopReason::CouplingLimit) {
    // Every flow solve converged; the staggered heat-flow loop did not settle.
    fmt::print(stderr,
               "formflow: NOT CONVERGED ({}): the heat-flow coupling took "
               "thermal.max_coupling_iterations = {} steps without meeting "
               "thermal.coupling_tolerance = {:g} (last change: temperature {:.3e} of its rise, "
               "pressure {}); results in {} are marked so\n",
               reason, results.thermal.coupling_iterations, case_.thermal.coupling_tolerance,
               results.thermal.temperature_change,
               results.thermal.force_change ? fmt::format("{:.3e}", *results.thermal.force_change)
                                            : std::string("not yet compared"),
               options.output_directory);
    return NotConverged;
  }
  if (!results.converged()) {
    fmt::print(stderr,
               "formflow: NOT CONVERGED ({}) after {} iterations; results in {} are marked "
               "so (summary.json converged: false, a comment in the CSVs and fields.vtu, a red "
               "mark on the pictures)\n",
               reason, results.iterations, options.output_directory);
    return NotConverged;
  }
  if (show)
    fmt::print("Nonlinear solve ({}) converged due to relative change < {:g}, iterations {}\n"
               "pressure: ram reaction {:.6f}  power balance {:.6f}  total power {:.6f}  "
               "mean -sigma_H near ram {:.6f}\nresults written to {}\n",
               results.method, case_.solver.tolerance, results.iterations,
               results.pressure.ram_reaction, results.pressure.power_balance,
               results.pressure.total_power, results.pressure.mean_hydrostatic_near_ram,
               options.output_directory);
  if (show && results.linear_algebra.ranks > 1)
    fmt::print("distributed: {} MPI ranks, the cells split by {} (summary.json linear_algebra)\n",
               results.linear_algebra.ranks, results.linear_algebra.partition);
  if (show) {
    const char* load =
        case_.process.type == physics::ProcessType::Drawing ? "drawing stress" : "ram pressure";
    if (results.load_error.error)
      fmt::print("load: {} p = {:.4f} ± {:.4f} (estimated error: discretisation and "
                 "regularisations, \"{}\" levels, docs/error-estimation.md)\n",
                 load, results.pressure.ram_reaction, *results.load_error.error,
                 results.load_error.method);
    else
      fmt::print("load: {} p = {:.4f} (no error estimate: {})\n", load,
                 results.pressure.ram_reaction, results.load_error.unavailable);
  }
  if (show && !results.adapt.cycles.empty()) {
    // One line per adaptive cycle ([adapt]), then why they stopped.
    for (std::size_t k = 0; k < results.adapt.cycles.size(); ++k) {
      const post::AdaptCycle& cycle = results.adapt.cycles[k];
      fmt::print("adapt cycle {}: {} cells, {} dofs, p = {:.5f}{}, {:.1f} s{}\n", k, cycle.cells,
                 cycle.dofs, cycle.load,
                 cycle.estimate ? fmt::format(" ± {:.5f}{}", *cycle.estimate,
                                              cycle.estimate_predicted ? " (predicted)" : "")
                                : std::string(),
                 cycle.seconds, cycle.refined_mesh ? " (the previous mesh split)" : "");
    }
    fmt::print("adapt: {} ({} cycles; target {:g} of the load)\n", results.adapt.stop,
               results.adapt.cycles.size(), case_.adapt.target_error);
  }
  if (show && !results.coarse_iterations.empty())
    fmt::print("coarse start (solver.coarse_levels): mesh.size {} took {} iterations "
               "(not counted above; their time is in the solver phases)\n",
               fmt::join(results.coarse_mesh_sizes, ", "),
               fmt::join(results.coarse_iterations, ", "));
  if (show && simulation.errors)
    fmt::print("manufactured solution: error V-norm {:.6e}  L2 {:.6e}  hydrostatic L2 {:.6e}\n",
               simulation.errors->v_norm, simulation.errors->l2, simulation.errors->hydrostatic_l2);
  return Ok;
}

} // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"formflow: steady-state metal forming (extrusion, drawing) by the finite element "
               "method of Angelov (2010)"};
  // The version, and the BLAS this process found (its kernels decide the speed of every
  // factorisation: solvers/blas_runtime.hpp).
  app.set_version_flag("--version", [] {
    const solvers::BlasRuntime blas = solvers::blas_runtime();
    std::string text = std::string("formflow ") + FORMFLOW_VERSION + "\nBLAS: " + blas.library;
    if (!blas.core.empty()) text += ", kernels " + blas.core;
    if (blas.threads) text += ", " + std::to_string(*blas.threads) + " thread(s)";
    return text;
  });
  app.require_subcommand(1);
  app.footer(exit_codes);
  Options options;

  CLI::App* run = app.add_subcommand("run", "Solve a case and write results")
                      ->footer(std::string("Example: formflow run cases/paper-q2-2x2-mesh2.toml -o "
                                           "results/q2 --set friction.mu=0.1\n") +
                               exit_codes);
  run->add_option("case", options.case_path, "Case file (TOML); omitted: the paper's benchmark")
      ->check(non_empty_path);
  run->add_option("-o,--output", options.output_directory, "Output directory")
      ->capture_default_str();
  run->add_option("--set", options.assignments, "Override a key, e.g. --set mesh.size=0.5")
      ->allow_extra_args(false);
  run->add_flag("-q,--quiet", options.quiet, "No monitor lines");
  run->add_flag("--json", options.json, "Print summary.json to stdout");

  CLI::App* check =
      app.add_subcommand("check", "Validate a case without solving")
          ->footer(std::string("Example: formflow check cases/paper-q2-2x2-mesh2.toml\n") +
                   exit_codes);
  check->add_option("case", options.case_path, "Case file (TOML)")
      ->required()
      ->check(non_empty_path);
  check->add_option("--set", options.assignments, "Override a key")->allow_extra_args(false);

  StudyCommand study_options;
  std::vector<std::string> study_assignments;
  CLI::App* study =
      app.add_subcommand("study", "Run a ladder over one key: study.csv (norms, observed orders) "
                                  "and a log-log study.png")
          ->footer("Examples:\n  formflow study --vary mesh.size=1,0.5,0.25,0.125 --set "
                   "process.ram=sticking -o results/ladder\n  formflow study --vary "
                   "mesh.size=1/4,1/8,1/16 --set verification.solution=smooth --set "
                   "integration.volumetric=1 --set mesh.element=Q1 -o results/mms\n"
                   "The last rung of a ladder that keeps the mesh (penalty.d, penalty.dT, "
                   "friction.radius, ...) is the reference u_ref of the difference norms.\n"
                   "Exit codes: 0 ok, 2 bad input (nothing written), 3 a rung did not converge.");
  study
      ->add_option("case", study_options.case_path,
                   "Case file (TOML); omitted: the paper's benchmark")
      ->check(non_empty_path);
  study->add_option("--vary", study_options.vary, "key=v1,v2,... (values may be fractions n/m)")
      ->required();
  study->add_option("--set", study_assignments, "Override a key in every rung")
      ->allow_extra_args(false);
  study->add_option("-o,--output", study_options.output_directory, "Output directory")
      ->capture_default_str();
  study->add_flag("--rcond", study_options.estimate_condition,
                  "Also estimate CHOLMOD's rcond of K(u) per rung (one extra factorisation)");
  study->add_flag("-q,--quiet", study_options.quiet, "No progress lines");
  study->add_option("--exact-load", study_options.exact_load,
                    "The exact load p: load_error_dofs.png shows |p_h - p| against dofs "
                    "(with the estimates' bars)");

  CLI::App* reference = app.add_subcommand(
      "case-reference", "Print the Markdown reference of every case key (docs/case-reference.md)");

  if (const auto command = unknown_command(app, argc, argv)) {
    fmt::print(stderr,
               "error: unknown command '{}' (commands: run, check, study, "
               "case-reference; see formflow --help)\n",
               printable_text(*command, 80));
    return BadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? Ok : BadInput;
  }
  try {
    if (*run) return run_case(options);
    if (*check) {
      const io::Case case_ =
          io::load_case(options.case_path, parse_assignments(options.assignments));
      // Meshing (or reading mesh.file) is part of the check: its errors are input errors too.
      print_warnings(case_);
      const mesh::AnyMesh mesh = io::load_mesh(case_);
      const auto [cells, nodes] = std::visit(
          [](const auto& typed) { return std::pair(typed.n_cells(), typed.n_nodes()); }, mesh);
      fmt::print("{}: valid ({} cells, {} nodes)\n", case_.source, cells, nodes);
      return Ok;
    }
    if (*study) {
      if (distribution().distributed())
        throw InputError("command line", 0, "study",
                         fmt::format("a study on {} MPI ranks is not served yet (docs/petsc.md)",
                                     distribution().size),
                         "run each rung with mpirun ... formflow run, or the study as one process");
      study_options.overrides = parse_assignments(study_assignments);
      return study_command(study_options);
    }
    if (*reference) {
      fmt::print("{}", io::case_reference_markdown());
      return Ok;
    }
  } catch (const InputError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return BadInput;
  } catch (const Stopped& stop) {
    fmt::print(stderr, "formflow: {}; the output directory was left as it was\n", stop.what());
    return stop_signal() != 0 ? signal_exit_code(stop_signal()) : InternalFailure;
  } catch (const io::OutputError& error) {
    fmt::print(stderr,
               "formflow: cannot write the results: {}; the output directory was left "
               "as it was\n",
               error.what());
    return InternalFailure;
  } catch (const std::exception& error) {
    fmt::print(stderr, "formflow: internal error: {}\n", error.what());
    return InternalFailure;
  }
  return BadInput;
}

} // namespace formflow::app
