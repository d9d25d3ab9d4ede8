// SPDX-License-Identifier: MIT
// The front ends' entry to a run: a case in, translated once into a run plan.
#pragma once

#include "formflow/app/run.hpp"
#include "formflow/io/case.hpp"

#include <string>
#include <vector>

namespace formflow::app {

/// The one translation of a case into a run plan (app/case_translation.cpp): the mesh
/// spec and its reader, the problem settings, the solve plan, the outer loops' settings
/// and the stages they compose, the keys' places. `case_` is validated (load_case).
RunPlan make_run_plan(const io::Case& case_);

/// simulate(make_run_plan(case_), ...): what the CLI, the Python module and a study run.
Simulation simulate(const io::Case& case_, const IterationCallback& on_iteration = {},
                    bool estimate_condition = false);

/// simulate_on(make_run_plan(case_), mesh, ...).
template <int dim>
Simulation simulate_on(const io::Case& case_, mesh::Mesh<dim> mesh,
                       const IterationCallback& on_iteration = {}, bool estimate_condition = false);

/// The discrete problem's parameters of `case_`: make_run_plan(case_).problem.
assembly::ProblemSettings problem_settings(const io::Case& case_);

/// The solve plan of a validated case (load_case refused what no loop serves).
SolvePlan make_solve_plan(const io::Case& case_);

/// resolved_load_error_method (app/load_error.hpp) of make_run_plan(case_).
solvers::LoadErrorMethod resolved_load_error_method(const io::Case& case_, bool mesh_from_case,
                                                    int dim, Index n_dofs, std::string& why);

/// On more than one rank, refuses (InputError naming the key, before the solve) what the
/// distributed run does not serve (the stage table, solvers/stage_table.hpp).
void check_distributed(const io::Case& case_);

/// `case_` loaded from `path` with `overrides`, and on more than one rank with PETSc as
/// the default of solver.linear (the one distributed back-end: `mpirun -np 2 formflow
/// run case.toml` runs): a case that sets solver.linear keeps its choice (and
/// check_distributed refuses any but PETSc, naming the key). Likewise friction.stick:
/// left unset where it would resolve to exact stick (serial only), it is "augmented".
io::Case load_run_case(const std::string& path, std::vector<io::Override> overrides);

} // namespace formflow::app
