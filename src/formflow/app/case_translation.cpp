// SPDX-License-Identifier: MIT
// The one translation of a case into a run plan, and the front ends' calls over a case.
#include "formflow/app/simulation.hpp"

#include "formflow/app/distributed_run.hpp"
#include "formflow/app/load_error.hpp"
#include "formflow/app/stages/composition.hpp"
#include "formflow/core/error.hpp"
#include "formflow/io/mesh_input.hpp"
#include "formflow/io/problem_shape.hpp"
#include "formflow/io/stage_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <variant>

namespace formflow::app {

namespace {

/// The discrete problem's parameters taken from `case_`, with the loop's friction
/// augmentation `augmentation`.
assembly::ProblemSettings settings_of(const io::Case& case_, Real augmentation) {
  assembly::ProblemSettings settings;
  settings.process = case_.process;
  settings.law = case_.material.selected();
  // Hot forming: what is not at a point's temperature (the constant-viscosity start, the
  // coarse levels of mesh sequencing) is at the billet's.
  if (case_.thermal.enabled)
    std::visit(
        [&](auto& law) {
          if constexpr (physics::TemperatureDependent<std::decay_t<decltype(law)>>)
            law.temperature =
                std::min(case_.thermal.billet_temperature, case_.thermal.max_temperature);
        },
        settings.law.model);
  settings.viscous_strain = case_.viscous_strain;
  settings.penalty = case_.penalty;
  settings.friction = case_.friction;
  // The augmentation of the loop that runs (friction.newton_augmentation for Newton's).
  settings.friction.augmentation = augmentation;
  settings.volumetric_points = case_.volumetric_points;
  settings.initial_rate = case_.solver.initial_rate;
  settings.symmetry = case_.symmetry;
  // Nodal points where exact stick runs, though contact.normals was not given.
  settings.contact = io::contact_settings(case_);
  settings.distribution = distribution(); // one rank's own cells in a distributed run
  return settings;
}

KeyPlaces key_places(const io::Case& case_) {
  KeyPlaces keys;
  keys.source = case_.source;
  for (const auto& [key, where] : case_.key_locations)
    keys.places.emplace(key, KeyPlaces::Place{where.file, where.line});
  return keys;
}

} // namespace

SolvePlan make_solve_plan(const io::Case& case_) {
  SolvePlan plan;
  plan.shape = io::problem_shape(case_);
  const auto choice = solvers::choose_loop(plan.shape);
  FF_ASSERT(std::holds_alternative<solvers::LoopKind>(choice),
            "load_case refuses the combinations no loop serves");
  plan.loop = std::holds_alternative<solvers::LoopKind>(choice)
                  ? std::get<solvers::LoopKind>(choice)
                  : solvers::LoopKind::Secant;
  plan.linear = solvers::linear_solver_for(plan.loop, plan.shape);
  plan.coarse_levels = plan.sequences_meshes() ? case_.solver.coarse_levels : 0;
  plan.friction_augmentation = plan.loop == solvers::LoopKind::AugmentedNewton
                                   ? case_.friction.newton_augmentation
                                   : case_.friction.augmentation;
  // Exact stick: r only predicts the active set (|λ̂ + r u_T| ≤ τ_f) and no longer holds
  // stuck points, so the stiff 100/d_N the penalty needed is not wanted: with it a slip
  // of 1e-8 flips a point, and one grid case cycled at δ = 1e-8 (axisymmetric Q2,
  // sliding, h = 0.5, μ = 0.3: stalled after 20; with 1/d_N converged in 15). Unless
  // friction.newton_augmentation is given, r = 1/d_N (docs/friction.md "Session 8").
  if (plan.shape.exact_stick && !case_.key_locations.count("friction.newton_augmentation"))
    plan.friction_augmentation = 1.0;
  return plan;
}

RunPlan make_run_plan(const io::Case& case_) {
  RunPlan plan;
  plan.mesh = case_.mesh;
  // io's reader needs the case for the element order, the process (drawing frees the
  // container wall) and the keys to blame for a bad file: a copy is bound here, once.
  plan.make_mesh = [reader = std::make_shared<const io::Case>(case_)](const mesh::MeshSpec& spec) {
    return io::load_mesh(*reader, spec);
  };
  plan.element = case_.element;
  plan.solve = make_solve_plan(case_);
  plan.problem = settings_of(case_, plan.solve.friction_augmentation);
  plan.formulation = case_.formulation;
  plan.solver = case_.solver;
  plan.thermal = case_.thermal;
  plan.adapt = case_.adapt;
  plan.manufactured = case_.manufactured;
  plan.stages = io::stage_set(case_);
  plan.stages.ranks = distribution().size;
  plan.stages.exact_stick = plan.solve.shape.exact_stick;
  // Taylor–Hood's vertex pressure couples the ranks' cells (a discontinuous pressure kept
  // as a saddle point is each cell's, so one rank's).
  plan.stages.taylor_hood_saddle_point =
      plan.solve.loop == solvers::LoopKind::SaddlePointSecant &&
      case_.formulation.discontinuous != assembly::DiscontinuousPressure::SaddlePoint;
  plan.keys = key_places(case_);
  return plan;
}

Simulation simulate(const io::Case& case_, const IterationCallback& on_iteration,
                    bool estimate_condition) {
  return simulate(make_run_plan(case_), on_iteration, estimate_condition);
}

template <int dim>
Simulation simulate_on(const io::Case& case_, mesh::Mesh<dim> mesh,
                       const IterationCallback& on_iteration, bool estimate_condition) {
  return simulate_on<dim>(make_run_plan(case_), std::move(mesh), on_iteration, estimate_condition);
}

assembly::ProblemSettings problem_settings(const io::Case& case_) {
  return make_run_plan(case_).problem;
}

solvers::LoadErrorMethod resolved_load_error_method(const io::Case& case_, bool mesh_from_case,
                                                    int dim, Index n_dofs, std::string& why) {
  return resolved_load_error_method(make_run_plan(case_), mesh_from_case, dim, n_dofs, why);
}

void check_distributed(const io::Case& case_) {
  refuse_composition(make_run_plan(case_));
}

io::Case load_run_case(const std::string& path, std::vector<io::Override> overrides) {
  if (!distribution().distributed()) return io::load_case(path, overrides);
  // On several ranks the default back-end is PETSc, the one distributed one (CHOLMOD is
  // serial): a default, so that the checks of the keys that need it (solver.petsc_options)
  // see it, and a case that names another back-end is still refused by that key.
  const std::vector<io::Override> defaults = {{"solver.linear", "petsc"}};
  io::Case case_ = io::load_case(path, overrides, defaults);
  if (case_.key_locations.count("friction.stick") == 0 &&
      make_solve_plan(case_).shape.exact_stick) {
    // The exact law's default under Newton (exact stick on nodal points) condenses the whole
    // tangent, which no rank holds: the augmented multipliers on the face points instead,
    // said once, since a serial run of the same case would take the other discretisation.
    fmt::print(stderr,
               "note: friction.stick = \"augmented\" on {} ranks (exact stick runs as one "
               "process; docs/petsc.md)\n",
               distribution().size);
    overrides.emplace_back("friction.stick", "augmented");
    case_ = io::load_case(path, overrides, defaults);
  }
  return case_;
}

template Simulation simulate_on<2>(const io::Case&, mesh::Mesh<2>, const IterationCallback&, bool);
template Simulation simulate_on<3>(const io::Case&, mesh::Mesh<3>, const IterationCallback&, bool);

} // namespace formflow::app
