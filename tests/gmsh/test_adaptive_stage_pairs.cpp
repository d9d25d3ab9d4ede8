// SPDX-License-Identifier: MIT
// The adaptive stage composed with the stages the table lets inside it (issue 43): the
// estimate on every cycle, the coarse start on cycle 0, exact-friction-free Newton.
#include "formflow/app/simulation.hpp"
#include "formflow/app/stages/composition.hpp"
#include "formflow/io/case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace formflow {
namespace {

/// The sticking ram on Q1 at h = 1/2 (coarse levels fit; the default solver.coarse_levels
/// is 2) with two cycles and an
/// unreachable target, so that both cycles run and stop on max_cycles.
io::Case two_small_cycles(const std::vector<io::Override>& overrides) {
  std::vector<io::Override> all = {
      {"process.ram", "\"sticking\""}, {"mesh.element", "\"Q1\""},     {"mesh.size", "0.5"},
      {"integration.volumetric", "1"}, {"adapt.target_error", "1e-9"}, {"adapt.max_cycles", "2"}};
  all.insert(all.end(), overrides.begin(), overrides.end());
  return io::load_case("", all);
}

std::vector<std::string> stage_names(const io::Case& case_) {
  std::vector<std::string> names;
  for (const app::Stage* stage :
       app::compose_stages(app::make_run_plan(case_), app::MeshOwnership::PlanMeshes))
    names.emplace_back(stage->name());
  return names;
}

TEST(AdaptiveStagePairs, EstimateInsideEveryCycle) {
  const io::Case case_ = two_small_cycles({{"solver.load_error", "\"refined\""}});
  const std::vector<std::string> names = stage_names(case_);
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), "adaptive cycles");
  const post::Results results = app::simulate(case_).results;
  ASSERT_TRUE(results.converged());
  ASSERT_EQ(results.adapt.cycles.size(), 2u);
  EXPECT_EQ(results.adapt.stop, "max_cycles");
  for (const post::AdaptCycle& cycle : results.adapt.cycles)
    EXPECT_TRUE(cycle.estimate.has_value()) << "each cycle's estimate decides its stop";
  // The last cycle's own estimate is the result's bar, its indicators one per cell.
  ASSERT_TRUE(results.load_error.error.has_value()) << results.load_error.unavailable;
  EXPECT_EQ(results.load_error.cell_indicators.size(), results.n_cells);
  EXPECT_GT(results.adapt.cycles[1].dofs, results.adapt.cycles[0].dofs);
}

TEST(AdaptiveStagePairs, CoarseStartInsideTheFirstCycle) {
  const io::Case with = two_small_cycles({{"solver.coarse_levels", "1"}});
  const std::vector<std::string> names = stage_names(with);
  EXPECT_NE(std::find(names.begin(), names.end(), "coarse start"), names.end());
  const post::Results sequenced = app::simulate(with).results;
  const post::Results plain =
      app::simulate(two_small_cycles({{"solver.coarse_levels", "0"}})).results;
  ASSERT_TRUE(sequenced.converged());
  ASSERT_TRUE(plain.converged());
  ASSERT_EQ(sequenced.adapt.cycles.size(), 2u);
  ASSERT_EQ(plain.adapt.cycles.size(), 2u);
  // Cycle 0 on the plan's mesh started from the coarse level: its Newton path is not the
  // one from the constant-viscosity start (8 steps against 7 here: on so small a mesh
  // the coarse start does not pay, docs/benchmarks.md), while without a coarse start the
  // two runs are the same computation. The discrete problem is the same: each load is
  // within its last Newton step, δ relative, of the discrete one (quadratic convergence),
  // the two within 2δ|p|.
  EXPECT_NE(sequenced.adapt.cycles[0].newton_iterations, plain.adapt.cycles[0].newton_iterations);
  EXPECT_NEAR(sequenced.adapt.cycles[0].load, plain.adapt.cycles[0].load,
              2 * with.solver.tolerance * std::abs(plain.adapt.cycles[0].load));
  EXPECT_EQ(sequenced.adapt.cycles[0].dofs, plain.adapt.cycles[0].dofs);
}

TEST(AdaptiveStagePairs, HotCycles) {
  // The ThermalBalance fixture's adiabatic tools; its coupling contracts slowly on the
  // finer meshes: each hot run (the cycles and their estimates' levels) gets the steps
  // it needs.
  const io::Case case_ = two_small_cycles({{"solver.load_error", "\"refined\""},
                                           {"thermal.enabled", "true"},
                                           {"thermal.billet_temperature", "0"},
                                           {"thermal.tool_temperature", "0"},
                                           {"thermal.max_temperature", "1000"},
                                           {"thermal.conductivity", "1e-3"},
                                           {"thermal.heat_transfer", "0"},
                                           {"thermal.max_coupling_iterations", "100"}});
  const std::vector<std::string> names = stage_names(case_);
  EXPECT_NE(std::find(names.begin(), names.end(), "thermal coupling"), names.end());
  const post::Results results = app::simulate(case_).results;
  ASSERT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  ASSERT_EQ(results.adapt.cycles.size(), 2u) << results.adapt.stop;
  EXPECT_EQ(results.adapt.stop, "max_cycles");
  for (const post::AdaptCycle& cycle : results.adapt.cycles) {
    EXPECT_TRUE(cycle.estimate.has_value()) << "each cycle's hot estimate decides its stop";
    EXPECT_FALSE(cycle.estimate_predicted) << "a hot run's cycles get the full estimate";
  }
  EXPECT_GT(results.adapt.cycles[1].dofs, results.adapt.cycles[0].dofs);
  // The last cycle is a hot run on the remeshed channel: its coupling block and T field.
  EXPECT_TRUE(results.thermal.enabled);
  EXPECT_TRUE(results.thermal.coupling_converged);
  EXPECT_EQ(results.fields.temperature.size(), results.fields.velocity.size() / 2);
  ASSERT_TRUE(results.load_error.error.has_value()) << results.load_error.unavailable;
}

} // namespace
} // namespace formflow
