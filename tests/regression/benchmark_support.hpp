// SPDX-License-Identifier: MIT
// Shared set-up of the benchmark regression tests: the paper's case with edits.
#pragma once

#include "formflow/app/simulation.hpp"

#include <cmath>
#include <functional>
#include <vector>

namespace formflow::testing {

/// The paper's benchmark (SPEC §4, the io::Case defaults) with `edit` applied, without
/// the load's error estimate unless `edit` asks for one: it is not what these tests
/// check (its own tests: test_load_error_estimate.cpp), and on the small meshes here the
/// default ("auto") estimate costs several runs.
inline post::Results solve_benchmark(const std::function<void(io::Case&)>& edit) {
  io::Case case_;
  case_.solver.load_error = solvers::LoadErrorMethod::None;
  edit(case_);
  return app::simulate(case_).results;
}

/// Aitken–Richardson limit of three successive rungs of a ladder with a fixed
/// refinement ratio: p∞ = p3 − (p3 − p2)² / ((p3 − p2) − (p2 − p1)).
inline double richardson_limit(double p1, double p2, double p3) {
  const double d1 = p2 - p1, d2 = p3 - p2;
  return p3 - d2 * d2 / (d2 - d1);
}

/// Observed order of convergence from three rungs with refinement ratio 2.
inline double observed_order(double p1, double p2, double p3) {
  return std::log2((p2 - p1) / (p3 - p2));
}

} // namespace formflow::testing
