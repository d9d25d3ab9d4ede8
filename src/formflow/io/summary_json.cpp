// SPDX-License-Identifier: MIT
// summary.json: the headline numbers of a run, the iteration history and the resolved case.
#include "formflow/core/error.hpp"
#include "formflow/io/case_json.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/io/problem_shape.hpp"
#include "formflow/io/results_writer.hpp"
#include "formflow/post/load_error_estimate.hpp"
#include "formflow/solvers/blas_runtime.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <variant>

#ifndef FORMFLOW_VERSION
#error "FORMFLOW_VERSION must be defined by the build (CMake project version)"
#endif

namespace formflow::io {

namespace {

/// Keys in insertion order, so the file opens with the outcome and the
/// pressures and ends with the long history and the case.
using json = nlohmann::ordered_json;

/// nlohmann-json would write NaN/Inf as null, which reads back as "no value";
/// the solver never hands out non-finite numbers, so one here is a bug.
template <typename Json> void require_finite(const Json& value, const std::string& key) {
  if (value.is_number_float() && !std::isfinite(value.template get<double>()))
    throw InternalError("summary.json: " + key + " is not finite");
  if (value.is_object())
    for (const auto& [name, item] : value.items())
      require_finite(item, key.empty() ? name : key + "." + name);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i)
      require_finite(value[i], key + "[" + std::to_string(i) + "]");
}

/// What the load's error estimate of `method` (LoadErrorEstimate::method) computed.
json error_estimate_description(const std::string& method) {
  if (method == "coarser")
    return "loads solved on the structured channel at 2h and 4h: the geometric tail beyond p_h "
           "of the differences, ratio observed on 4h, 2h, h, times the safety factor, plus the "
           "doubled regularisations' offset on 2h";
  if (method == "refined" || method == "linearized")
    return "adjoint of the reaction on the mesh refined once (dual-weighted residual), its "
           "geometric tail times the safety factor, plus the doubled regularisations' offset";
  return nullptr;
}

json pressure_json(const Case& case_, const post::Results& results) {
  const post::Pressures& pressure = results.pressure;
  json out = {{"ram_reaction", pressure.ram_reaction},
              {"power_balance", pressure.power_balance},
              {"total_power", pressure.total_power},
              {"mean_hydrostatic_near_ram", pressure.mean_hydrostatic_near_ram}};
  // In drawing the reaction on the pulled front end is the drawing stress.
  // The load's error bar (post/load_error_estimate.hpp); null when not computed.
  const post::LoadErrorEstimate& estimate = results.load_error;
  const json error = estimate.error ? json(*estimate.error) : json(nullptr);
  out["ram_reaction_error"] = error;
  if (case_.process.type == physics::ProcessType::Drawing) {
    out["drawing_stress"] = pressure.ram_reaction;
    out["drawing_stress_error"] = error;
  }
  out["error_estimate"] = {
      {"method", estimate.method.empty() ? json(nullptr) : json(estimate.method)},
      {"description", error_estimate_description(estimate.method)},
      {"computed", estimate.error.has_value()},
      {"unavailable", estimate.error ? json(nullptr) : json(estimate.unavailable)},
      {"refined_dofs", estimate.enriched_dofs},
      {"refined_newton_iterations", estimate.settle_iterations},
      {"refined_change", estimate.error && estimate.method != "coarser"
                             ? json(estimate.enriched_change)
                             : json(nullptr)},
      {"coarser_change", estimate.coarser_change ? json(*estimate.coarser_change) : json(nullptr)},
      {"finer_change", estimate.finer_change ? json(*estimate.finer_change) : json(nullptr)},
      {"coarsest_change",
       estimate.coarsest_change ? json(*estimate.coarsest_change) : json(nullptr)},
      {"coarser_newton_iterations", estimate.coarser_newton_iterations},
      {"observed_ratio", estimate.observed_ratio ? json(*estimate.observed_ratio) : json(nullptr)},
      {"tail_ratio", estimate.error ? json(estimate.ratio) : json(nullptr)},
      {"discretisation", estimate.error ? json(estimate.discretisation_error) : json(nullptr)},
      {"penalty_change",
       estimate.error && estimate.penalty_change ? json(*estimate.penalty_change) : json(nullptr)},
      {"of_refined_mesh", estimate.of_refined_mesh},
      {"penalty_newton_iterations", estimate.penalty_newton_iterations},
      {"assumed_order", post::assumed_load_error_order},
      {"safety_factor", post::grid_convergence_safety_factor}};
  return out;
}

/// Per rank, the dofs it owns and its ghosts; null on one rank.
json rank_dofs_json(const std::vector<std::pair<Index, Index>>& rank_dofs) {
  if (rank_dofs.empty()) return nullptr;
  json ranks = json::array();
  for (const auto& [owned, ghosts] : rank_dofs)
    ranks.push_back({{"owned", owned}, {"ghosts", ghosts}});
  return ranks;
}

json power_json(const post::PowerTerms& power) {
  return {{"plastic_dissipation", power.plastic_dissipation},
          {"viscous_form", power.viscous_form},
          {"volumetric_penalty", power.volumetric_penalty},
          {"contact_penalty", power.contact_penalty},
          {"friction", power.friction},
          {"total", power.total()}};
}

json zones_json(const post::ContactZones& zones) {
  return {{"length", zones.length},
          {"stick_length", zones.stick_length},
          {"slip_length", zones.slip_length()},
          {"stick_fraction", zones.length > 0 ? zones.stick_length / zones.length : 0.0}};
}

/// Stick and slip per contact part, and how the friction law was solved.
json contact_json(const Case& case_, const post::Results& results) {
  const bool exact = case_.friction.regularization == physics::FrictionRegularization::None;
  json out = json::object();
  out["regularization"] = exact ? "none" : "regularized";
  // The loop that ran and how it held stuck points (friction.stick "auto" resolved).
  const solvers::ProblemShape shape = problem_shape(case_);
  const auto loop = solvers::choose_loop(shape);
  const bool newton = std::holds_alternative<solvers::LoopKind>(loop) &&
                      std::get<solvers::LoopKind>(loop) == solvers::LoopKind::AugmentedNewton;
  out["stick_criterion"] = !exact   ? "|sigma_T| < 0.99 tau_f, i.e. |u_T| < 7.02 d_T"
                           : newton ? "|u_T| <= solver.tolerance * process.speed"
                                    : "|lambda_T + r u_T| <= tau_f (Alart-Curnier active set)";
  // Where Γ3's points were (the nodes also where exact stick put them there unasked).
  out["points"] =
      stick_choice(case_).normals == assembly::ContactNormals::Nodes ? "nodes" : "faces";
  out["container"] = zones_json(results.container_zones);
  out["die"] = zones_json(results.die_zones);
  if (exact) {
    const StickChoice choice = stick_choice(case_);
    // Which method held the stuck points, and whether the user chose it or the default did.
    out["stick"] = !newton                                   ? "augmented (secant loop)"
                   : choice.stick == StickEnforcement::Exact ? "exact"
                                                             : "augmented";
    out["stick_given"] = choice.stick_given;
    out["augmented_lagrangian"] = {{"outer_iterations", results.augmentation.outer_iterations},
                                   {"multiplier_change", results.augmentation.multiplier_change}};
    // The Coulomb conditions' residual at the last update, at the problem's scale
    // ‖λ_T‖/‖u_T‖ (what the Newton loop's stop rule tests against solver.tolerance).
    out["friction_residual"] = results.augmentation.friction_residual;
    // Newton: the residual's power relative to the ram's (solvers/power_residual.hpp).
    out["power_residual"] = results.augmentation.power_residual;
  }
  return out;
}

/// What the mesh that ran looks like. mesh.size made the structured (and the
/// manufactured) grid and is Gmsh's target size; a mesh read from a file has
/// no size, so "size" is null there and the cell diameters describe it.
json mesh_json(const Case& case_, const post::Results& results) {
  // A verification run meshes the unit square itself, whatever mesh.source says.
  const bool manufactured = case_.manufactured != physics::ManufacturedSolution::None;
  const bool from_file = !manufactured && case_.mesh.source == mesh::MeshSource::File;
  json out = {{"source", manufactured
                             ? "box"
                             : std::get<std::string>(find_case_key("mesh.source")->get(case_))},
              {"dimension", results.dimension},
              {"elements", results.n_cells},
              {"nodes", results.n_nodes},
              {"dofs", results.n_dofs},
              {"element", std::string(fem::element_name(case_.element))}};
  out["size"] = from_file ? json(nullptr) : json(case_.mesh.size);
  out["min_cell_diameter"] = results.min_cell_diameter;
  out["max_cell_diameter"] = results.max_cell_diameter;
  return out;
}

/// Hot forming (docs/thermal.md): exit and peak temperature and where the heat went,
/// per unit depth (per radian in axisymmetry): deformation + friction = tools +
/// free_surfaces + convected + conducted.
json thermal_json(const post::ThermalResults& thermal) {
  return {{"exit_temperature",
           {{"min", thermal.exit_min}, {"mean", thermal.exit_mean}, {"max", thermal.exit_max}}},
          {"max_temperature", thermal.max_temperature},
          {"min_temperature", thermal.min_temperature},
          {"heat",
           {{"deformation", thermal.deformation},
            {"friction", thermal.friction},
            {"tools", thermal.tools},
            {"convected", thermal.convected},
            {"free_surfaces", thermal.free_surfaces},
            {"conducted", thermal.conducted}}},
          {"coupling",
           {{"iterations", thermal.coupling_iterations},
            {"converged", thermal.coupling_converged},
            {"temperature_change", thermal.temperature_change},
            {"force_change", thermal.force_change ? json(*thermal.force_change) : json(nullptr)},
            {"flow_iterations", thermal.flow_iterations}}}};
}

/// Adaptive refinement ([adapt], docs/error-estimation.md): one entry per cycle,
/// the last one being the mesh the rest of the summary describes.
json adapt_json(const Case& case_, const post::AdaptRecord& record) {
  json cycles = json::array();
  for (std::size_t k = 0; k < record.cycles.size(); ++k) {
    const post::AdaptCycle& cycle = record.cycles[k];
    cycles.push_back({{"cycle", k},
                      {"cells", cycle.cells},
                      {"dofs", cycle.dofs},
                      {"load", cycle.load},
                      {"estimate", cycle.estimate ? json(*cycle.estimate) : json(nullptr)},
                      {"estimate_predicted", cycle.estimate_predicted},
                      {"relative_estimate", cycle.estimate && cycle.load != 0
                                                ? json(*cycle.estimate / std::abs(cycle.load))
                                                : json(nullptr)},
                      {"newton_iterations", cycle.newton_iterations},
                      {"marked_cells", cycle.marked},
                      {"refined_mesh", cycle.refined_mesh},
                      {"time_s", cycle.seconds},
                      {"cpu_s", cycle.cpu_seconds},
                      {"estimate_time_s", cycle.estimate_seconds}});
  }
  return {{"target_error", case_.adapt.target_error},
          {"fraction", case_.adapt.fraction},
          {"reached_target", record.reached_target},
          {"stop", record.stop},
          {"cycles", std::move(cycles)}};
}

json timing_json(const PhaseTimes& timing) {
  json out = json::object();
  // The phases every run has are always present, so readers need no defaults.
  for (const char* phase : {"total", "assembly", "factorization", "solve"}) out[phase] = 0.0;
  for (const auto& [phase, seconds] : timing.all()) out[phase] = seconds;
  return out;
}

/// The case, in the key table's order, with the contact points the run used (exact
/// stick puts them on the nodes when contact.normals was not given): run again from
/// this block, the case runs the same way.
json case_json(const Case& case_) {
  json resolved = case_to_json(case_);
  require_finite(resolved, "case");
  if (stick_choice(case_).normals == assembly::ContactNormals::Nodes)
    resolved["contact"]["normals"] = "nodes";
  return resolved;
}

json summary_document(const Case& case_, const post::Results& results) {
  json history = json::array(), history_pressure = json::array();
  for (const auto& record : results.history) {
    history.push_back(record.relative_change);
    history_pressure.push_back(record.pressure);
  }
  json out = json::object();
  out["formflow_version"] = FORMFLOW_VERSION;
  out["converged"] = results.converged();
  out["stop_reason"] = std::string(solvers::stop_reason_name(results.stop_reason));
  out["iterations"] = results.iterations;
  out["coarse_iterations"] = results.coarse_iterations;
  out["coarse_mesh_sizes"] = results.coarse_mesh_sizes;
  out["method"] = results.method;
  // The secant loop's acceleration (solver.acceleration) and how many of the recorded
  // steps started from a mixed iterate (the rest: plain, loose, or after a restart).
  const bool anderson = case_.solver.acceleration == solvers::NonlinearAcceleration::Anderson;
  long mixed_steps = 0;
  for (const auto& record : results.history)
    if (record.mixed_columns > 0) ++mixed_steps;
  out["acceleration"] = {
      {"method", anderson ? "anderson" : "none"},
      {"depth", anderson ? json(case_.solver.acceleration_depth) : json(nullptr)},
      {"mixed_steps", mixed_steps}};
  out["pressure"] = pressure_json(case_, results);
  out["power"] = power_json(results.power);
  out["max_equivalent_strain_rate"] = results.max_equivalent_strain_rate;
  out["contact"] = contact_json(case_, results);
  if (results.exit.present) {
    const post::ExitFlow& exit = results.exit;
    // The exit section (post/exit_flow.hpp): axial velocity, its spread, the flux balance.
    out["exit"] = {
        {"velocity",
         {{"min", exit.velocity_min}, {"mean", exit.velocity_mean}, {"max", exit.velocity_max}}},
        {"nonuniformity", exit.nonuniformity ? json(*exit.nonuniformity) : json(nullptr)},
        {"flux_balance", exit.flux_balance},
        {"exit_flux", exit.exit_flux},
        {"entry_flux", exit.entry_flux},
        {"free_surface_flux", exit.free_surface_flux},
        {"wall_flux", exit.wall_flux},
        {"area", exit.area}};
    // A profile: the mean exit speed of each outline edge's part of the section.
    if (!exit.edges.empty()) {
      json edges = json::array();
      for (std::size_t e = 0; e < exit.edges.size(); ++e) {
        const post::ExitEdge& edge = exit.edges[e];
        edges.push_back(
            {{"edge", e},
             {"from", {edge.from[0], edge.from[1]}},
             {"to", {edge.to[0], edge.to[1]}},
             {"bearing_length", edge.bearing_length},
             {"area", edge.area},
             {"velocity_mean",
              std::isfinite(edge.velocity_mean) ? json(edge.velocity_mean) : json(nullptr)}});
      }
      out["exit"]["edges"] = std::move(edges);
    }
  }
  if (results.thermal.enabled) out["thermal"] = thermal_json(results.thermal);
  out["mesh"] = mesh_json(case_, results);
  if (!results.adapt.cycles.empty()) {
    out["mesh"]["adapted"] = results.adapt.cycles.size() > 1; // Gmsh remeshes after cycle 0
    out["adapt"] = adapt_json(case_, results.adapt);
  }
  out["timing_s"] = timing_json(results.timing);
  // What the time bought: every factorisation (coarse levels and secant steps
  // included) and the GMRES iterations of Newton's unsymmetric steps; the back-end,
  // its own Krylov iterations on the fine mesh (per iteration of the loop, null for
  // CHOLMOD and UMFPACK, which have none) and the MPI ranks.
  const auto count_or_null = [](long count) { return count < 0 ? json(nullptr) : json(count); };
  json per_step = json::array();
  for (const auto& record : results.history)
    per_step.push_back(count_or_null(record.linear_iterations));
  out["linear_algebra"] = {{"solver", results.linear_algebra.solver},
                           {"iterations", count_or_null(results.linear_algebra.iterations)},
                           {"iterations_per_step", std::move(per_step)},
                           {"ranks", results.linear_algebra.ranks},
                           {"partition", results.linear_algebra.partition.empty()
                                             ? json(nullptr)
                                             : json(results.linear_algebra.partition)},
                           {"dofs_per_rank", rank_dofs_json(results.linear_algebra.rank_dofs)},
                           {"factorizations", results.timing.counted("factorization")},
                           {"krylov_iterations", results.timing.counted("krylov iterations")}};
  // The fill (counts from the back-end's analysis; null when it does not report them).
  // CHOLMOD counts in doubles; they are whole numbers, written as such.
  const auto count_or_null_real = [](double count) {
    return count < 0 ? json(nullptr) : json(static_cast<long long>(std::llround(count)));
  };
  out["linear_algebra"]["matrix_nonzeros"] =
      count_or_null_real(results.linear_algebra.matrix_nonzeros);
  out["linear_algebra"]["factor_nonzeros"] =
      count_or_null_real(results.linear_algebra.factor_nonzeros);
  out["linear_algebra"]["factor_flops"] = count_or_null_real(results.linear_algebra.factor_flops);
  // The BLAS that did the dense work, and which kernels it chose for this CPU: the same
  // run is slower on OpenBLAS's generic kernels (solvers/blas_runtime.hpp).
  const solvers::BlasRuntime blas = solvers::blas_runtime();
  out["linear_algebra"]["blas"] = {{"library", blas.library},
                                   {"core", blas.core.empty() ? json(nullptr) : json(blas.core)},
                                   {"threads", blas.threads ? json(*blas.threads) : json(nullptr)}};
  // How often each timed phase ran (timing_s / timing_calls = cost per call).
  json calls = json::object();
  for (const auto& [phase, seconds] : results.timing.all())
    calls[phase] = results.timing.counted(phase);
  out["timing_calls"] = std::move(calls);
  out["history"] = std::move(history);
  out["history_pressure"] = std::move(history_pressure);
  out["case"] = case_json(case_);
  return out;
}

} // namespace

std::string summary_json(const Case& case_, const post::Results& results) {
  const json document = summary_document(case_, results);
  require_finite(document, "");
  // A case path with invalid UTF-8 must not abort the whole write; U+FFFD marks it.
  return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

} // namespace formflow::io
