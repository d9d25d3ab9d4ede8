// SPDX-License-Identifier: MIT
// Triangles against the referees (issue 39): the sticking ram's slip-line load
// (1 + π/2) k by extrapolation, the paper's benchmark converging to the quadrilaterals'
// limit, and ram reaction = total power on every pair of elements.
#include "formflow/app/simulation.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/io/case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace formflow {
namespace {

constexpr Real slip_line_load = 1.0 + std::numbers::pi / 2.0; // (1 + π/2) k, SPEC §4

/// The case file `case_file` (empty: the embedded benchmark) with `overrides` at
/// mesh.size `size`, no load error estimate (the referees here are the loads themselves).
app::Simulation solve(std::vector<io::Override> overrides, Real size,
                      const std::string& case_file = "") {
  overrides.emplace_back("mesh.size", std::to_string(size));
  overrides.emplace_back("solver.load_error", "\"none\"");
  return app::simulate(io::load_case(case_file, overrides));
}

/// The relative distance of the final iterate to the fixed point the loop converges to,
/// estimated from its last changes c_k: at a contraction ρ (the geometric mean ratio of
/// the last five) the remaining steps sum to c_n ρ/(1 − ρ). At least the stop's δ.
Real remaining_iteration_error(const post::Results& results, Real tolerance) {
  const auto& history = results.history;
  if (history.size() < 6) return tolerance;
  const Real last = history.back().relative_change;
  const Real earlier = history[history.size() - 6].relative_change;
  const Real rate = std::pow(last / earlier, 1.0 / 5.0);
  if (!(rate < 1.0)) return tolerance;
  return std::max(tolerance, last * rate / (1.0 - rate));
}

/// Every run's ram reaction (the consistent reaction K_c·u) equals its total discrete
/// power at the fixed point; at the final iterate they differ by what the remaining
/// iterations would change: twice its relative distance (the power is quadratic in u,
/// the reaction linear).
void expect_reaction_is_power(const app::Simulation& run, const std::string& what) {
  ASSERT_TRUE(run.results.converged()) << what;
  const Real tolerance = io::load_case("", {}).solver.tolerance;
  const Real distance = remaining_iteration_error(run.results, tolerance);
  const auto& pressure = run.results.pressure;
  EXPECT_LE(std::abs(pressure.ram_reaction - pressure.total_power),
            2.0 * distance * pressure.total_power)
      << what;
}

/// Ram pressures on h = 1, 1/2, 1/4, and their Richardson limit P₃ + (P₃ − P₂)/(2^q − 1)
/// at the observed order q = log₂((P₁ − P₂)/(P₂ − P₃)).
struct Ladder {
  std::array<Real, 3> load{};
  Real order = 0.0, limit = 0.0;
};

Ladder ladder(const std::vector<io::Override>& overrides, const std::string& what,
              const std::string& case_file = "", Real coarsest = 1.0) {
  Ladder result;
  const std::array<Real, 3> sizes = {coarsest, coarsest / 2, coarsest / 4};
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const app::Simulation run = solve(overrides, sizes[k], case_file);
    expect_reaction_is_power(run, what + " h = " + std::to_string(sizes[k]));
    result.load[k] = run.results.pressure.ram_reaction;
  }
  const auto& p = result.load;
  result.order = std::log2((p[0] - p[1]) / (p[1] - p[2]));
  result.limit = p[2] + (p[2] - p[1]) / (std::exp2(result.order) - 1.0);
  std::printf("%s: %.5f %.5f %.5f, order %.3f, limit %.5f\n", what.c_str(), p[0], p[1], p[2],
              result.order, result.limit);
  return result;
}

TEST(SimplexReferees, StickingRamOnTrianglesExtrapolatesToTheSlipLineLoad) {
  const Ladder triangles =
      ladder({{"mesh.cell", "\"triangle\""}, {"process.ram", "\"sticking\""}}, "P2+-P1disc");
  // Upper bounds falling towards the limit: the discrete velocity is kinematically
  // admissible, so its power bounds the rigid-plastic load from above (SPEC §4).
  EXPECT_GT(triangles.load[2], slip_line_load);
  EXPECT_LT(triangles.load[2], triangles.load[1]);
  // Issue 39's bound: within 0.5 % of (1 + π/2) k by extrapolation.
  EXPECT_LT(std::abs(triangles.limit / slip_line_load - 1.0), 5e-3);
}

TEST(SimplexReferees, BenchmarkOnTrianglesConvergesToTheQuadrilateralsLimit) {
  const Ladder triangles = ladder({{"mesh.cell", "\"triangle\""}}, "triangles P2+-P1disc");
  const Ladder quadrilaterals = ladder({}, "quadrilaterals Q2");
  // Different elements, one limit: the extrapolated loads agree to a tenth of the finest
  // rung's own discretisation error (what extrapolation removed; its higher-order
  // remainder at h = 1/4 is smaller than that).
  const Real quadrilateral_error = quadrilaterals.load[2] - quadrilaterals.limit;
  EXPECT_GT(quadrilateral_error, 0.0);
  EXPECT_LT(std::abs(triangles.limit - quadrilaterals.limit), 0.1 * quadrilateral_error);
}

TEST(SimplexReferees, AxisymmetricTrianglesAndMixedConvergeToThePenaltyLimit) {
  // The conical-die rod (30°, 50 % reduction, μ = 0.05 on the die): the mixed
  // formulation's divergence with its hoop rate, on quadrilaterals and triangles, against
  // the Q2 penalty's extrapolated load, to a tenth of that ladder's finest-rung error.
  const std::string rod = FORMFLOW_SOURCE_DIR "/cases/conical-die-rod-extrusion.toml";
  const Ladder penalty = ladder({}, "axisymmetric Q2 penalty", rod, 0.25);
  const Real bound = 0.1 * (penalty.load[2] - penalty.limit);
  EXPECT_GT(bound, 0.0);
  const std::vector<std::pair<std::string, std::vector<io::Override>>> pairs = {
      {"axisymmetric Q2-P1disc", {{"formulation.type", "\"mixed\""}}},
      {"axisymmetric P2+-P1disc", {{"mesh.cell", "\"triangle\""}, {"mesh.element", "\"P2\""}}},
      {"axisymmetric P2-P1",
       {{"mesh.cell", "\"triangle\""},
        {"mesh.element", "\"P2\""},
        {"formulation.pressure", "\"P1\""}}}};
  for (const auto& [name, overrides] : pairs)
    EXPECT_LT(std::abs(ladder(overrides, name, rod, 0.25).limit - penalty.limit), bound) << name;
}

/// ∫ σ_H dV from the cells' means of σ_H and their areas.
Real hydrostatic_integral(const app::Simulation& run) {
  const mesh::Mesh<2>& mesh = run.plane_mesh();
  fem::CellValues<2> values(mesh.cell_type(), fem::full_rule<2>(mesh.cell_type()));
  fem::CellValues<2>::Gradients coordinates(2, mesh.nodes_per_cell());
  Real integral = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    values.reinit(coordinates);
    Real area = 0.0;
    for (int q = 0; q < values.n_points(); ++q) area += values.JxW(q);
    integral += area * run.results.fields.cell_hydrostatic_stress[cell];
  }
  return integral;
}

TEST(SimplexReferees, TheFluxBalanceIsThePenaltysCompressibility) {
  // What leaves through the exit, the free surfaces and the walls, less what enters, is
  // ∫ div u dV = d ∫ σ_H dV (the penalty's σ_H = ε̇_V/d, the mixed pressure's
  // B u = d M c): the flux balance is the material's compressibility and the leaks.
  for (const std::string cell : {"quadrilateral", "triangle"}) {
    const app::Simulation run = solve({{"mesh.cell", "\"" + cell + "\""}}, 1.0);
    const post::ExitFlow& flow = run.results.exit;
    ASSERT_TRUE(flow.present) << cell;
    const Real outflow = flow.exit_flux - flow.entry_flux + flow.free_surface_flux + flow.wall_flux;
    const Real d = io::load_case("", {}).penalty.d;
    const Real compressibility = d * hydrostatic_integral(run);
    std::printf("%s: flux balance %.6f, net outflow %.6e, d ∫σ_H %.6e, free %.3e, walls %.3e\n",
                cell.c_str(), flow.flux_balance, outflow, compressibility, flow.free_surface_flux,
                flow.wall_flux);
    // Both sides are exact integrals of polynomials on these straight-sided cells (the
    // face and full rules, the reduced rule of Q2's penalty being exact for its biquadratic
    // div u): they differ by the round-off of ~10³ summed terms, far below 1e-9 of the flux.
    EXPECT_NEAR(outflow, compressibility, 1e-9 * flow.entry_flux) << cell;
  }
}

TEST(SimplexReferees, TaylorHoodAndMiniElementRunWithReactionEqualToPower) {
  // P2–P1 (Taylor–Hood) and P1b–P1 (MINI) solve the continuous pressure as a saddle
  // point. MINI is first order in the velocity gradient: its error at least nearly halves
  // from h = 1 to 1/2 (order ≥ 0.8 on this singular problem, whose loads converge at
  // order 1 on every pair: docs/verification.md).
  const app::Simulation taylor_hood =
      solve({{"mesh.cell", "\"triangle\""}, {"formulation.pressure", "\"P1\""}}, 0.5);
  expect_reaction_is_power(taylor_hood, "P2-P1");
  const Real p1disc = solve({{"mesh.cell", "\"triangle\""}}, 0.5).results.pressure.ram_reaction;
  const Real p1disc_finer =
      solve({{"mesh.cell", "\"triangle\""}}, 0.25).results.pressure.ram_reaction;
  // Both pairs approximate the same load from above: they differ by less than
  // P2+–P1disc's own change from h = 1/2 to 1/4 (at first order, half its error at 1/2).
  EXPECT_LT(std::abs(taylor_hood.results.pressure.ram_reaction - p1disc), p1disc - p1disc_finer);
  const std::vector<io::Override> mini = {
      {"mesh.cell", "\"triangle\""}, {"mesh.element", "\"P1b\""}, {"process.ram", "\"sticking\""}};
  const app::Simulation coarse = solve(mini, 1.0), fine = solve(mini, 0.5);
  expect_reaction_is_power(coarse, "P1b h = 1");
  expect_reaction_is_power(fine, "P1b h = 1/2");
  const Real coarse_error = coarse.results.pressure.ram_reaction - slip_line_load;
  const Real fine_error = fine.results.pressure.ram_reaction - slip_line_load;
  std::printf("P1b-P1 sticking ram: %.5f, %.5f\n", coarse.results.pressure.ram_reaction,
              fine.results.pressure.ram_reaction);
  EXPECT_GT(fine_error, 0.0);
  EXPECT_LT(fine_error, std::exp2(-0.8) * coarse_error);
}

} // namespace
} // namespace formflow
