// SPDX-License-Identifier: MIT
// Shared set-up of the verification tests: manufactured-solution cases and ladders.
#pragma once

#include "formflow/app/study.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace formflow::testing {

/// The smooth manufactured solution on the unit square with `element` and the
/// reduced volumetric rule of SPEC §3 (1×1 for Q1, 2×2 for Q2), d = 1e-3 (the
/// paper's). `nonlinear`: the paper's law (5.4); otherwise α = 1, i.e. the
/// constant viscosity A. The secant tolerance (1e-8) is far below the
/// discretisation error (≥ 1e-4 here) so that the measured error is the
/// discretisation error alone; with α = 1e-3 the secant iteration contracts
/// slowly (a few hundred iterations to 1e-8, hence the limit).
inline io::Case manufactured_case(fem::ElementKind element, Real size, mesh::Distortion distortion,
                                  bool nonlinear) {
  io::Case case_;
  case_.manufactured = physics::ManufacturedSolution::Smooth;
  case_.element = element;
  case_.mesh.size = size;
  case_.volumetric_points = element == fem::ElementKind::Q1 ? 1 : 2;
  case_.mesh.distortion = {distortion, distortion == mesh::Distortion::Random ? 0.2 : 0.1, 1};
  if (!nonlinear) case_.material.parameters_of<physics::PiecewisePower>().alpha = 1.0;
  case_.solver.tolerance = 1e-8;
  case_.solver.max_iterations = 1000;
  return case_;
}

/// Every rung of a refinement ladder converged, and both error norms fall with each
/// refinement (call through ASSERT_NO_FATAL_FAILURE: a rung that did not converge stops
/// the test).
inline void expect_converged_errors_fall(const post::StudyTable& table) {
  ASSERT_TRUE(table.all_converged());
  for (std::size_t k = 1; k < table.rungs.size(); ++k) {
    EXPECT_LT(table.rungs[k].error->v_norm, table.rungs[k - 1].error->v_norm);
    EXPECT_LT(table.rungs[k].error->l2, table.rungs[k - 1].error->l2);
  }
}

/// manufactured_case on simplices (triangles, or tetrahedra with `dimension` 3): P2+ with the
/// discontinuous linear pressure condensed per cell (mixed, d > 0).
inline io::Case simplex_manufactured_case(Real size, int dimension, mesh::Distortion distortion,
                                          bool nonlinear) {
  io::Case case_ = manufactured_case(fem::ElementKind::Q2, size, distortion, nonlinear);
  case_.mesh.dimension = dimension;
  case_.mesh.cell = dimension == 2 ? mesh::CellKind::Triangle : mesh::CellKind::Tetrahedron;
  case_.element = fem::ElementKind::P2;
  case_.formulation.type = assembly::FormulationType::Mixed;
  case_.formulation.pressure = fem::PressureSpace::P1disc;
  return case_;
}

/// A study over mesh.size of `make(size)` for each size.
template <class Make> post::StudyTable mesh_ladder(const std::vector<Real>& sizes, Make make) {
  app::StudyPlan plan;
  plan.key = "mesh.size";
  for (Real size : sizes) {
    plan.values.push_back(fmt::format("{:g}", size));
    plan.cases.push_back(make(size));
  }
  return app::run_study(plan, false);
}

} // namespace formflow::testing

#include "formflow/app/simulation.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/secant_iteration.hpp"

namespace formflow::testing {

/// A forming case solved on a given mesh (for transformed meshes), optionally from `start`.
struct Solved {
  VectorX velocity;
  post::Results results;
};

inline Solved solve_on(const mesh::Mesh<2>& mesh, const io::Case& case_,
                       const VectorX* start = nullptr) {
  const assembly::FormingProblem<2> problem(mesh, app::problem_settings(case_));
  auto solver = solvers::make_cholmod_solver();
  PhaseTimes times;
  solvers::FormingNonlinearProblem<2> nonlinear(problem);
  solvers::SecantOutcome outcome =
      solvers::secant_iteration(nonlinear, *solver, case_.solver, {}, times, start);
  Solved solved{outcome.velocity, {}};
  solved.results.stop_reason = outcome.stop_reason;
  solved.results.iterations = static_cast<int>(outcome.history.size());
  post::evaluate_results(problem, outcome.velocity, solved.results);
  return solved;
}

/// The paper's benchmark on the coarse mesh h = 2.5 (Q2, 2×2 volumetric rule)
/// with nonlocal friction, solved tightly: small and fast, yet every term of
/// the problem (contact penalty, mollified friction) is active.
inline io::Case coarse_benchmark() {
  io::Case case_;
  case_.mesh.size = 2.5;
  case_.friction.mu = 0.1;
  case_.friction.radius = 2.0;
  case_.solver.tolerance = 1e-9;
  case_.solver.max_iterations = 1000;
  return case_;
}

} // namespace formflow::testing
