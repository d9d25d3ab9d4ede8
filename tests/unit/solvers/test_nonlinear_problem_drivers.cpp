// SPDX-License-Identifier: MIT
// The drivers see a problem only through solvers::NonlinearProblem: a tiny fake
// (a chain of power-law dashpots, no mesh, no FormingProblem) is solved by the
// secant and Newton drivers to its closed-form solution, and its after-iteration
// hook decides when they may stop.
#include "formflow/solvers/newton_iteration.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace formflow {
namespace {

/// E dashpots in series between node 0 (u = 0) and node E (u = 1, the driven end):
/// element e carries the flux q_e = c_e |g|^(m−1) g, g = u_{e+1} − u_e (a 1D power-law
/// flow law, ν = c |g|^(m−1) its secant viscosity). Equilibrium: the same flux q in
/// every element, so g_e = (q/c_e)^(1/m) with Σ g_e = 1, q = (Σ c_e^(−1/m))^(−m).
/// The small ε in |g|² + ε² only keeps ν finite should an iterate reach g = 0;
/// at the solution (g ≥ 2e-3 with c_e = 1 + e) it changes q by a relative (ε/g)² < 1e-18.
class DashpotChain final : public solvers::NonlinearProblem {
public:
  static constexpr int n_elements = 6;
  static constexpr Real exponent = 0.3; // m: strongly nonlinear, like σ_p ∝ ε̄̇^m
  static constexpr Real epsilon = 1e-12;

  DashpotChain() : plan_(make_plan()), prescribed_(VectorX::Zero(n_elements + 1)) {
    prescribed_[n_elements] = 1.0;
  }

  static Real coefficient(int element) { return 1.0 + element; }

  /// The closed-form solution (full nodal vector) and its flux.
  static VectorX exact_velocity() {
    Real sum = 0.0;
    for (int e = 0; e < n_elements; ++e) sum += std::pow(coefficient(e), -1.0 / exponent);
    const Real flux = std::pow(sum, -exponent);
    VectorX u = VectorX::Zero(n_elements + 1);
    for (int e = 0; e < n_elements; ++e)
      u[e + 1] = u[e] + std::pow(flux / coefficient(e), 1.0 / exponent);
    return u;
  }

  std::function<solvers::AfterIteration(const solvers::IterationState&)> hook;
  int hook_calls = 0;

  const assembly::ScatterPlan& plan() const override { return plan_; }
  const VectorX& prescribed_values() const override { return prescribed_; }

  void assemble_secant(const VectorX* w, assembly::LinearSystem& system) const override {
    assembly::ScatterPlan::clear(system);
    for (int e = 0; e < n_elements; ++e) {
      // w = nullptr: the constant starting viscosity c_e (ν at g = 1).
      const Real nu =
          w ? coefficient(e) * std::pow(gradient(*w, e) * gradient(*w, e) + epsilon * epsilon,
                                        (exponent - 1.0) / 2.0)
            : coefficient(e);
      plan_.scatter(e, nu * stencil(), prescribed_, system);
    }
  }
  Real driven_force(const assembly::LinearSystem& system, const VectorX& u) const override {
    const Index row = plan_.prescribed_index(n_elements);
    return (system.reaction_rows * u)[row] - system.prescribed_loads[row];
  }
  Real internal_driven_force(const VectorX& internal_force) const override {
    return internal_force[n_elements];
  }
  Real driven_height() const override { return 1.0; }

  /// The chain has no near-rigid zones: the primal (exact) tangent needs no duals.
  struct NoDuals final : solvers::DualState {
    std::unique_ptr<DualState> clone() const override { return std::make_unique<NoDuals>(); }
  };
  std::unique_ptr<solvers::DualState> make_duals() const override {
    return std::make_unique<NoDuals>();
  }
  void assemble_newton(const VectorX& u, const solvers::DualState&, VectorX& internal_force,
                       assembly::LinearSystem* tangent) override {
    internal_force = VectorX::Zero(n_elements + 1);
    if (tangent) assembly::ScatterPlan::clear(*tangent);
    for (int e = 0; e < n_elements; ++e) {
      const Real g = gradient(u, e), s2 = g * g + epsilon * epsilon;
      const Real flux = coefficient(e) * std::pow(s2, (exponent - 1.0) / 2.0) * g;
      internal_force[e] -= flux;
      internal_force[e + 1] += flux;
      // dq/dg = c (g² + ε²)^((m−3)/2) (m g² + ε²) > 0: the tangent is SPD.
      const Real slope = coefficient(e) * std::pow(s2, (exponent - 3.0) / 2.0) *
                         (exponent * g * g + epsilon * epsilon);
      if (tangent) plan_.scatter(e, slope * stencil(), prescribed_, *tangent);
    }
  }
  bool has_coupling() const override { return false; }
  void apply_coupling(const VectorX&, VectorX&) const override {}
  void update_duals(const VectorX&, const VectorX&, const VectorX&,
                    solvers::DualState&) const override {}
  void secant_duals(const VectorX*, const VectorX&, solvers::DualState&) const override {}

  solvers::AfterIteration after_iteration(const solvers::IterationState& state) override {
    ++hook_calls;
    return hook ? hook(state) : solvers::AfterIteration{};
  }

private:
  static assembly::ScatterPlan make_plan() {
    std::vector<bool> prescribed(n_elements + 1, false);
    prescribed.front() = prescribed.back() = true;
    assembly::BlockDofs blocks;
    for (Index e = 0; e < n_elements; ++e) blocks.add({e, e + 1});
    return assembly::ScatterPlan(n_elements + 1, prescribed, blocks);
  }
  static MatrixX stencil() {
    MatrixX k(2, 2);
    k << 1.0, -1.0, -1.0, 1.0;
    return k;
  }
  static Real gradient(const VectorX& u, int e) { return u[e + 1] - u[e]; }

  assembly::ScatterPlan plan_;
  VectorX prescribed_;
};

solvers::IterationControl tight_control() {
  solvers::IterationControl control;
  control.tolerance = 1e-10;
  control.max_iterations = 300;
  control.coarse_levels = 0;
  return control;
}

Real relative_error(const VectorX& u) {
  const VectorX exact = DashpotChain::exact_velocity();
  return (u - exact).norm() / exact.norm();
}

TEST(NonlinearProblemDrivers, SecantConvergesToTheClosedFormSolution) {
  DashpotChain chain;
  auto solver = solvers::make_cholmod_solver();
  PhaseTimes times;
  const auto outcome = solvers::secant_iteration(chain, *solver, tight_control(), {}, times);
  ASSERT_EQ(outcome.stop_reason, solvers::StopReason::Converged);
  ASSERT_GE(outcome.history.size(), 4u);
  // The Kachanov iteration contracts linearly: with rate ρ, the remaining error is at
  // most ρ/(1 − ρ) times the last change; ρ estimated by the largest of the last
  // three ratios of successive changes.
  const auto& h = outcome.history;
  const std::size_t n = h.size();
  Real rate = 0.0;
  for (std::size_t k = n - 3; k < n; ++k)
    rate = std::max(rate, h[k].relative_change / h[k - 1].relative_change);
  ASSERT_LT(rate, 1.0);
  EXPECT_LE(relative_error(outcome.velocity), rate / (1.0 - rate) * h.back().relative_change);
  // The monitored pressure is the secant reaction at the driven end, ν(w) c g(u) with
  // w the previous iterate, against the flux q = c g*^m: to first order its relative
  // error is (m − 1) δg_w/g + δg_u/g, and |δg| ≤ √2 × the nodal error (E for u,
  // E + the last change for w), g the last element's exact gradient.
  const VectorX exact = DashpotChain::exact_velocity();
  const Real m = DashpotChain::exponent;
  const Real flux = DashpotChain::coefficient(0) * std::pow(exact[1], m);
  const int last = DashpotChain::n_elements - 1;
  const Real g_last = exact[last + 1] - exact[last];
  const Real error = (outcome.velocity - exact).norm();
  const Real change = h.back().relative_change * outcome.velocity.norm();
  const Real pressure_bound =
      std::sqrt(2.0) * ((1.0 - m) * (error + change) + error) / g_last * flux;
  EXPECT_NEAR(h.back().pressure, flux, pressure_bound);
  // One analysis, one factorisation per solve (the first plus one per iteration).
  EXPECT_EQ(times.counted("analysis"), 1);
  EXPECT_EQ(times.counted("factorization"), static_cast<long>(n) + 1);
  EXPECT_EQ(chain.hook_calls, static_cast<int>(n));
}

TEST(NonlinearProblemDrivers, NewtonConvergesToTheSameSolutionInFewerIterations) {
  DashpotChain secant_chain, newton_chain;
  auto solver = solvers::make_cholmod_solver();
  PhaseTimes times;
  const auto secant = solvers::secant_iteration(secant_chain, *solver, tight_control(), {}, times);
  const auto newton = solvers::newton_iteration(newton_chain, *solver, tight_control(), {}, times);
  ASSERT_EQ(newton.stop_reason, solvers::StopReason::Converged);
  // Quadratic convergence: the error after the last step is of the order of that
  // step squared (down to round-off), so below δ, which bounds the step itself.
  EXPECT_LT(newton.history.back().relative_change, tight_control().tolerance);
  EXPECT_LE(relative_error(newton.velocity), tight_control().tolerance);
  EXPECT_LT(newton.history.size(), secant.history.size());
  EXPECT_EQ(newton_chain.hook_calls, static_cast<int>(newton.history.size()));
}

TEST(NonlinearProblemDrivers, TheHookDecidesWhenAConvergedDriverMayStop) {
  for (const bool use_newton : {false, true}) {
    SCOPED_TRACE(use_newton ? "newton" : "secant");
    auto solver = solvers::make_cholmod_solver();
    PhaseTimes times;
    const auto run = [&](DashpotChain& chain) {
      return use_newton ? solvers::newton_iteration(chain, *solver, tight_control(), {}, times)
                        : solvers::secant_iteration(chain, *solver, tight_control(), {}, times);
    };
    DashpotChain plain;
    const auto reference = run(plain);
    ASSERT_EQ(reference.stop_reason, solvers::StopReason::Converged);

    // Settled only at the third iteration the driver itself calls converged: the
    // driver goes on for exactly two more iterations (the change stays below δ).
    DashpotChain held;
    int converged_calls = 0;
    held.hook = [&](const solvers::IterationState& state) {
      EXPECT_NE(state.velocity, nullptr);
      if (state.converged) ++converged_calls;
      return solvers::AfterIteration{converged_calls >= 3, std::nullopt};
    };
    const auto outcome = run(held);
    EXPECT_EQ(outcome.stop_reason, solvers::StopReason::Converged);
    EXPECT_EQ(outcome.history.size(), reference.history.size() + 2);
    EXPECT_EQ(held.hook_calls, static_cast<int>(outcome.history.size()));

    // A reason to stop from the hook ends the run at that iteration.
    DashpotChain failing;
    failing.hook = [](const solvers::IterationState& state) {
      return solvers::AfterIteration{false, state.iteration == 2
                                                ? std::optional(solvers::StopReason::NonFinite)
                                                : std::nullopt};
    };
    const auto stopped = run(failing);
    EXPECT_EQ(stopped.stop_reason, solvers::StopReason::NonFinite);
    EXPECT_EQ(stopped.history.size(), 2u);
  }
}

} // namespace
} // namespace formflow
