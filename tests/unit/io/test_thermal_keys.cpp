// SPDX-License-Identifier: MIT
// The [thermal] keys (issue 18): defaults, the TOML boolean switch, units, and the
// refusals with the key, file and line named.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_json.hpp"

#include <gtest/gtest.h>

#include <string>

namespace formflow::io {
namespace {

InputError thermal_error_in(const std::string& text, const std::string& key, int line) {
  try {
    load_case_text(text, "hot.toml", {});
  } catch (const InputError& error) {
    EXPECT_EQ(error.key, key) << error.what();
    EXPECT_EQ(error.line, line) << error.what();
    EXPECT_EQ(error.file, "hot.toml") << error.what();
    return error;
  }
  ADD_FAILURE() << "no InputError for\n" << text;
  return InputError("", -1, "", "");
}

TEST(ThermalKeys, DefaultsAreIsothermalWithTheIssuesShares) {
  const Case case_ = load_case("", {});
  EXPECT_FALSE(case_.thermal.enabled);
  EXPECT_EQ(case_.thermal.taylor_quinney, 0.9);
  EXPECT_EQ(case_.thermal.friction_share, 0.5);
  EXPECT_EQ(case_.thermal.heat_transfer, 0.0);
  EXPECT_EQ(case_.thermal.unit, physics::TemperatureUnit::Celsius);
}

TEST(ThermalKeys, EnabledTakesATomlBooleanAndTheString) {
  EXPECT_TRUE(load_case_text("[thermal]\nenabled = true\n", "hot.toml", {}).thermal.enabled);
  EXPECT_TRUE(load_case_text("", "hot.toml", {{"thermal.enabled", "true"}}).thermal.enabled);
  EXPECT_TRUE(load_case_text("[thermal]\nenabled = \"true\"\n", "hot.toml", {}).thermal.enabled);
  thermal_error_in("[thermal]\nenabled = 1\n", "thermal.enabled", 2);
}

TEST(ThermalKeys, EnabledIsAJsonBooleanInTheCaseEcho) {
  // summary.json's `case` block: a switch reads as true/false, not as a string.
  const auto off = case_to_json(load_case("", {}));
  const auto on = case_to_json(load_case_text("[thermal]\nenabled = true\n", "hot.toml", {}));
  ASSERT_TRUE(off["thermal"]["enabled"].is_boolean()) << off["thermal"].dump();
  ASSERT_TRUE(on["thermal"]["enabled"].is_boolean()) << on["thermal"].dump();
  EXPECT_FALSE(off["thermal"]["enabled"].get<bool>());
  EXPECT_TRUE(on["thermal"]["enabled"].get<bool>());
  // The other enums stay strings.
  EXPECT_TRUE(on["thermal"]["temperature_unit"].is_string());
}

TEST(ThermalKeys, TheUnitSetsSellarsTegartsAbsoluteTemperature) {
  const Case celsius =
      load_case_text("[material]\nlaw = \"sellars_tegart\"\ntemperature = 500\n", "hot.toml", {});
  const Case kelvin = load_case_text("[material]\nlaw = \"sellars_tegart\"\ntemperature = 773.15\n"
                                     "[thermal]\ntemperature_unit = \"kelvin\"\n",
                                     "hot.toml", {});
  // Sheppard's AA6063 constants (the defaults): σ_p = 20.5 MPa at 500 °C and 1 s⁻¹.
  EXPECT_NEAR(celsius.material.yield_stress(1.0), 20.497, 1e-3);
  EXPECT_NEAR(kelvin.material.yield_stress(1.0), celsius.material.yield_stress(1.0), 1e-9);
}

TEST(ThermalKeys, MaxTemperatureMustExceedThePrescribedOnes) {
  const InputError error = thermal_error_in("[thermal]\nenabled = true\nbillet_temperature = 450\n"
                                            "max_temperature = 400\n",
                                            "thermal.max_temperature", 4);
  EXPECT_NE(std::string(error.what()).find("450"), std::string::npos) << error.what();
}

TEST(ThermalKeys, ASharesIsAFraction) {
  thermal_error_in("[thermal]\nfriction_share = 1.5\n", "thermal.friction_share", 2);
  thermal_error_in("[thermal]\ntaylor_quinney = -0.1\n", "thermal.taylor_quinney", 2);
}

TEST(ThermalKeys, TrescaAndHybridWorkWithThermal) {
  // Their shear yield is taken at the Γ3 points' temperature (test_contact_temperature).
  EXPECT_TRUE(load_case_text("[friction]\nlaw = \"tresca\"\nm = 0.5\n[thermal]\nenabled = true\n",
                             "hot.toml", {})
                  .thermal.enabled);
  EXPECT_TRUE(load_case_text("[friction]\nlaw = \"hybrid\"\nmu = 0.2\nm = 0.5\n[thermal]\n"
                             "enabled = true\n",
                             "hot.toml", {})
                  .thermal.enabled);
}

TEST(ThermalKeys, ConditionTwoElevenIsCheckedOverTheTemperatureRange) {
  // Hensel–Spittel's rate exponent m3 + m8 T = 0.1 + 0.002 T leaves (0, 1] above 450 °C:
  // fine at the billet's 400 °C, refused on [400, 500].
  const std::string law = "[material]\nlaw = \"hensel_spittel\"\nhs_m3 = 0.1\nhs_m8 = 0.002\n"
                          "temperature = 400\n";
  EXPECT_NO_THROW(load_case_text(law, "hot.toml", {}));
  const InputError error = thermal_error_in(
      law + "[thermal]\nenabled = true\nbillet_temperature = 400\ntool_temperature = "
            "400\nmax_temperature = 500\n",
      "thermal.max_temperature", 10);
  EXPECT_NE(std::string(error.what()).find("2.11"), std::string::npos) << error.what();
}

} // namespace
} // namespace formflow::io
