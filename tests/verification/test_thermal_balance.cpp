// SPDX-License-Identifier: MIT
// Hot forming's energy balance (issue 18): with adiabatic tools the convected heat
// out − in is β × the plastic power + share × the friction power, on the paper's
// geometry and through a wedge die; and the discrete heat budget closes.
#include "formflow/app/simulation.hpp"
#include "formflow/io/case.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace formflow {
namespace {

// Pe = ρc u⁰ L/κ = 10/1e-3 = 1e4 over the container length: conduction is a
// 1e-3-length layer, and the sticking ram keeps the plastic zone (x > 2.9, SPEC §4)
// away from the rear end, friction on the die only keeps Γ3's heat there too, so the
// heat conducted back into the billet is nil and all of it is convected. (Heat released
// in the cells at the rear end goes partly into its Dirichlet rows, "conducted": with
// container friction at μ = 0.1 on mesh II that is 1.1e-3 of the total, O(h).) d = 1e-3 leaves ∇·u
// = O(d σ_H), which does not enter: the convected heat is the discrete ∫ ρc u·∇T dx the equations
// balance.
const std::string thermal_text = R"(
[process]
ram = "sticking"
[mesh]
element = "Q1"
size = 1.0
[integration]
volumetric = 1
[friction]
mu = 0.1
on = ["die"]
[thermal]
enabled = true
billet_temperature = 0
tool_temperature = 0
max_temperature = 1000
conductivity = 1e-3
heat_transfer = 0
)";

post::Results run(const std::string& extra) {
  const io::Case case_ = io::load_case_text(thermal_text + extra, "thermal.toml", {});
  app::Simulation simulation = app::simulate(case_);
  EXPECT_TRUE(simulation.results.converged());
  return simulation.results;
}

void expect_balance(const post::Results& results) {
  const post::ThermalResults& thermal = results.thermal;
  ASSERT_TRUE(thermal.enabled);
  // The source is the plastic power's own integrand at the same points and weights:
  // equal up to the round-off of summing ~1e3 terms (1e-12 relative).
  const Real plastic = results.power.plastic_dissipation, friction = results.power.friction;
  EXPECT_NEAR(thermal.deformation, 0.9 * plastic, 1e-12 * plastic);
  EXPECT_NEAR(thermal.friction, 0.5 * friction, 1e-12 * std::max(friction, plastic));
  const Real heat = thermal.deformation + thermal.friction;
  ASSERT_GT(heat, 0.0);
  // The discrete budget (test function 1): exact up to the LU's residual, ~1e-12 of
  // the largest row sums here; 1e-9 relative leaves a margin for any BLAS.
  EXPECT_NEAR(heat, thermal.tools + thermal.free_surfaces + thermal.convected + thermal.conducted,
              1e-9 * heat);
  EXPECT_EQ(thermal.tools, 0.0);
  // The issue's criterion: convected out − in = β P_plastic + share P_friction within 1e-3.
  EXPECT_NEAR(thermal.convected, heat, 1e-3 * heat);
  EXPECT_GT(thermal.max_temperature, 0.0);
  EXPECT_GE(thermal.exit_max, thermal.exit_mean);
  EXPECT_GE(thermal.exit_mean, thermal.exit_min);
}

TEST(ThermalBalance, PaperGeometryAdiabaticTools) {
  const post::Results results = run("");
  expect_balance(results);
  // The load's estimate would solve its other meshes without the heat coupling: the
  // default ("auto") says why instead (docs/error-estimation.md).
  EXPECT_FALSE(results.load_error.error.has_value());
  EXPECT_NE(results.load_error.unavailable.find("hot forming"), std::string::npos)
      << results.load_error.unavailable;
}

TEST(ThermalBalance, WedgeDieAdiabaticTools) {
  expect_balance(run("[geometry]\ndie = \"wedge\"\ndie_angle = 30\n"));
}

TEST(ThermalBalance, AxisymmetricAndQ2) {
  // Per radian (r-weighted integrals) and with the Q2 temperature of a Q2 velocity.
  expect_balance(run("[geometry]\nsymmetry = \"axisymmetric\"\n"));
  const io::Case q2 = io::load_case_text(thermal_text, "thermal.toml",
                                         {{"mesh.element", "Q2"}, {"integration.volumetric", "2"}});
  expect_balance(app::simulate(q2).results);
}

TEST(ThermalBalance, ToolsTakeHeatAndTheBudgetCloses) {
  // Cold tools (T_tool < T_billet): heat flows out through Γ3 (tools > 0) and the
  // workpiece leaves cooler on average than the adiabatic run's exit.
  const post::Results adiabatic = run("");
  io::Case case_ =
      io::load_case_text(thermal_text, "thermal.toml",
                         {{"thermal.heat_transfer", "0.05"}, {"thermal.tool_temperature", "-1"}});
  const post::Results results = app::simulate(case_).results;
  EXPECT_GT(results.thermal.tools, 0.0);
  const post::ThermalResults& t = results.thermal;
  EXPECT_NEAR(t.deformation + t.friction, t.tools + t.free_surfaces + t.convected + t.conducted,
              1e-9 * (t.deformation + t.friction + std::abs(t.tools)));
  EXPECT_LT(t.exit_mean, adiabatic.thermal.exit_mean);
}

} // namespace
} // namespace formflow
