// SPDX-License-Identifier: MIT
// The data of the steady heat problem of hot forming (issue 18, SPEC §6).
#pragma once

#include "formflow/core/types.hpp"

namespace formflow::physics {

/// The unit the case's temperatures are in; laws that need an absolute temperature
/// (Sellars–Tegart) add `absolute_offset` to it.
enum class TemperatureUnit { Kelvin, Celsius };
inline Real absolute_offset(TemperatureUnit unit) {
  return unit == TemperatureUnit::Celsius ? 273.15 : 0.0;
}

/// ρc u·∇T = ∇·(κ∇T) + β σ_p ε̄̇ in the workpiece; T = billet_temperature on the rear
/// end Γ1 (the inflow end of extrusion and of drawing, where it is the entry); on Γ3
/// −κ ∂T/∂n = h (T − T_tool) − share·τ_f|u_T|; on the free surfaces Γ2, Γ4 −κ ∂T/∂n =
/// h_free (T − T_ambient) (0: adiabatic); the outflow end is adiabatic. Units: any
/// consistent set in which ρc is stress/temperature (power density = stress/time).
struct Thermal {
  bool enabled = false;
  TemperatureUnit unit = TemperatureUnit::Celsius;
  Real billet_temperature = 450.0;  ///< T on the inflow end
  Real density = 1.0;               ///< ρ (mass/length³)
  Real heat_capacity = 1.0;         ///< c (energy/(mass·temperature)); ρc in stress/temperature
  Real conductivity = 1.0;          ///< κ (power/(length·temperature))
  Real taylor_quinney = 0.9;        ///< β: share of the plastic work turned into heat
  Real friction_share = 0.5;        ///< share of τ_f|u_T| entering the workpiece
  Real tool_temperature = 450.0;    ///< T of container and die
  Real heat_transfer = 0.0;         ///< h on Γ3 (power/(area·temperature)); 0: adiabatic tools
  Real free_surface_transfer = 0.0; ///< h on Γ2, Γ4; 0: adiabatic free surfaces
  Real ambient_temperature = 20.0;  ///< T of the surroundings of Γ2, Γ4
  Real max_temperature = 700.0;     ///< the flow law is taken at min(T, this) (checked range)
  Real coupling_tolerance = 1e-4;   ///< max |ΔT|/ΔT_scale and |ΔF|/F between coupling steps
  int max_coupling_iterations = 30;
  Real volumetric_heat() const { return density * heat_capacity; }
};

} // namespace formflow::physics
