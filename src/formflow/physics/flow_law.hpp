// SPDX-License-Identifier: MIT
// The uniaxial yield limit σ_p(ε̄̇), its secant viscosity and derivative (SPEC §1,
// eq. 5.4), for the paper's piecewise power law and the other laws of issue 6.
#pragma once

#include "formflow/core/types.hpp"

#include <optional>
#include <string>

namespace formflow::physics {

/// Which law gives σ_p on [rate1, rate2]; outside that range every law is
/// continued linearly through the origin, as the paper's (5.4) is, so that the
/// secant viscosity σ_p/ε̄̇ stays bounded (condition 2.11). Inside the range all
/// of them are a power law C ε̄̇^m; they differ in how C and m are given:
///  * PiecewisePower (paper eq. 5.4): C = A, m = α.
///  * NortonHoff: s = 2K(√3 ε̄̇)^(m−1) ė, i.e. σ_p = √3 K (√3 ε̄̇)^m; m = 1 is
///    linear viscous (σ_p = 3K ε̄̇, K the shear viscosity).
///  * HenselSpittel, isothermal at temperature T and at a fixed reference strain ε
///    (the steady-state model carries no strain history):
///    σ_p = A e^(m1 T) ε^m2 e^(m4/ε) ε̄̇^(m3 + m8 T).
///  * PerfectlyPlastic (rate independent): σ_p = σ0, m = 0; σ_p′ = 0 in the
///    plastic range, so (2.11) holds there only with η1 = 0 (the α → 0 limit of 5.4).
enum class FlowLawKind { PiecewisePower, NortonHoff, HenselSpittel, PerfectlyPlastic };

struct FlowLaw {
  FlowLawKind kind = FlowLawKind::PiecewisePower;
  Real A = 1.7320508075688772;      ///< √3: shear yield k = σ_p/√3 ≈ 1 (PiecewisePower)
  Real alpha = 1e-3;                ///< strain-rate sensitivity, 0 < α ≤ 1 (PiecewisePower)
  Real rate1 = 1e-3;                ///< lower limit of the power-law range
  Real rate2 = 1e3;                 ///< upper limit of the power-law range
  Real K = 1.0;                     ///< Norton–Hoff consistency (stress·time^m)
  Real m = 0.1;                     ///< Norton–Hoff rate sensitivity, 0 < m ≤ 1
  Real sigma0 = 1.7320508075688772; ///< PerfectlyPlastic yield stress
  /// Hensel–Spittel parameters (see FlowLawKind) and the state it is evaluated at.
  Real hs_A = 1.7320508075688772, hs_m1 = 0.0, hs_m2 = 0.0, hs_m3 = 0.1, hs_m4 = 0.0, hs_m8 = 0.0,
       temperature = 0.0, strain = 1.0;

  /// C of σ_p = C ε̄̇^m on [rate1, rate2].
  Real coefficient() const;
  /// m of σ_p = C ε̄̇^m on [rate1, rate2].
  Real exponent() const;

  /// Uniaxial yield limit σ_p at equivalent strain rate `rate` ≥ 0.
  Real yield_stress(Real rate) const;
  /// Secant viscosity σ_p(ε̄̇)/ε̄̇, finite at ε̄̇ = 0 (the linear branch).
  Real secant_viscosity(Real rate) const;
  /// dσ_p/dε̄̇ (one-sided at the break points: the linear branch's value there).
  Real yield_stress_derivative(Real rate) const;
  /// secant_viscosity(rate) and yield_stress_derivative(rate) from one power
  /// (equal to round-off): the Newton loops need both at every point.
  struct SecantAndDerivative {
    Real viscosity, derivative;
  };
  SecantAndDerivative secant_viscosity_and_derivative(Real rate) const;
  /// Plastic dissipation density σ_p(ε̄̇)·ε̄̇.
  Real dissipation(Real rate) const { return yield_stress(rate) * rate; }
};

/// The paper's law keeps its historical name.
using PowerLaw = FlowLaw;

/// Checks condition (2.11), η1 ≤ σ_p′(ε̄̇) ≤ σ_p(ε̄̇)/ε̄̇ ≤ η2 with η1 > 0 (η1 = 0
/// allowed for the rate-independent law only), on a logarithmic sweep over
/// [rate1/10, 10 rate2] that includes the break points. Returns what is violated, or
/// std::nullopt. A law that fails is refused at load time (io/case_file.cpp).
std::optional<std::string> check_flow_law(const FlowLaw& law);

} // namespace formflow::physics
