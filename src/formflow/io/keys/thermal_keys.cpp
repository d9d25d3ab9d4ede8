// SPDX-License-Identifier: MIT
// Case keys of the [thermal] section (hot forming, issue 18): rows of the table in
// io/case_keys.cpp. Units: any consistent set in which ρc is a stress per temperature,
// e.g. MPa, mm, s, K or °C: ρ in t/mm³, c in mm²/(s²·K), κ in N/(s·K) = W/(m·K),
// h in N/(mm·s·K) = kW/(m²·K) (docs/thermal.md).
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

namespace {

inline constexpr std::string_view temperature_range =
    "temperatures within −1e4…1e4 keep exp(Q/(R T)) and the heat terms finite";
inline constexpr std::string_view property_range =
    "material properties within 1e-15…1e15 keep ρc, κ and the Péclet number finite";

} // namespace

std::vector<CaseKey> thermal_keys() {
  return {
      enum_key(
          "thermal.enabled", "false", {{"false", false}, {"true", true}},
          [](auto& c) -> auto& { return c.thermal.enabled; })
          .doc("true: solve the steady heat equation ρc u·∇T = ∇·(κ∇T) + β σ_p ε̄̇ with the "
               "flow, coupled to the flow law's temperature (a TOML boolean or \"true\")"),
      enum_key(
          "thermal.temperature_unit", "celsius",
          {{"celsius", physics::TemperatureUnit::Celsius},
           {"kelvin", physics::TemperatureUnit::Kelvin}},
          [](auto& c) -> auto& { return c.thermal.unit; })
          .doc("unit of every temperature of the case (material.temperature too); "
               "sellars_tegart takes T + 273.15 for celsius"),
      real_key(
          "thermal.billet_temperature", 450.0,
          [](auto& c) -> auto& { return c.thermal.billet_temperature; })
          .within(-1e4, 1e4)
          .why(temperature_range)
          .unit("temperature")
          .doc("T of the incoming billet, imposed on the rear end Γ1 (the inflow end)"),
      real_key(
          "thermal.density", 1.0, [](auto& c) -> auto& { return c.thermal.density; })
          .within(1e-15, 1e15)
          .why(property_range)
          .unit("mass/length³")
          .doc("ρ; ρc must be a stress per temperature (MPa, mm, s: t/mm³, 2.7e-9 for "
               "aluminium)"),
      real_key(
          "thermal.heat_capacity", 1.0, [](auto& c) -> auto& { return c.thermal.heat_capacity; })
          .within(1e-15, 1e15)
          .why(property_range)
          .unit("energy/(mass·temperature)")
          .doc("c (MPa, mm, s: mm²/(s²·K), 9.0e8 for aluminium: ρc = 2.43 MPa/K)"),
      real_key(
          "thermal.conductivity", 1.0, [](auto& c) -> auto& { return c.thermal.conductivity; })
          .within(1e-15, 1e15)
          .why(property_range)
          .unit("power/(length·temperature)")
          .doc("κ (MPa, mm, s: N/(s·K) = W/(m·K), 200 for aluminium)"),
      real_key(
          "thermal.taylor_quinney", 0.9, [](auto& c) -> auto& { return c.thermal.taylor_quinney; })
          .within(0.0, 1.0)
          .why("a share of the plastic work")
          .doc("β: the share of the plastic power σ_p ε̄̇ that becomes heat"),
      real_key(
          "thermal.friction_share", 0.5, [](auto& c) -> auto& { return c.thermal.friction_share; })
          .within(0.0, 1.0)
          .why("a share of the friction power")
          .doc("share of the friction power τ_f|u_T| on Γ3 that enters the workpiece (the rest "
               "goes into the tools)"),
      real_key(
          "thermal.tool_temperature", 450.0,
          [](auto& c) -> auto& { return c.thermal.tool_temperature; })
          .within(-1e4, 1e4)
          .why(temperature_range)
          .unit("temperature")
          .doc("T_tool of container and die in the transfer h (T − T_tool) on Γ3"),
      real_key(
          "thermal.heat_transfer", 0.0, [](auto& c) -> auto& { return c.thermal.heat_transfer; })
          .within(0.0, 1e15)
          .why(property_range)
          .unit("power/(area·temperature)")
          .doc("h of the heat flux h (T − T_tool) from the workpiece into container and die "
               "(MPa, mm, s: N/(mm·s·K) = kW/(m²·K)); 0 = adiabatic tools"),
      real_key(
          "thermal.free_surface_transfer", 0.0,
          [](auto& c) -> auto& { return c.thermal.free_surface_transfer; })
          .within(0.0, 1e15)
          .why(property_range)
          .unit("power/(area·temperature)")
          .doc("h of convection h (T − T_ambient) on the free surfaces Γ2, Γ4; 0 = adiabatic"),
      real_key(
          "thermal.ambient_temperature", 20.0,
          [](auto& c) -> auto& { return c.thermal.ambient_temperature; })
          .within(-1e4, 1e4)
          .why(temperature_range)
          .unit("temperature")
          .doc("T of the surroundings of the free surfaces"),
      real_key(
          "thermal.max_temperature", 700.0,
          [](auto& c) -> auto& { return c.thermal.max_temperature; })
          .within(-1e4, 1e4)
          .why(temperature_range)
          .constraint("> every prescribed temperature; condition (2.11) is checked from the "
                      "lowest of them to this")
          .unit("temperature")
          .doc("the flow law is taken at min(T, this): the top of the temperature range "
               "the law is checked on"),
      real_key(
          "thermal.coupling_tolerance", 1e-4,
          [](auto& c) -> auto& { return c.thermal.coupling_tolerance; })
          .within(1e-15, 1.0)
          .why(tolerance_range)
          .doc("the staggered flow ↔ heat loop stops when the change of T (relative to the "
               "largest T − T_billet) and of the process force are both below it"),
      integer_key(
          "thermal.max_coupling_iterations", 30,
          [](auto& c) -> auto& { return c.thermal.max_coupling_iterations; })
          .within(1, 1000)
          .why("each coupling step is one flow solve and one heat solve")
          .doc("most staggered coupling steps; not converged then: exit 3"),
  };
}

} // namespace formflow::io::keys
