// SPDX-License-Identifier: MIT
// The coupled manufactured solution of hot forming (issue 18): the smooth velocity of
// physics/manufactured.hpp with a smooth temperature, and the body force and heat
// source that make the pair the exact solution of the coupled problem.
#pragma once

#include "formflow/physics/manufactured.hpp"
#include "formflow/physics/thermal.hpp"

namespace formflow::physics {

/// T = T₀ + ΔT sin(πx/2)(1 + ½ cos πy) on the unit square: smooth, in no polynomial
/// space (so Q1 and Q2 both have an error), different from T₀ on three sides, and within
/// [T₀, T₀ + 1.5 ΔT].
class ManufacturedTemperature {
public:
  ManufacturedTemperature(Real base, Real rise) : base_(base), rise_(rise) {}
  Real value(const Point<2>& x) const;
  Point<2> gradient(const Point<2>& x) const;
  Real laplacian(const Point<2>& x) const;
  Real lowest() const { return base_; }
  Real highest() const { return base_ + 1.5 * rise_; }

private:
  Real base_, rise_;
};

/// ΔT of the coupled manufactured case: T runs from thermal.billet_temperature to 1.5 ΔT
/// above it (the case validation asks thermal.max_temperature to cover that).
inline constexpr Real coupled_temperature_rise = 60.0;

/// The flow law `law` at temperature T (a law that does not read T: `law` itself).
FlowLaw law_at_temperature(FlowLaw law, Real temperature);

/// ∂σ_p/∂T of `law` (at its own temperature) at `rate` in [rate1, rate2]; 0 for a law
/// that does not read T.
Real yield_stress_temperature_slope(const FlowLaw& law, Real rate);

/// f = −div τ with τ = ⅔ (σ_p(ε̄̇, T)/ε̄̇) ε̇ for the field's u and T(x): the isothermal
/// force of the law at T(x) plus −⅔ (∂σ_p/∂T / ε̄̇) ε̇ ∇T, the viscosity's change along ∇T.
Point<2> coupled_body_force(const FlowLaw& law, const StreamFunctionField& field,
                            const ManufacturedTemperature& temperature, const Point<2>& x);

/// s = ρc u·∇T − κ ΔT − β σ_p(ε̄̇, T) ε̄̇ for the exact pair: with it, the exact T solves
/// ρc u·∇T = κ ΔT + β σ_p ε̄̇ + s, the heat equation of thermal.enabled plus s.
Real coupled_heat_source(const FlowLaw& law, const Thermal& thermal,
                         const StreamFunctionField& field,
                         const ManufacturedTemperature& temperature, const Point<2>& x);

} // namespace formflow::physics
