// SPDX-License-Identifier: MIT
// Case keys of the [material] section (The flow law): rows of the table in io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

#include <tuple>

namespace formflow::io::keys {

namespace {

/// The choices of material.law: the names of the registered laws (physics::FlowLaws).
std::vector<std::pair<std::string_view, std::string_view>> law_names() {
  std::vector<std::pair<std::string_view, std::string_view>> names;
  std::apply([&](const auto&... law) { (names.emplace_back(law.name, law.name), ...); },
             physics::FlowLaws::Tuple{});
  return names;
}

/// Accessor of parameter `field` of law `Law` in the case (whichever law is selected).
template <class Law> auto law_parameter(Real Law::*field) {
  return [field](auto& c) -> auto& {
    return c.material.template parameters_of<Law>().*field;
  };
}

/// material.temperature: the isothermal T of every temperature-dependent law.
KeySpec temperature_key() {
  KeySpec spec("material.temperature", KeyType::Real, 0.0);
  spec.key.set = [](Case& c, const KeyValue& value) {
    c.material.parameters_of<physics::HenselSpittel>().temperature = std::get<Real>(value);
    c.material.parameters_of<physics::SellarsTegart>().temperature = std::get<Real>(value);
  };
  spec.key.get = [](const Case& c) -> KeyValue {
    return c.material.parameters_of<physics::HenselSpittel>().temperature;
  };
  return spec;
}

} // namespace

std::vector<CaseKey> material_keys() {
  using physics::HenselSpittel;
  using physics::NortonHoff;
  using physics::PerfectlyPlastic;
  using physics::PiecewisePower;
  using physics::SellarsTegart;
  return {
      enum_key(
          "material.law", "piecewise_power", law_names(),
          [](auto& c) -> auto& { return c.material.law; })
          .constraint("the law must satisfy condition (2.11) (checked at load time)")
          .doc("σ_p on [rate1, rate2], linear through the origin outside: piecewise_power "
               "A ε̄̇^α (paper eq. 5.4); norton_hoff √3 K (√3 ε̄̇)^m; hensel_spittel "
               "A e^(m1 T) ε^m2 e^(m4/ε) ε̄̇^(m3 + m8 T); perfectly_plastic σ0; sellars_tegart "
               "(1/α_s) asinh((ε̄̇ e^(Q/(R T))/A)^(1/n))"),
      real_key("material.A", 1.7320508075688772, law_parameter(&PiecewisePower::A))
          .within(1e-12, 1e12)
          .why(stress_range)
          .unit("stress·time^α")
          .doc("A of σ_p = A ε̄̇^α (paper eq. 5.4); √3 gives the shear yield k ≈ 1"),
      real_key("material.alpha", 1e-3, law_parameter(&PiecewisePower::alpha))
          .within(1e-6, 1)
          .why(exponent_range)
          .doc("strain-rate sensitivity α"),
      real_key(
          "material.rate1", 1e-3, [](auto& c) -> auto& { return c.material.rate1; })
          .within(1e-12, 1e12)
          .why(rate_range)
          .constraint("< material.rate2")
          .unit("1/time")
          .doc("ε̄̇₁: below it σ_p is continued linearly through the origin"),
      real_key(
          "material.rate2", 1e3, [](auto& c) -> auto& { return c.material.rate2; })
          .within(1e-12, 1e12)
          .why(rate_range)
          .constraint("> material.rate1")
          .unit("1/time")
          .doc("ε̄̇₂: above it σ_p is continued linearly through the origin"),
      real_key("material.K", 1.0, law_parameter(&NortonHoff::K))
          .within(1e-12, 1e12)
          .why(stress_range)
          .unit("stress·time^m")
          .doc("norton_hoff: consistency K of s = 2K(√3 ε̄̇)^(m−1) ė"),
      real_key("material.m", 0.1, law_parameter(&NortonHoff::m))
          .within(1e-6, 1)
          .why(exponent_range)
          .doc("norton_hoff: strain-rate sensitivity m (1 = linear viscous)"),
      real_key("material.sigma0", 1.7320508075688772, law_parameter(&PerfectlyPlastic::sigma0))
          .within(1e-12, 1e12)
          .why(stress_range)
          .unit("stress")
          .doc("perfectly_plastic: the rate-independent yield stress σ0"),
      real_key("material.hs_A", 1.7320508075688772, law_parameter(&HenselSpittel::A))
          .within(1e-12, 1e12)
          .why(stress_range)
          .unit("stress·time^(m3+m8 T)")
          .doc("hensel_spittel: A"),
      real_key("material.hs_m1", 0.0, law_parameter(&HenselSpittel::m1))
          .within(-10, 10)
          .why(law_parameter_range)
          .unit("1/temperature")
          .doc("hensel_spittel: temperature factor e^(m1 T)"),
      real_key("material.hs_m2", 0.0, law_parameter(&HenselSpittel::m2))
          .within(-10, 10)
          .why(law_parameter_range)
          .doc("hensel_spittel: strain-hardening exponent of ε^m2"),
      real_key("material.hs_m3", 0.1, law_parameter(&HenselSpittel::m3))
          .within(-10, 10)
          .why(law_parameter_range)
          .constraint("0 < m3 + m8 T ≤ 1")
          .doc("hensel_spittel: strain-rate exponent m3 of ε̄̇^(m3 + m8 T)"),
      real_key("material.hs_m4", 0.0, law_parameter(&HenselSpittel::m4))
          .within(-10, 10)
          .why(law_parameter_range)
          .doc("hensel_spittel: softening term e^(m4/ε)"),
      real_key("material.hs_m8", 0.0, law_parameter(&HenselSpittel::m8))
          .within(-1, 1)
          .why(law_parameter_range)
          .unit("1/temperature")
          .constraint("0 < m3 + m8 T ≤ 1")
          .doc("hensel_spittel: temperature dependence m8 T of the strain-rate exponent"),
      temperature_key()
          .within(-10000.0, 10000.0)
          .why(law_parameter_range)
          .unit("temperature")
          .doc("hensel_spittel, sellars_tegart: the (uniform, constant) temperature T of the "
               "isothermal form (thermal.enabled replaces it by the field's T at each point)"),
      real_key("material.strain", 1.0, law_parameter(&HenselSpittel::strain))
          .within(1e-6, 1e6)
          .why(law_parameter_range)
          .doc("hensel_spittel: the reference equivalent strain ε at which the law is taken "
               "(the steady model carries no strain history)"),
      real_key("material.st_alpha", 0.040, law_parameter(&SellarsTegart::alpha))
          .within(1e-12, 1e12)
          .why(law_parameter_range)
          .unit("1/stress")
          .doc("sellars_tegart: α_s of σ_p = (1/α_s) asinh((Z/A)^(1/n)), Z = ε̄̇ e^(Q/(R T))"),
      real_key("material.st_n", 5.385, law_parameter(&SellarsTegart::n))
          .within(1, 100)
          .why("n ≥ 1 keeps σ_p′ ≤ σ_p/ε̄̇ (condition 2.11)")
          .doc("sellars_tegart: stress exponent n"),
      real_key("material.st_Q", 141550.0, law_parameter(&SellarsTegart::activation))
          .within(0, 1e7)
          .why(law_parameter_range)
          .unit("energy/mol")
          .doc("sellars_tegart: activation energy Q (J/mol)"),
      real_key("material.st_A", 5.91e9, law_parameter(&SellarsTegart::A))
          .within(1e-100, 1e100)
          .why(law_parameter_range)
          .unit("1/time")
          .doc("sellars_tegart: A of Z/A"),
      real_key("material.st_R", 8.314, law_parameter(&SellarsTegart::gas_constant))
          .within(1e-12, 1e12)
          .why(law_parameter_range)
          .unit("energy/(mol·K)")
          .doc("sellars_tegart: gas constant R (8.314 J/(mol·K))"),
  };
}

} // namespace formflow::io::keys
