// SPDX-License-Identifier: MIT
// The load's error estimate (docs/error-estimation.md) on the coarse rungs of the
// sticking-ram benchmark and Hill's wedge drawing, against their exact loads.
#include "benchmark_support.hpp"
#include "support/angles.hpp"
#include "support/forming_references.hpp"

#include "formflow/app/load_error.hpp"
#include "formflow/io/results_writer.hpp"
#include "formflow/post/load_error_estimate.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <vector>

namespace formflow::testing {
namespace {

/// The effectivity band: the issue's [0.5, 3]. What the estimate's construction
/// gives (docs/error-estimation.md): F_s |p_{h/2} − p_h| / (1 − q) with F_s = 1.25
/// and q ≥ ½ the larger of first order and the observed contraction, plus the
/// penalties' offset. For a load converging at order r′ ∈ [½, 1] with the observed q
/// its own, the tail part alone is F_s times the true discretisation error times
/// (1 + ε), ε the relative error of the refined change (the independent check below
/// holds it within 15 %); the penalty part adds at most the offset it estimates,
/// itself part of the true error. So the index lies in [1.25 · 0.85, 1.25 · 1.15 + 1]
/// = [1.06, 2.44] ⊂ [0.5, 3]; the band asserted is the issue's, wider than that.
constexpr double min_effectivity = 0.5, max_effectivity = 3.0;

io::Case sticking_ram(double size) {
  io::Case case_;
  case_.process.ram = physics::RamCondition::Sticking;
  case_.material.parameters_of<physics::PiecewisePower>().alpha = 1e-4;
  case_.penalty.d = 1e-4;
  case_.mesh.size = size;
  case_.solver.load_error = solvers::LoadErrorMethod::Refined;
  return case_;
}

io::Case hill_drawing(double degrees, double size) {
  io::Case case_;
  case_.process.type = physics::ProcessType::Drawing;
  const double r = hill_special_reduction(degrees * degree);
  case_.mesh.geometry = mesh::ChannelGeometry{2.0, 1.0, 1.0 - r, 2.0};
  case_.mesh.geometry.die = mesh::DieShape::Wedge;
  case_.mesh.geometry.die_angle = degrees;
  case_.mesh.size = size;
  case_.material.parameters_of<physics::PiecewisePower>().alpha = 1e-4;
  case_.solver.load_error = solvers::LoadErrorMethod::Refined;
  return case_;
}

/// Effectivity of the run's estimate against `exact`, with the estimate's own checks.
double effectivity(const post::Results& results, double exact) {
  EXPECT_TRUE(results.converged());
  const post::LoadErrorEstimate& estimate = results.load_error;
  EXPECT_TRUE(estimate.error.has_value()) << estimate.unavailable;
  if (!estimate.error) return 0.0;
  // A kinematic approximation: refining lowers the load (the discrete load lies above).
  EXPECT_LT(estimate.enriched_change, 0.0);
  EXPECT_GT(results.pressure.ram_reaction, exact);
  // One indicator per cell; that their sum is the refined change is the estimate's
  // definition (bookkeeping only): the check against an independent refined run is
  // expect_indicators_sum_to_the_refined_runs_change below.
  EXPECT_EQ(estimate.cell_indicators.size(), results.n_cells);
  EXPECT_NEAR(estimate.cell_indicators.sum(), estimate.enriched_change,
              1e-12 * estimate.cell_indicators.cwiseAbs().sum());
  EXPECT_TRUE(estimate.penalty_change.has_value());
  return *estimate.error / std::abs(results.pressure.ram_reaction - exact);
}

/// The effectivity within [min_effectivity, max_effectivity] and the interval
/// p_h ± estimate around `exact` (Hill's wedge at `degrees`).
void expect_effective_and_containing(const post::Results& results, double exact, double degrees) {
  const double index = effectivity(results, exact);
  EXPECT_GE(index, min_effectivity) << degrees << "°";
  EXPECT_LE(index, max_effectivity) << degrees << "°";
  ASSERT_TRUE(results.load_error.error.has_value());
  EXPECT_LE(std::abs(results.pressure.ram_reaction - exact), *results.load_error.error)
      << degrees << "°: p_h = " << results.pressure.ram_reaction << ", exact " << exact;
}

TEST(LoadErrorEstimate, StickingRamCoarseRungIsEffective) {
  // Exact (1 + π/2) k, k = 1 (SPEC §4); h = 1: 1 322 dofs, 5 042 on the refined mesh.
  const double exact = 1.0 + std::numbers::pi / 2.0;
  // Every solve of the run reaches its callback, the estimate's under their stages (a
  // monitor shows what runs during the estimate; a stop signal is checked there).
  std::map<std::string, int> records;
  const auto count = [&records](const solvers::IterationRecord& record) {
    ++records[record.stage];
  };
  const post::Results results = app::simulate(sticking_ram(1.0), count).results;
  EXPECT_EQ(records[""], results.iterations);
  EXPECT_EQ(records["error estimate: the mesh refined once, 5042 dofs"],
            results.load_error.settle_iterations);
  EXPECT_EQ(records["error estimate: the regularisations doubled, 1322 dofs"],
            results.load_error.penalty_newton_iterations);
  // The third level (h/4, mesh II has no 2h), named with its own dofs.
  const std::string third = "error estimate: the third level, the mesh refined twice, ";
  const auto third_level = records.lower_bound(third);
  ASSERT_NE(third_level, records.end());
  EXPECT_EQ(third_level->first.rfind(third, 0), 0u) << third_level->first;
  EXPECT_GT(third_level->second, 0);
  EXPECT_EQ(records.size(), 4u);
  const double index = effectivity(results, exact);
  EXPECT_GE(index, min_effectivity);
  EXPECT_LE(index, max_effectivity);
  // Reliability: the interval p_h ± estimate holds the exact load. Here 2 |p_{1/2} −
  // p_1| (first order) is the error to 1e-4; the safety factor adds a quarter of it
  // and the regularisations' offset (α, d: −3.9e-4) another 0.15 %
  // (docs/error-estimation.md).
  ASSERT_TRUE(results.load_error.error.has_value());
  EXPECT_LE(std::abs(results.pressure.ram_reaction - exact), *results.load_error.error)
      << "p_h = " << results.pressure.ram_reaction << ", exact " << exact;
  // The bar is F_s times the tail plus the regularisations' offset, and the summary
  // says which factor was used.
  const post::LoadErrorEstimate& estimate = results.load_error;
  // Mesh II at h = 1 admits no 2h: the third level is h/4, and the ratio observed
  // there is first order (0.4996 measured), so q = ½ as the argument assumes.
  EXPECT_TRUE(estimate.finer_change.has_value());
  EXPECT_EQ(estimate.ratio, std::max(0.5, estimate.observed_ratio.value_or(0.0)));
  EXPECT_DOUBLE_EQ(estimate.discretisation_error,
                   1.25 * std::abs(estimate.enriched_change) / (1.0 - estimate.ratio));
  EXPECT_DOUBLE_EQ(*estimate.error,
                   estimate.discretisation_error + std::abs(*estimate.penalty_change));
  const std::string summary = io::summary_json(sticking_ram(1.0), results);
  EXPECT_NE(summary.find("\"safety_factor\": 1.25"), std::string::npos);
}

TEST(LoadErrorEstimate, HillWedgeDrawingOneRowRungsUseTheFinerThirdLevel) {
  // h = 1: one row of cells across the exit, 66 (30°) and 78 (15°) dofs, and lengths
  // that admit no 2h. Until session 11 the order was assumed there (q = ½), and the
  // 30° rung missed Hill's value by 2 % of its error: its next ratio is 0.72, far
  // above ½ (one row across the exit is pre-asymptotic). Roache's two-grid factor
  // F_s = 3 would hold it (effectivity 2.34) but puts the first-order sticking ram's
  // h = 1 at 3.0004, outside [0.5, 3] (docs/error-estimation.md, "The two-grid
  // factor"). Instead the third level is h/4, and the ratio (p_{1/4} − p_{1/2}) /
  // (p_{1/2} − p_1) observed there sums the tail. Why that contains the exact value:
  // the tail after p_{1/2} contracts by the later ratios of the converged ladders,
  // at most 0.576 (step 5 (iv)), below the one observed here, so the geometric sum
  // with the observed q is at least the true tail even before F_s.
  for (double degrees : {15.0, 30.0}) {
    const post::Results results = app::simulate(hill_drawing(degrees, 1.0)).results;
    const post::LoadErrorEstimate& estimate = results.load_error;
    ASSERT_TRUE(estimate.finer_change.has_value()) << degrees << "°";
    EXPECT_FALSE(estimate.coarser_change.has_value()) << degrees << "°";
    ASSERT_TRUE(estimate.observed_ratio.has_value()) << degrees << "°";
    EXPECT_DOUBLE_EQ(*estimate.observed_ratio, *estimate.finer_change / estimate.enriched_change);
    EXPECT_EQ(estimate.ratio, std::max(0.5, *estimate.observed_ratio));
    expect_effective_and_containing(results, hill_wedge_stress(degrees * degree), degrees);
  }
}

TEST(LoadErrorEstimate, HillWedgeDrawingCoarseRungsAreEffective) {
  // Hill's slip-line drawing stress 2k(1 + α) r (docs/validation.md), 4 rows. The
  // channel admits 2h = 1/2: the ratio is the observed one where it is above ½.
  // These are the rungs where the tail without the safety factor missed Hill's value
  // by 2 % of the error: the loads converge to it (HillWedgeLaddersBracketHillsValue
  // below), but the ratio observed on 1/2, 1/4, 1/8 (0.517, 0.536) is below the mean
  // ratio of the tail that follows (0.527, 0.545 needed; docs/error-estimation.md,
  // step 5 (iv)). With F_s = 1.25 the estimate covers a mean tail ratio up to
  // 1 − (1 − q)/F_s = 0.614 (15°) and 0.629 (30°); every ratio on the ladders to
  // h = 1/64 is at most 0.576. So containment is asserted here.
  for (double degrees : {15.0, 30.0}) {
    const post::Results results = app::simulate(hill_drawing(degrees, 0.25)).results;
    const post::LoadErrorEstimate& estimate = results.load_error;
    ASSERT_TRUE(estimate.observed_ratio.has_value()) << degrees << "°";
    EXPECT_EQ(estimate.ratio, std::max(0.5, *estimate.observed_ratio));
    expect_effective_and_containing(results, hill_wedge_stress(degrees * degree), degrees);
  }
}

/// The drawing stress of `hill_drawing(degrees, size)`, no estimate, Newton to δ = 1e-8
/// (its load then agrees with δ = 1e-10 to 1e-7 on these meshes), optionally with d,
/// d_N and α doubled.
double converged_drawing_stress(double degrees, double size, bool doubled = false) {
  io::Case case_ = hill_drawing(degrees, size);
  case_.solver.load_error = solvers::LoadErrorMethod::None;
  case_.solver.tolerance = 1e-8;
  if (doubled) {
    case_.penalty.d *= 2;
    case_.penalty.d_n *= 2;
    case_.material.parameters_of<physics::PiecewisePower>().alpha *= 2;
  }
  const post::Results results = app::simulate(case_).results;
  EXPECT_TRUE(results.converged());
  return results.pressure.ram_reaction; // the front reaction over its height in drawing
}

TEST(LoadErrorEstimate, HillWedgeLaddersBracketHillsValue) {
  // The wedges' discrete loads converge to Hill's value. Session 9 read 0.3–0.4 %
  // above it off a secant ladder stopped early (docs/validation.md, "What the wedge
  // ladders converge to"). On the rungs 1/4, 1/8, 1/16 the differences shrink by
  // q > ½ and keep shrinking by ratios between ½ and q (the ladders to 1/64: 15°
  // 0.534, 0.526, 0.522; 30° 0.576, 0.517, 0.517). So the limit lies between the
  // tails summed from p_{1/16} with ½ and with q. That is the limit of the
  // regularised problem: widen by its first-order offset |p(2ε) − p(ε)| (doubled d,
  // d_N, α on 1/16). At 15° an offset of 0.3 % (0.0026) would put Hill's value
  // outside: the bracket's lower side clears it by 0.0012 (at 30°, q = 0.576, by 0.0099).
  for (double degrees : {15.0, 30.0}) {
    const double coarse = converged_drawing_stress(degrees, 0.25);
    const double middle = converged_drawing_stress(degrees, 0.125);
    const double fine = converged_drawing_stress(degrees, 0.0625);
    const double change = fine - middle;
    const double ratio = change / (middle - coarse);
    ASSERT_GT(ratio, 0.0) << degrees << "°";
    ASSERT_LT(ratio, 1.0) << degrees << "°";
    const auto limit = [&](double q) { return fine + change * q / (1.0 - q); };
    const double regularisations = std::abs(converged_drawing_stress(degrees, 0.0625, true) - fine);
    const double exact = hill_wedge_stress(degrees * degree);
    EXPECT_GE(exact, std::min(limit(0.5), limit(ratio)) - regularisations) << degrees << "°";
    EXPECT_LE(exact, std::max(limit(0.5), limit(ratio)) + regularisations) << degrees << "°";
  }
}

/// Σ η_K against the refined mesh's own load, solved directly (a converged run on
/// the case at mesh.size / 2, the very mesh the estimate refines to): an
/// independent p_{h/2} − p_h, not the DWR sum under another name. The band above
/// assumes the refined change within ε = 15 % of the true one; this checks it.
void expect_indicators_sum_to_the_refined_runs_change(const io::Case& coarse_case) {
  const post::Results coarse = app::simulate(coarse_case).results;
  io::Case fine_case = coarse_case;
  fine_case.mesh.size /= 2;
  fine_case.solver.load_error = solvers::LoadErrorMethod::None;
  const post::Results fine = app::simulate(fine_case).results;
  ASSERT_TRUE(coarse.converged() && fine.converged());
  ASSERT_TRUE(coarse.load_error.error.has_value()) << coarse.load_error.unavailable;
  const double direct = fine.pressure.ram_reaction - coarse.pressure.ram_reaction;
  EXPECT_EQ(coarse.load_error.enriched_dofs, fine.n_dofs) << "the same refined mesh";
  EXPECT_NEAR(coarse.load_error.cell_indicators.sum(), direct, 0.15 * std::abs(direct))
      << "direct p_{h/2} - p_h = " << direct;
}

TEST(LoadErrorEstimate, StickingRamIndicatorsSumToTheRefinedRunsChange) {
  expect_indicators_sum_to_the_refined_runs_change(sticking_ram(1.0));
}

TEST(LoadErrorEstimate, WedgeIndicatorsSumToTheRefinedRunsChange) {
  expect_indicators_sum_to_the_refined_runs_change(hill_drawing(15.0, 0.25));
}

TEST(LoadErrorEstimate, CoulombFrictionIndicatorsSumToTheRefinedRunsChange) {
  // μ = 0.1 on the container and the die: the adjoint now carries the transpose of
  // dτ_f through the mollified contact pressure (FormingProblem::apply_coupling_transpose).
  io::Case case_ = sticking_ram(1.0);
  case_.friction.mu = 0.1;
  expect_indicators_sum_to_the_refined_runs_change(case_);
}

TEST(LoadErrorEstimate, TailRatioIsTheSlowerOfFirstOrderAndTheObserved) {
  EXPECT_EQ(post::tail_ratio(std::nullopt), 0.5);   // no third level: r = 1
  EXPECT_EQ(post::tail_ratio(0.3), 0.5);            // faster than first order observed
  EXPECT_EQ(post::tail_ratio(0.6), 0.6);            // slower: the observed ratio
  EXPECT_FALSE(post::tail_ratio(1.2).has_value());  // no contraction: no tail
  EXPECT_FALSE(post::tail_ratio(-0.4).has_value()); // oscillating levels
  // F_s |Δ|/(1 − q) + |penalty|: F_s = 1.25, q = 0.6, Δ = −0.04, penalty +0.003 →
  // 1.25 · 0.1 + 0.003; beyond the refined mesh the tail is q times that part.
  EXPECT_EQ(post::grid_convergence_safety_factor, 1.25);
  EXPECT_DOUBLE_EQ(post::discretisation_tail(-0.04, 0.6), 0.125);
  EXPECT_DOUBLE_EQ(post::load_error_bound(-0.04, 0.6, 0.003), 0.128);
  EXPECT_DOUBLE_EQ(post::tail_beyond_refined(-0.04, 0.6), 0.075);
}

TEST(LoadErrorEstimate, CoarserLevelsContainHillsValue) {
  // solver.load_error = "coarser" (the default where the channel admits 2h and 4h):
  // F_s |p_h − p_{2h}| q/(1 − q) + |p_{2h}(2ε) − p_{2h}(ε)|, q = max(½, observed on 4h,
  // 2h, h). h = 1/4 is the rung whose 4h = 1 has one row of cells across the exit: the
  // most pre-asymptotic ratio of the reliability table (30°: 0.726, effectivity 2.82;
  // docs/error-estimation.md, "An estimate on every run"). Why it contains Hill's
  // value: the ratios after it on the converged ladders are at most 0.576, below the
  // observed q, so the geometric tail with q is at least the true one before F_s.
  for (double degrees : {15.0, 30.0}) {
    io::Case case_ = hill_drawing(degrees, 0.25);
    case_.solver.load_error = solvers::LoadErrorMethod::Coarser;
    const post::Results results = app::simulate(case_).results;
    ASSERT_TRUE(results.converged());
    const post::LoadErrorEstimate& estimate = results.load_error;
    ASSERT_TRUE(estimate.error.has_value()) << estimate.unavailable;
    EXPECT_EQ(estimate.method, "coarser");
    ASSERT_TRUE(estimate.coarser_change && estimate.coarsest_change && estimate.observed_ratio);
    // A kinematic approximation: each coarser level's load lies above.
    EXPECT_LT(*estimate.coarser_change, 0.0) << degrees << "°";
    EXPECT_LT(*estimate.coarsest_change, 0.0) << degrees << "°";
    EXPECT_DOUBLE_EQ(*estimate.observed_ratio,
                     *estimate.coarser_change / *estimate.coarsest_change);
    EXPECT_EQ(estimate.ratio, std::max(0.5, *estimate.observed_ratio));
    // The bar from its parts (the rule itself is checked on numbers below,
    // CoarserLevelsBoundIsTheTailBeyondTheRun).
    ASSERT_TRUE(estimate.penalty_change.has_value());
    EXPECT_EQ(*estimate.error, post::coarser_levels_bound(*estimate.coarser_change, estimate.ratio,
                                                          *estimate.penalty_change));
    EXPECT_EQ(estimate.enriched_dofs, 0) << "no mesh finer than the run's";
    // The cell indicators (the adjoint on the run's mesh, weighted residuals of u_h and
    // u_2h) sum to the solved p_h − p_2h up to the two levels' iteration errors: each
    // Newton solve stops after a change below δ with a contraction of at most 0.7
    // (docs/error-estimation.md), so its velocity is within δ 0.7/0.3 < 2.5 δ of the
    // discrete solution and its load, nearly homogeneous in u, within 2.5 δ |p|.
    ASSERT_EQ(estimate.cell_indicators.size(), results.n_cells);
    const double delta = case_.solver.tolerance;
    EXPECT_NEAR(estimate.cell_indicators.sum(), *estimate.coarser_change,
                2 * 2.5 * delta * std::abs(results.pressure.ram_reaction))
        << degrees << "°";
    EXPECT_GT(estimate.coarser_newton_iterations, 0);
    const double exact = hill_wedge_stress(degrees * degree);
    const double index = *estimate.error / std::abs(results.pressure.ram_reaction - exact);
    EXPECT_GE(index, min_effectivity) << degrees << "°";
    EXPECT_LE(index, max_effectivity) << degrees << "°";
    EXPECT_LE(std::abs(results.pressure.ram_reaction - exact), *estimate.error)
        << degrees << "°: p_h = " << results.pressure.ram_reaction << ", exact " << exact;
    const std::string summary = io::summary_json(case_, results);
    EXPECT_NE(summary.find("\"method\": \"coarser\""), std::string::npos);
  }
  // h = 1/2: 2h = 1 exists but 4h does not; q = ½ assumed there failed (30°: 0.196
  // against an error of 0.2475), so "coarser" is refused with the reason.
  io::Case unfit = hill_drawing(30.0, 0.5);
  unfit.solver.load_error = solvers::LoadErrorMethod::Coarser;
  const post::Results results = app::simulate(unfit).results;
  EXPECT_FALSE(results.load_error.error.has_value());
  EXPECT_NE(results.load_error.unavailable.find("2h and 4h"), std::string::npos)
      << results.load_error.unavailable;
}

/// Hill's 15° wedge at h = 1/4 read as the CLI reads it (io::load_case_text resolves
/// the solve plan), with `extra` overrides.
io::Case hill_drawing_read(std::vector<io::Override> extra) {
  const double r = hill_special_reduction(15.0 * degree);
  std::vector<io::Override> overrides = {{"process.type", "drawing"},
                                         {"geometry.die", "wedge"},
                                         {"geometry.die_angle", "15"},
                                         {"geometry.entry_half_height", "1"},
                                         {"geometry.container_length", "2"},
                                         {"geometry.exit_length", "2"},
                                         {"geometry.exit_half_height", fmt::format("{}", 1.0 - r)},
                                         {"material.alpha", "1e-4"},
                                         {"mesh.element", "Q2"},
                                         {"mesh.size", "0.25"}};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return io::load_case_text("", "wedge.toml", overrides);
}

TEST(LoadErrorEstimate, CoarserLevelsBoundIsTheTailBeyondTheRun) {
  // F_s |Δ| q/(1 − q) + |Δ_ε| with F_s = 1.25: Δ = −0.04, q = 0.6, Δ_ε = 0.003 gives
  // 1.25 · 0.04 · 1.5 + 0.003 = 0.078; with q = ½ the tail is F_s |Δ|: 0.025 + 0.001.
  // Rounding: the three decimal inputs and the expected value are each within half an
  // ulp, and five operations round once each on intermediates of at most twice the
  // result (0.125 here); the error 1/(1 − q) ≤ 2.5 amplifies stays below 16 ulps of it.
  const auto within_rounding = [](double expected) {
    return 16 * std::numeric_limits<double>::epsilon() * expected;
  };
  EXPECT_NEAR(post::coarser_levels_bound(-0.04, 0.6, 0.003), 0.078, within_rounding(0.078));
  EXPECT_NEAR(post::coarser_levels_bound(0.02, 0.5, -0.001), 0.026, within_rounding(0.026));
}

TEST(LoadErrorEstimate, CoarserLevelsReachTheLoopsNewtonDoesNot) {
  // Exact incompressibility (mixed, d = 0: Uzawa steps around the secant loop) has no
  // Newton tangent, so no refined estimate; "coarser" solves its levels by the run's own
  // loop. Hill's value is the referee: the same argument as the penalty's (the tail
  // with q ≥ every later ratio of the ladders), and no d to double (α and d_N are).
  const io::Case exact = hill_drawing_read({{"formulation.type", "mixed"}, {"penalty.d", "0"}});
  const post::Results results = app::simulate(exact).results;
  ASSERT_TRUE(results.converged());
  const post::LoadErrorEstimate& estimate = results.load_error;
  ASSERT_TRUE(estimate.error.has_value()) << estimate.unavailable;
  EXPECT_EQ(estimate.method, "coarser") << "auto, the channel admits 2h and 4h";
  ASSERT_TRUE(estimate.coarser_change && estimate.coarsest_change && estimate.penalty_change);
  EXPECT_DOUBLE_EQ(*estimate.error,
                   post::coarser_levels_bound(*estimate.coarser_change, estimate.ratio,
                                              *estimate.penalty_change));
  const double hill = hill_wedge_stress(15.0 * degree);
  const double index = *estimate.error / std::abs(results.pressure.ram_reaction - hill);
  EXPECT_GE(index, min_effectivity);
  EXPECT_LE(index, max_effectivity);
  EXPECT_LE(std::abs(results.pressure.ram_reaction - hill), *estimate.error)
      << "p_h = " << results.pressure.ram_reaction << ", Hill " << hill;
  // Exact Coulomb friction (semismooth Newton with its multipliers): computed too, its
  // levels by the augmented loop (no referee with friction: only that it is there and
  // is the bound of its levels).
  const io::Case friction = hill_drawing_read(
      {{"friction.mu", "0.1"}, {"friction.law", "coulomb"}, {"friction.regularization", "none"}});
  const post::Results rough = app::simulate(friction).results;
  ASSERT_TRUE(rough.converged());
  ASSERT_TRUE(rough.load_error.error.has_value()) << rough.load_error.unavailable;
  EXPECT_EQ(rough.load_error.method, "coarser");
  EXPECT_GT(rough.load_error.coarser_newton_iterations, 0);
  EXPECT_DOUBLE_EQ(*rough.load_error.error,
                   post::coarser_levels_bound(*rough.load_error.coarser_change,
                                              rough.load_error.ratio,
                                              *rough.load_error.penalty_change));
}

TEST(LoadErrorEstimate, AutoTakesTheCheapestReliableEstimate) {
  // The default resolves per mesh (app/load_error.hpp): the coarser levels where the
  // structured channel admits 2h and 4h, else the refined mesh while it is small.
  io::Case case_ = hill_drawing(15.0, 0.25);
  case_.solver.load_error = solvers::LoadErrorMethod::Auto;
  EXPECT_EQ(io::Case{}.solver.load_error, solvers::LoadErrorMethod::Auto) << "the default";
  std::string why;
  EXPECT_EQ(app::resolved_load_error_method(case_, true, 2, 810, why),
            solvers::LoadErrorMethod::Coarser);
  // Not the case's own mesh (an adaptive cycle's, a file): refined up to the limit
  // of refined dofs, 2^dim times the run's, then none with the reason.
  const Index limit = app::auto_refined_dofs_limit(2);
  EXPECT_EQ(app::resolved_load_error_method(case_, false, 2, limit / 4, why),
            solvers::LoadErrorMethod::Refined);
  EXPECT_EQ(app::resolved_load_error_method(case_, false, 2, limit / 4 + 1, why),
            solvers::LoadErrorMethod::None);
  EXPECT_NE(why.find("\"refined\""), std::string::npos) << why;
  const Index solid_limit = app::auto_refined_dofs_limit(3);
  EXPECT_LT(solid_limit, limit) << "a hexahedral factor fills more";
  EXPECT_EQ(app::resolved_load_error_method(case_, false, 3, solid_limit / 8 + 1, why),
            solvers::LoadErrorMethod::None);
  EXPECT_EQ(app::resolved_load_error_method(case_, false, 3, solid_limit / 8, why),
            solvers::LoadErrorMethod::Refined);
  // h = 1/2 admits 2h but not 4h: the refined estimate.
  io::Case half = hill_drawing(15.0, 0.5);
  half.solver.load_error = solvers::LoadErrorMethod::Auto;
  EXPECT_EQ(app::resolved_load_error_method(half, true, 2, 230, why),
            solvers::LoadErrorMethod::Refined);
  // An asked method is kept.
  half.solver.load_error = solvers::LoadErrorMethod::Coarser;
  EXPECT_EQ(app::resolved_load_error_method(half, true, 2, 230, why),
            solvers::LoadErrorMethod::Coarser);
  // The benchmark's mesh II at h = 1 (the default case) has no 2h: a run gets the
  // refined estimate, and says so.
  io::Case ram = sticking_ram(1.0);
  ram.solver.load_error = solvers::LoadErrorMethod::Auto;
  const post::Results results = app::simulate(ram).results;
  ASSERT_TRUE(results.load_error.error.has_value()) << results.load_error.unavailable;
  EXPECT_EQ(results.load_error.method, "refined");
}

TEST(LoadErrorEstimate, WithoutEstimateSummarySaysNull) {
  io::Case case_ = sticking_ram(1.0);
  case_.solver.load_error = solvers::LoadErrorMethod::None;
  const post::Results results = app::simulate(case_).results;
  EXPECT_FALSE(results.load_error.error.has_value());
  EXPECT_NE(results.load_error.unavailable.find("none"), std::string::npos);
  const std::string summary = io::summary_json(case_, results);
  EXPECT_NE(summary.find("\"ram_reaction_error\": null"), std::string::npos);
  EXPECT_EQ(summary.find("NaN"), std::string::npos);
}

TEST(LoadErrorEstimate, ExactConstraintsSayWhyNot) {
  // d = 0: Uzawa steps, no Newton tangent on the refined mesh.
  io::Case case_ = sticking_ram(1.0);
  case_.formulation.type = assembly::FormulationType::Mixed;
  case_.penalty.d = 0;
  case_.solver.method = solvers::NonlinearMethod::Secant;
  const post::Results results = app::simulate(case_).results;
  EXPECT_FALSE(results.load_error.error.has_value());
  EXPECT_NE(results.load_error.unavailable.find("exact constraints"), std::string::npos);
  // The default on mesh II at h = 1 (no 2h, 4h) falls back to the refined estimate,
  // which has no tangent here: the reason names both, and what would give a bar.
  case_.solver.load_error = solvers::LoadErrorMethod::Auto;
  const std::string why = app::simulate(case_).results.load_error.unavailable;
  EXPECT_NE(why.find("2h and 4h"), std::string::npos) << why;
  EXPECT_NE(why.find("exact constraints"), std::string::npos) << why;
}

} // namespace
} // namespace formflow::testing
