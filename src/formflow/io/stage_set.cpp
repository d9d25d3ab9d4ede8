// SPDX-License-Identifier: MIT
// The outer loops a case asks for, for the composition table.
#include "formflow/io/stage_set.hpp"

#include "formflow/io/problem_shape.hpp"

namespace formflow::io {

solvers::StageSet stage_set(const Case& case_) {
  solvers::StageSet stages;
  stages.manufactured = case_.manufactured != physics::ManufacturedSolution::None;
  stages.thermal = case_.thermal.enabled;
  stages.adapt = case_.adapt.enabled();
  stages.linearized_estimate_asked =
      case_.solver.load_error == solvers::LoadErrorMethod::Linearized;
  stages.exact_friction = case_.friction.regularization == physics::FrictionRegularization::None;
  stages.exact_incompressibility =
      case_.formulation.type == assembly::FormulationType::Mixed && case_.penalty.d == 0;
  stages.exact_contact = case_.penalty.d_n == 0;
  stages.newton = case_.solver.method == solvers::NonlinearMethod::Newton;
  stages.petsc = case_.solver.linear == solvers::LinearSolverKind::Petsc;
  return stages;
}

} // namespace formflow::io
