// SPDX-License-Identifier: MIT
// Ladder of runs over one key: running, differences, orders (planning: app/study_plan.cpp).
#include "formflow/app/study.hpp"

#include "formflow/app/simulation.hpp"
#include "formflow/core/error.hpp"
#include "formflow/io/case_keys.hpp"

#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <type_traits>
#include <variant>

namespace formflow::app {

namespace {

bool same_mesh(const mesh::AnyMesh& any_a, const mesh::AnyMesh& any_b) {
  if (any_a.index() != any_b.index()) return false;
  return std::visit(
      [&any_b](const auto& a) {
        const auto& b = std::get<std::decay_t<decltype(a)>>(any_b);
        return a.order == b.order && a.nodes.cols() == b.nodes.cols() && a.nodes == b.nodes &&
               a.cells == b.cells;
      },
      any_a);
}

/// ε̄̇ around the die corner (L_c, H_out) from ρ = 0.01 to the exit half height, 5 bins a
/// decade. The corner is a point of the plane channel: plane runs only.
post::CornerProfile die_corner_profile(const io::Case& case_, const Simulation& simulation) {
  const assembly::FormingProblem<2> problem(simulation.plane_mesh(), problem_settings(case_));
  const Point<2> corner(case_.mesh.geometry.container_length, case_.mesh.geometry.exit_half_height);
  return post::corner_profile<2>(problem, simulation.results.fields.velocity, corner, 0.01,
                                 case_.mesh.geometry.exit_half_height, 5);
}

} // namespace

post::StudyTable run_study(const StudyPlan& plan, bool estimate_condition,
                           const std::function<void(const post::StudyRung&)>& on_rung,
                           const IterationCallback& on_iteration) {
  const io::CaseKey* key = io::find_case_key(plan.key);
  FF_ASSERT(key, "plan_study checked the key");
  post::StudyTable table;
  table.key = plan.key;
  table.description = plan.description;
  std::vector<Simulation> simulations;
  // A mesh ladder of a case with [adapt] compares uniform with adaptive refinement:
  // the rungs are the uniform ladder (no [adapt], the load's estimate kept on), and
  // one adaptive run starts from the first rung's case (docs/error-estimation.md,
  // "Convergence picture").
  const bool against_adaptive = plan.key == "mesh.size" && plan.cases.front().adapt.enabled();
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    const auto start = std::chrono::steady_clock::now();
    io::Case rung_case = plan.cases[k];
    if (against_adaptive) {
      rung_case.adapt.target_error = 0;
      // The DWR estimate the adaptive cycles use, unless the case asked for another.
      if (rung_case.solver.load_error == solvers::LoadErrorMethod::None ||
          rung_case.solver.load_error == solvers::LoadErrorMethod::Auto)
        rung_case.solver.load_error = solvers::LoadErrorMethod::Refined;
    }
    Simulation simulation = simulate(rung_case, on_iteration, estimate_condition);
    post::StudyRung rung;
    rung.value_text = plan.values[k];
    rung.parameter = numeric_key_value(*key, plan.cases[k]);
    rung.dofs = simulation.results.n_dofs;
    rung.iterations = simulation.results.iterations;
    rung.stop_reason = simulation.results.stop_reason;
    rung.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rung.pressure = simulation.results.pressure;
    rung.error = simulation.errors;
    rung.reciprocal_condition = simulation.reciprocal_condition;
    rung.load_error_estimate = simulation.results.load_error.error;
    // The re-entrant corner (L_c, H_out) exists only for the square die of SPEC §4.
    if (plan.key == "mesh.size" &&
        plan.cases[k].manufactured == physics::ManufacturedSolution::None &&
        plan.cases[k].mesh.geometry.die == mesh::DieShape::Square && simulation.dimension() == 2)
      rung.corner = die_corner_profile(plan.cases[k], simulation);
    table.rungs.push_back(rung);
    if (on_rung) on_rung(table.rungs.back());
    simulations.push_back(std::move(simulation));
  }
  // Penalty and regularisation ladders keep the mesh: measure each rung
  // against the last one, which the user makes the reference (smallest d).
  const Simulation& last = simulations.back();
  bool common_mesh = true;
  for (const Simulation& simulation : simulations)
    common_mesh &= same_mesh(simulation.mesh, last.mesh);
  if (common_mesh)
    std::visit(
        [&](const auto& mesh) {
          constexpr int dim = std::decay_t<decltype(mesh)>::dimension;
          const assembly::FormingProblem<dim> problem(mesh, problem_settings(plan.cases.back()));
          for (std::size_t k = 0; k + 1 < simulations.size(); ++k)
            table.rungs[k].difference = post::difference_norms<dim>(
                problem, simulations[k].results.fields.velocity, last.results.fields.velocity);
        },
        last.mesh);
  post::compute_orders(table);
  if (against_adaptive)
    table.adaptive = simulate(plan.cases.front(), on_iteration).results.adapt; // [adapt]
  const io::Case& first = plan.cases.front();
  if (plan.key == "mesh.size" && first.manufactured != physics::ManufacturedSolution::None) {
    const int order = fem::element_order(first.element); // Theorem 4.1, smooth solution
    table.theory_order_v = order;
    table.theory_order_l2 = order + 1;
  } else if (plan.key == "penalty.d") { // Theorem 3.4
    table.theory_order_v = table.theory_order_l2 = 1.0;
  } else if (plan.key == "penalty.dT") { // Theorem 3.3 (a bound)
    table.theory_order_v = table.theory_order_l2 = 0.5;
  }
  return table;
}

} // namespace formflow::app
