// SPDX-License-Identifier: MIT
// The outer loops composed by the run plan (issue 43): each pair the stage table allows
// runs on a small case with both stages' blocks in the results; each pair it refuses
// is an InputError naming the keys (the CLI's exit 2: tests/cli/test_stage_refusals.cpp).
#include "formflow/app/simulation.hpp"
#include "formflow/app/stages/composition.hpp"
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace formflow {
namespace {

/// The sticking ram on Q1 at h = 1/2: mesh II's lengths admit 2h = 1, so one coarse
/// level fits (h = 1 admits none), and the run is a few hundred dofs.
const std::string small_case_text = R"(
[process]
ram = "sticking"
[mesh]
element = "Q1"
size = 0.5
[integration]
volumetric = 1
)";

/// The hot run of tests/verification/test_thermal_balance.cpp's fixture (adiabatic tools).
const std::string hot_text = R"(
[thermal]
enabled = true
billet_temperature = 0
tool_temperature = 0
max_temperature = 1000
conductivity = 1e-3
heat_transfer = 0
)";

io::Case small_case(const std::vector<io::Override>& overrides, const std::string& extra = "") {
  return io::load_case_text(small_case_text + extra, "stages.toml", overrides);
}

std::vector<std::string> stage_names(const app::RunPlan& plan) {
  std::vector<std::string> names;
  for (const app::Stage* stage : app::compose_stages(plan, app::MeshOwnership::PlanMeshes))
    names.emplace_back(stage->name());
  return names;
}

bool has_stage(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(StageComposition, EveryFormingChainEndsInTheLoopInsideTheSolve) {
  const std::vector<std::string> names = stage_names(app::make_run_plan(small_case({})));
  ASSERT_GE(names.size(), 3u);
  EXPECT_EQ(names.back(), "nonlinear loop");
  // The estimate reads the solved problem: outside the solve stage.
  const auto solve = std::find(names.begin(), names.end(), "solve");
  const auto estimate = std::find(names.begin(), names.end(), "error estimate");
  ASSERT_NE(solve, names.end());
  ASSERT_NE(estimate, names.end());
  EXPECT_LT(estimate - names.begin(), solve - names.begin());
}

TEST(StageComposition, CoarseStartInsideTheThermalCoupling) {
  const io::Case case_ = small_case({{"solver.coarse_levels", "1"}}, hot_text);
  const app::RunPlan plan = app::make_run_plan(case_);
  const std::vector<std::string> names = stage_names(plan);
  ASSERT_TRUE(has_stage(names, "thermal coupling"));
  ASSERT_TRUE(has_stage(names, "coarse start"));
  const post::Results results = app::simulate(plan).results;
  ASSERT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  // Both stages' blocks: the coarse level solved once (its start served the first
  // coupling step only), the coupling converged over more than one step.
  ASSERT_EQ(results.coarse_mesh_sizes.size(), 1u);
  EXPECT_EQ(results.coarse_mesh_sizes[0], 2 * case_.mesh.size);
  EXPECT_NE(results.method.find("from coarse meshes"), std::string::npos) << results.method;
  EXPECT_TRUE(results.thermal.coupling_converged);
  EXPECT_GE(results.thermal.coupling_iterations, 2);
  EXPECT_EQ(results.thermal.flow_iterations.size(),
            static_cast<std::size_t>(results.thermal.coupling_iterations));
  // The history holds every coupling step's flow iterations.
  int flow_iterations = 0;
  for (int count : results.thermal.flow_iterations) flow_iterations += count;
  EXPECT_EQ(results.iterations, flow_iterations);
}

TEST(StageComposition, CoarseStartInsideTheEstimate) {
  const io::Case case_ =
      small_case({{"solver.coarse_levels", "1"}, {"solver.load_error", "refined"}});
  const post::Results results = app::simulate(case_).results;
  ASSERT_TRUE(results.converged());
  EXPECT_EQ(results.coarse_mesh_sizes.size(), 1u);
  ASSERT_TRUE(results.load_error.error.has_value()) << results.load_error.unavailable;
  EXPECT_EQ(results.load_error.method, "refined");
  // The same run without the coarse start: the same discrete problem, each run stopped
  // when Newton's step is below δ relative to u. Newton converges quadratically, so each
  // velocity is within its last step of the discrete solution, and the load (the ram's
  // reaction, linear in u) of each within δ|p|: the two within 2δ|p|.
  const post::Results plain =
      app::simulate(small_case({{"solver.coarse_levels", "0"}, {"solver.load_error", "refined"}}))
          .results;
  ASSERT_TRUE(plain.converged());
  EXPECT_TRUE(plain.coarse_mesh_sizes.empty());
  EXPECT_NEAR(results.pressure.ram_reaction, plain.pressure.ram_reaction,
              2 * case_.solver.tolerance * std::abs(plain.pressure.ram_reaction));
}

TEST(StageComposition, ThermalWithTheAutomaticEstimateSaysWhyItHasNoBar) {
  const post::Results results = app::simulate(small_case({}, hot_text)).results;
  ASSERT_TRUE(results.converged());
  EXPECT_TRUE(results.thermal.coupling_converged);
  EXPECT_FALSE(results.load_error.error.has_value());
  EXPECT_NE(results.load_error.unavailable.find("hot forming"), std::string::npos)
      << results.load_error.unavailable;
}

TEST(StageComposition, CoarserEstimateSolvesItsLevelsWithTheCoupling) {
  // h = 1/4: the structured channel admits 2h and 4h (= 1, mesh II's own size). The
  // coupling of this fixture contracts slowly on the finer meshes (44 steps on h/2 to
  // thermal.coupling_tolerance): each run gets the steps it needs, not the default 30.
  const std::vector<io::Override> hot_runs = {{"thermal.max_coupling_iterations", "100"}};
  std::vector<io::Override> estimated = hot_runs;
  estimated.insert(estimated.end(), {{"mesh.size", "0.25"}, {"solver.load_error", "\"coarser\""}});
  const io::Case case_ = small_case(estimated, hot_text);
  const post::Results results = app::simulate(case_).results;
  ASSERT_TRUE(results.converged());
  ASSERT_TRUE(results.thermal.coupling_converged);
  const post::LoadErrorEstimate& estimate = results.load_error;
  ASSERT_TRUE(estimate.error.has_value()) << estimate.unavailable;
  EXPECT_EQ(estimate.method, "coarser");
  // Each level is a whole hot run (the thermal stage around its loop), counted per level.
  EXPECT_GT(estimate.coarser_newton_iterations, 0);
  EXPECT_GT(estimate.penalty_newton_iterations, 0);
  // The bar's claim: |p_h − p| ≤ error. The hot run on h/2 is closer to p: with the
  // levels' contraction q the bound's tail is |p_h − p_{h/2}|/(1 − q) ≥ |p_h − p_{h/2}|,
  // so the refined run's load must lie within the bar.
  std::vector<io::Override> refined = hot_runs;
  refined.insert(refined.end(), {{"mesh.size", "0.125"}, {"solver.load_error", "\"none\""}});
  const post::Results finer = app::simulate(small_case(refined, hot_text)).results;
  ASSERT_TRUE(finer.converged());
  EXPECT_LE(std::abs(finer.pressure.ram_reaction - results.pressure.ram_reaction), *estimate.error);
}

TEST(StageComposition, RefinedEstimateSolvesItsLevelsWithTheCoupling) {
  // h = 1/2: its refined mesh h/4 and its third level 2h = 1 are hot runs too; the slow
  // coupling of this fixture gets the steps it needs (44 on h/4).
  const std::vector<io::Override> hot_runs = {{"thermal.max_coupling_iterations", "100"}};
  std::vector<io::Override> estimated = hot_runs;
  estimated.insert(estimated.end(), {{"solver.load_error", "\"refined\""}});
  const post::Results results = app::simulate(small_case(estimated, hot_text)).results;
  ASSERT_TRUE(results.converged());
  const post::LoadErrorEstimate& estimate = results.load_error;
  ASSERT_TRUE(estimate.error.has_value()) << estimate.unavailable;
  EXPECT_EQ(estimate.method, "refined");
  EXPECT_GT(estimate.settle_iterations, 0) << "the refined mesh's hot run";
  EXPECT_TRUE(estimate.coarser_change.has_value()) << "the third level, 2h";
  EXPECT_TRUE(estimate.penalty_change.has_value()) << "the doubled regularisations";
  // The indicators an adaptive cycle marks by: one per cell of the run's mesh.
  ASSERT_EQ(estimate.cell_indicators.size(), results.n_cells);
  EXPECT_TRUE(estimate.cell_indicators.allFinite());
  // The bar's claim |p_h − p| ≤ error, checked against the hot run on h/4 (finer than
  // the estimate's own levels, so not one of the numbers it was made from): with the
  // levels' contraction q, |p_h − p_{h/4}| ≤ |p_h − p| within the model.
  std::vector<io::Override> finest = hot_runs;
  finest.insert(finest.end(), {{"mesh.size", "0.125"}, {"solver.load_error", "\"none\""}});
  const post::Results reference = app::simulate(small_case(finest, hot_text)).results;
  ASSERT_TRUE(reference.converged());
  EXPECT_LE(std::abs(reference.pressure.ram_reaction - results.pressure.ram_reaction),
            *estimate.error);
}

/// The InputError that composing `plan` throws: empty key if none is thrown.
InputError refusal_of(const app::RunPlan& plan) {
  try {
    app::refuse_composition(plan);
  } catch (const InputError& error) {
    return error;
  }
  return InputError("", 0, "", "");
}

TEST(StageComposition, DistributedRowsRefuseByKey) {
  struct Row {
    std::vector<io::Override> overrides;
    std::string key;
    std::string words;
  };
  const std::vector<Row> rows = {
      {{{"solver.linear", "cholmod"}}, "solver.linear", "needs the PETSc back-end"},
      {{{"solver.linear", "petsc"}, {"verification.solution", "smooth"}, {"mesh.size", "0.25"}},
       "verification.solution",
       "solves forming cases only"},
      {{{"solver.linear", "petsc"},
        {"friction.regularization", "none"},
        {"friction.mu", "0.1"},
        {"friction.stick", "exact"}},
       "friction.stick",
       "imposes no exact stick yet"},
  };
  for (const Row& row : rows) {
    app::RunPlan plan = app::make_run_plan(small_case(row.overrides));
    EXPECT_TRUE(refusal_of(plan).key.empty()) << row.key << ": one process runs it";
    plan.stages.ranks = 2; // what main sets on two MPI ranks
    const InputError error = refusal_of(plan);
    EXPECT_EQ(error.key, row.key);
    EXPECT_NE(error.message.find("on 2 MPI ranks"), std::string::npos) << error.message;
    EXPECT_NE(error.message.find(row.words), std::string::npos) << error.message;
    EXPECT_EQ(error.file, "--set") << "located where the key was given";
  }
}

TEST(StageComposition, DistributedComposesWithThermalAndTheEstimate) {
  app::RunPlan plan = app::make_run_plan(
      small_case({{"solver.linear", "petsc"}, {"solver.coarse_levels", "1"}}, hot_text));
  plan.stages.ranks = 2;
  EXPECT_TRUE(refusal_of(plan).key.empty()) << refusal_of(plan).message;
  const std::vector<std::string> names = stage_names(plan);
  EXPECT_TRUE(has_stage(names, "thermal coupling"));
  EXPECT_TRUE(has_stage(names, "error estimate"));
  EXPECT_TRUE(has_stage(names, "coarse start"));
}

} // namespace
} // namespace formflow
