// SPDX-License-Identifier: MIT
// The uniaxial yield limit σ_p(ε̄̇), its secant viscosity and derivative (SPEC §1,
// eq. 5.4), for every flow law (one type each in physics/flow_laws/).
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/physics/flow_laws/hensel_spittel.hpp"
#include "formflow/physics/flow_laws/norton_hoff.hpp"
#include "formflow/physics/flow_laws/perfectly_plastic.hpp"
#include "formflow/physics/flow_laws/piecewise_power.hpp"
#include "formflow/physics/flow_laws/sellars_tegart.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>

namespace formflow::physics {

/// The registration of the flow laws: every type of physics/flow_laws/ in one list
/// (the key material.law takes their `name`s). A law type has `name`,
/// `rate_independent` and `at(rate) → FlowResponse` on [rate1, rate2].
template <class... Laws> struct FlowLawList {
  using Variant = std::variant<Laws...>;
  using Tuple = std::tuple<Laws...>;
};
using FlowLaws =
    FlowLawList<PiecewisePower, NortonHoff, HenselSpittel, PerfectlyPlastic, SellarsTegart>;

/// True for a law whose response depends on a `temperature` member (hot-forming laws):
/// a thermal run evaluates it at each point's temperature (FlowLawAt).
template <class Law>
concept TemperatureDependent = requires(Law law) {
  law.temperature = Real{};
};

/// What every flow law answers, from its `response(rate)` (the law's own response at a
/// rate clamped to [rate1, rate2]): the continuation outside [rate1, rate2], linear
/// through the origin as the paper's (5.4) is, so that the secant viscosity σ_p/ε̄̇ stays
/// bounded (condition 2.11). Shared by FlowLaw (the law chosen at run time) and
/// BoundFlowLaw (one law type, for loops that dispatch once, not per point).
template <class Derived> struct FlowLawMethods {
  /// Secant viscosity σ_p(ε̄̇)/ε̄̇, finite at ε̄̇ = 0 (the linear branch).
  Real secant_viscosity(Real rate) const { return self().response(rate).viscosity; }
  /// Uniaxial yield limit σ_p at equivalent strain rate `rate` ≥ 0.
  Real yield_stress(Real rate) const { return secant_viscosity(rate) * rate; }
  /// True where σ_p is linear in ε̄̇ (outside (rate1, rate2)): there σ_p′ = ν and the
  /// secant matrix is already the tangent.
  bool is_linear_at(Real rate) const { return rate <= self().rate1 || rate >= self().rate2; }
  /// dσ_p/dε̄̇ (one-sided at the break points: the linear branch's value there).
  Real yield_stress_derivative(Real rate) const {
    const FlowResponse at = self().response(rate);
    return rate < self().rate1 || rate > self().rate2 ? at.viscosity : at.slope;
  }
  /// secant_viscosity(rate) and yield_stress_derivative(rate) from one evaluation.
  struct SecantAndDerivative {
    Real viscosity, derivative;
  };
  SecantAndDerivative secant_viscosity_and_derivative(Real rate) const {
    const FlowResponse at = self().response(rate);
    if (rate < self().rate1 || rate > self().rate2) return {at.viscosity, at.viscosity};
    return {at.viscosity, at.slope};
  }
  /// Plastic dissipation density σ_p(ε̄̇)·ε̄̇.
  Real dissipation(Real rate) const { return yield_stress(rate) * rate; }

private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

/// One law type with its range: FlowLaw's answers without the run-time dispatch.
template <class Law> struct BoundFlowLaw : FlowLawMethods<BoundFlowLaw<Law>> {
  const Law& law;
  Real rate1, rate2;
  BoundFlowLaw(const Law& law_, Real rate1_, Real rate2_)
      : law(law_), rate1(rate1_), rate2(rate2_) {}
  FlowResponse response(Real rate) const {
    return law.at(rate <= rate1 ? rate1 : (rate >= rate2 ? rate2 : rate));
  }
};

/// One law evaluated at a point: the law of `model` on [rate1, rate2], continued
/// linearly outside it (FlowLawMethods). The solvers ask this object, never the law's
/// parameters.
struct FlowLaw : FlowLawMethods<FlowLaw> {
  FlowLaws::Variant model = PiecewisePower{};
  Real rate1 = 1e-3; ///< lower limit of the law's range
  Real rate2 = 1e3;  ///< upper limit of the law's range

  /// The law's own response at a rate clamped to [rate1, rate2].
  FlowResponse response(Real rate) const {
    const Real clamped = rate <= rate1 ? rate1 : (rate >= rate2 ? rate2 : rate);
    return std::visit([clamped](const auto& law) { return law.at(clamped); }, model);
  }
  /// Calls `f(BoundFlowLaw<Law>)` for the law `model` holds: a loop over every point
  /// written inside `f` dispatches once instead of at each point (the dual update
  /// evaluates the law twice per point; the run-time dispatch cost it 9 %).
  template <class F> decltype(auto) visit_bound(F&& f) const {
    return std::visit(
        [&](const auto& law) {
          return f(BoundFlowLaw<std::decay_t<decltype(law)>>(law, rate1, rate2));
        },
        model);
  }
  /// The law's name (its material.law spelling).
  std::string_view name() const {
    return std::visit([](const auto& law) { return std::string_view(law.name); }, model);
  }
  bool is_rate_independent() const {
    return std::visit([](const auto& law) { return law.rate_independent; }, model);
  }
  /// The parameters of law `Law`, which `model` holds.
  template <class Law> Law& as() { return std::get<Law>(model); }
  template <class Law> const Law& as() const { return std::get<Law>(model); }
  /// True when the law held reads a temperature (TemperatureDependent).
  bool is_temperature_dependent() const {
    return std::visit(
        [](const auto& law) { return TemperatureDependent<std::decay_t<decltype(law)>>; }, model);
  }
};

/// The law of `law` at temperature `temperature` (a thermal run's value at one quadrature
/// point): a law that is not TemperatureDependent answers as `law` does. The isothermal
/// path never builds one (it asks FlowLaw itself), so isothermal runs are unchanged.
struct FlowLawAt : FlowLawMethods<FlowLawAt> {
  const FlowLaw& law;
  Real temperature;
  Real rate1, rate2;
  FlowLawAt(const FlowLaw& law_, Real temperature_)
      : law(law_), temperature(temperature_), rate1(law_.rate1), rate2(law_.rate2) {}
  FlowResponse response(Real rate) const {
    const Real clamped = rate <= rate1 ? rate1 : (rate >= rate2 ? rate2 : rate);
    return std::visit(
        [&](const auto& model) {
          using Law = std::decay_t<decltype(model)>;
          if constexpr (TemperatureDependent<Law>) {
            Law at_point = model;
            at_point.temperature = temperature;
            return at_point.at(clamped);
          } else {
            return model.at(clamped);
          }
        },
        law.model);
  }
};

/// What the case file says of the material: the law by name, its range and the
/// parameters of every law (keys may come in any order; only the named one is used).
struct FlowLawChoice {
  std::string_view law = PiecewisePower::name;
  Real rate1 = 1e-3;
  Real rate2 = 1e3;
  FlowLaws::Tuple parameters;

  template <class Law> Law& parameters_of() { return std::get<Law>(parameters); }
  template <class Law> const Law& parameters_of() const { return std::get<Law>(parameters); }
  /// The law named `law` with its parameters and range.
  FlowLaw selected() const;
  /// Shorthands of selected(), for code that evaluates the case's law directly.
  Real yield_stress(Real rate) const { return selected().yield_stress(rate); }
};

/// Checks condition (2.11), η1 ≤ σ_p′(ε̄̇) ≤ σ_p(ε̄̇)/ε̄̇ ≤ η2 with η1 > 0 (η1 = 0
/// allowed for a rate-independent law only), on a logarithmic sweep over
/// [rate1/10, 10 rate2] that includes the break points. Returns what is violated, or
/// std::nullopt. A law that fails is refused at load time (io/case_cross_checks.cpp).
std::optional<std::string> check_flow_law(const FlowLaw& law);

/// Condition (2.11) of a temperature-dependent law at every temperature of
/// [low, high] (a sweep of 21 temperatures including both ends); the message names the
/// temperature where it fails.
std::optional<std::string> check_flow_law_over(const FlowLaw& law, Real low, Real high);

} // namespace formflow::physics
