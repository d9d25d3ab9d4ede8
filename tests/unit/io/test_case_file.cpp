// SPDX-License-Identifier: MIT
// load_case: defaults, every validation error (key, file, line, hint), --set overrides,
// case_to_json.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_json.hpp"
#include "formflow/io/case_keys.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

namespace formflow::io {
namespace {

namespace fs = std::filesystem;

using testing::has_text;

/// The InputError that loading throws (a failed expectation if it throws none).
InputError load_error(const std::string& path, const std::vector<Override>& overrides = {}) {
  try {
    load_case(path, overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "load_case(\"" << path << "\") did not throw InputError";
  return InputError("", -1, "", "");
}

class CaseFile : public ::testing::Test {
protected:
  /// Writes `text` to a fresh case file and returns its path.
  std::string write(const std::string& text) {
    const fs::path path = directory_ / ("case" + std::to_string(++n_files_) + ".toml");
    std::ofstream(path) << text;
    return path.string();
  }

  /// Loads `text` as a case file, expecting InputError at `key` on `line`.
  InputError error_in(const std::string& text, const std::string& key, int line) {
    const std::string path = write(text);
    InputError error = load_error(path);
    EXPECT_EQ(error.file, path) << error.what();
    EXPECT_EQ(error.key, key) << error.what();
    EXPECT_EQ(error.line, line) << error.what();
    return error;
  }

  testing::ScratchDirectory directory_{"formflow-case"};
  int n_files_ = 0;
};

TEST_F(CaseFile, DefaultsAreThePapersBenchmark) {
  const Case case_ = load_case("", {});
  EXPECT_EQ(case_.source, "<default>");
  EXPECT_EQ(case_.process.type, physics::ProcessType::Extrusion);
  EXPECT_EQ(case_.process.speed, 1.0);
  EXPECT_EQ(case_.process.ram, physics::RamCondition::Sliding);
  EXPECT_EQ(case_.mesh.geometry.container_length, 10.0);
  EXPECT_EQ(case_.mesh.geometry.entry_half_height, 10.0);
  EXPECT_EQ(case_.mesh.geometry.exit_half_height, 5.0);
  EXPECT_EQ(case_.mesh.geometry.exit_length, 10.0);
  EXPECT_EQ(case_.element, fem::ElementKind::Q2);
  EXPECT_EQ(case_.mesh.size, 1.0);
  EXPECT_EQ(case_.volumetric_points, 2);
  EXPECT_EQ(case_.material.parameters_of<physics::PiecewisePower>().A, std::sqrt(3.0));
  EXPECT_EQ(case_.material.parameters_of<physics::PiecewisePower>().alpha, 1e-3);
  EXPECT_EQ(case_.material.rate1, 1e-3);
  EXPECT_EQ(case_.material.rate2, 1e3);
  EXPECT_EQ(case_.viscous_strain, physics::ViscousStrain::Full);
  EXPECT_EQ(case_.friction.mu, 0.0);
  EXPECT_EQ(case_.friction.radius, 0.0);
  EXPECT_TRUE(case_.friction.on_container);
  EXPECT_TRUE(case_.friction.on_die);
  EXPECT_EQ(case_.penalty.d, 1e-3);
  EXPECT_EQ(case_.penalty.d_n, 1e-6);
  EXPECT_EQ(case_.friction.d_t, 1e-6);
  EXPECT_EQ(case_.solver.tolerance, 1e-4);
  EXPECT_EQ(case_.solver.max_iterations, 500);
  EXPECT_EQ(case_.solver.initial_rate, 1.0);
}

TEST_F(CaseFile, TableDefaultsEqualTheCaseStructDefaults) {
  const Case from_struct{};
  for (const CaseKey& key : case_keys())
    EXPECT_EQ(format_key_value(key.get(from_struct)), format_key_value(key.default_value))
        << key.name;
}

TEST_F(CaseFile, AnEmptyFileIsTheDefaultCase) {
  const std::string path = write("# nothing but a comment\n");
  const Case case_ = load_case(path, {});
  EXPECT_EQ(case_.source, path);
  nlohmann::ordered_json expected = case_to_json(load_case("", {}));
  expected["source"] = path;
  EXPECT_EQ(case_to_json(case_), expected);
}

TEST_F(CaseFile, JsonFollowsTheKeyTableOrderNotTheAlphabet) {
  // The echo reads like docs/case-reference.md: sections and keys in the table's order.
  std::vector<std::string> from_table, from_json;
  for (const CaseKey& key : case_keys()) from_table.emplace_back(key.name);
  const nlohmann::ordered_json json = case_to_json(load_case("", {}));
  for (const auto& [section, table] : json.items())
    if (table.is_object())
      for (const auto& [leaf, value] : table.items()) from_json.push_back(section + "." + leaf);
  EXPECT_EQ(from_json, from_table);
  // "process" comes before "material" in the table but after it in the alphabet.
  const std::string text = json.dump();
  EXPECT_LT(text.find("\"process\""), text.find("\"material\""));
}

TEST_F(CaseFile, UnknownKeyNamesTheClosestValidKey) {
  const InputError error = error_in("[friction]\nmu = 0.1\nmue = 0.2\n", "friction.mue", 3);
  EXPECT_TRUE(has_text(error.hint, "did you mean `friction.mu`?"));
  EXPECT_TRUE(has_text(error.what(), ":3: friction.mue: unknown key"));
  EXPECT_TRUE(has_text(error_in("[penalty]\ndn = 1e-6\n", "penalty.dn", 2).hint, "`penalty.dN`"));
}

TEST_F(CaseFile, KeyOutsideAnySectionNamesItsSection) {
  EXPECT_TRUE(has_text(error_in("\nspeed = 2.0\n", "speed", 2).hint, "`process.speed`"));
}

TEST_F(CaseFile, UnknownSectionNamesTheClosestSection) {
  const InputError error =
      error_in("[process]\ntype = \"extrusion\"\n\n[frction]\nmu = 0.1\n", "frction", 4);
  EXPECT_TRUE(has_text(error.message, "unknown section"));
  EXPECT_TRUE(has_text(error.hint, "`[friction]`"));
}

TEST_F(CaseFile, WrongTypeSaysWhatIsExpected) {
  const InputError error = error_in("[mesh]\n\nsize = \"fine\"\n", "mesh.size", 3);
  EXPECT_TRUE(has_text(error.message, "expected a real number, got string \"fine\""));
  EXPECT_TRUE(
      has_text(error_in("[integration]\nvolumetric = 2.0\n", "integration.volumetric", 2).message,
               "expected an integer"));
  EXPECT_TRUE(has_text(error_in("[mesh]\nelement = 2\n", "mesh.element", 2).message,
                       "expected a string, got integer 2"));
  EXPECT_TRUE(has_text(error_in("[friction]\non = \"die\"\n", "friction.on", 2).message,
                       "expected a list of strings"));
  EXPECT_TRUE(has_text(error_in("process = 1\n", "process", 1).message, "expected a section"));
}

TEST_F(CaseFile, IntegersAreAcceptedForRealKeys) {
  const Case case_ =
      load_case(write("[process]\nspeed = 2\n[material]\nA = 1\n[mesh]\nsize = 5\n"), {});
  EXPECT_EQ(case_.process.speed, 2.0);
  EXPECT_EQ(case_.material.parameters_of<physics::PiecewisePower>().A, 1.0);
  EXPECT_EQ(case_.mesh.size, 5.0);
}

TEST_F(CaseFile, OutOfRangeValuesNameTheRange) {
  const InputError mu = error_in("[friction]\nmu = -0.1\n", "friction.mu", 2);
  EXPECT_TRUE(has_text(mu.message, "-0.1"));
  EXPECT_TRUE(has_text(mu.hint, "0 ≤ value ≤ 10"));
  // d = 0 is the exact constraint: valid only for the mixed formulation (docs/mixed.md).
  EXPECT_TRUE(has_text(error_in("[penalty]\nd = 0\n", "penalty.d", 2).hint, "\"mixed\""));
  EXPECT_TRUE(
      has_text(error_in("[penalty]\nd = -1e-3\n", "penalty.d", 2).hint, "0, or 1e-15 ≤ value"));
  EXPECT_TRUE(has_text(error_in("[solver]\ntolerance = 1\n", "solver.tolerance", 2).hint,
                       "1e-15 ≤ value < 1"));
  EXPECT_TRUE(
      has_text(error_in("[material]\nalpha = nan\n", "material.alpha", 2).message, "not finite"));
  const InputError volumetric =
      error_in("[integration]\nvolumetric = 4\n", "integration.volumetric", 2);
  EXPECT_TRUE(has_text(volumetric.hint, "1 ≤ value ≤ 3"));
}

TEST_F(CaseFile, InvalidChoicesListTheValidOnes) {
  const InputError element = error_in("[mesh]\nelement = \"Q3\"\n", "mesh.element", 2);
  EXPECT_TRUE(has_text(element.message, "\"Q3\""));
  EXPECT_TRUE(has_text(element.hint, "\"Q1\", \"Q2\""));
  const InputError entry =
      error_in("[friction]\non = [\"container\", \"wall\"]\n", "friction.on", 2);
  EXPECT_TRUE(has_text(entry.message, "\"wall\""));
  EXPECT_TRUE(has_text(entry.hint, "\"container\", \"die\""));
  EXPECT_TRUE(has_text(error_in("[friction]\non = [\"die\", \"die\"]\n", "friction.on", 2).message,
                       "duplicate"));
}

TEST_F(CaseFile, MeshSizeThatDoesNotFitSuggestsSizesThatDo) {
  const InputError error =
      error_in("[geometry]\nexit_length = 10\n[mesh]\nsize = 0.3\n", "mesh.size", 4);
  EXPECT_TRUE(has_text(error.message, "geometry.container_length"));
  EXPECT_TRUE(has_text(error.hint, "(= 10/34)"));
  EXPECT_TRUE(has_text(error.hint, "0.3125 (= 10/32)"));
  // Every suggested size must itself be accepted.
  for (const std::string size : {"0.3", "0.7", "3", "1.7", "0.123"}) {
    const InputError unfit = load_error("", {{"mesh.size", size}});
    const std::regex suggestion("([0-9.e+-]+) \\(= ");
    int n_suggestions = 0;
    for (std::sregex_iterator it(unfit.hint.begin(), unfit.hint.end(), suggestion), end; it != end;
         ++it, ++n_suggestions)
      EXPECT_NO_THROW(load_case("", {{"mesh.size", (*it)[1].str()}})) << unfit.hint;
    EXPECT_GE(n_suggestions, 1) << unfit.hint;
  }
}

TEST_F(CaseFile, MeshIOfTheSpecFits) {
  EXPECT_EQ(load_case(write("[mesh]\nsize = 1.6666666666666667\n"), {}).mesh.size, 10.0 / 6.0);
}

TEST_F(CaseFile, LengthThatDoesNotFitTheDefaultSizeIsBlamed) {
  const InputError error =
      error_in("[geometry]\ncontainer_length = 10.5\n", "geometry.container_length", 2);
  EXPECT_TRUE(has_text(error.message, "mesh.size"));
}

TEST_F(CaseFile, CrossKeyErrorsBlameTheKeySetLast) {
  EXPECT_TRUE(has_text(error_in("[material]\nrate1 = 10\nrate2 = 10\n", "material.rate2", 3).hint,
                       "material.rate2 must be > material.rate1"));
  EXPECT_TRUE(has_text(error_in("[material]\nrate1 = 2000\n", "material.rate1", 2).hint,
                       "material.rate1 must be < material.rate2"));
  error_in("[geometry]\nexit_half_height = 10\n", "geometry.exit_half_height", 2);
  error_in("[geometry]\nexit_half_height = 4\n\nentry_half_height = 3\n",
           "geometry.entry_half_height", 4);
}

TEST_F(CaseFile, TomlSyntaxErrorNamesFileAndLine) {
  const InputError error = error_in("[friction]\nmu = 0.1\nradius = 0.1 x\n", "syntax", 3);
  EXPECT_TRUE(has_text(error.message, "invalid TOML"));
  EXPECT_TRUE(has_text(error.hint, "radius = 0.1 x"));
  EXPECT_TRUE(has_text(error_in("[mesh]\nelement = Q2\n", "syntax", 2).hint, "quotes"));
  error_in("[mesh]\nsize = 1.0\nsize = 2.0\n", "syntax", 3);
}

TEST_F(CaseFile, MissingOrUnreadableFileIsAnInputError) {
  const std::string missing = (directory_ / "missing.toml").string();
  const InputError error = load_error(missing);
  EXPECT_EQ(error.file, missing);
  EXPECT_EQ(error.line, 0);
  EXPECT_TRUE(has_text(error.message, "no such file"));
  EXPECT_TRUE(has_text(load_error(directory_.path().string()).message, "not a regular file"));
}

TEST_F(CaseFile, OverridesApplyAfterTheFileInOrder) {
  const std::string path = write("[friction]\nmu = 0.1\n");
  EXPECT_EQ(load_case(path, {}).friction.mu, 0.1);
  EXPECT_EQ(load_case(path, {{"friction.mu", "0.3"}}).friction.mu, 0.3);
  EXPECT_EQ(load_case(path, {{"friction.mu", "0.3"}, {"friction.mu", "0.2"}}).friction.mu, 0.2);
  // Cross-key checks run after all overrides: a bad file size fixed on the command line is fine.
  EXPECT_EQ(load_case(write("[mesh]\nsize = 0.3\n"), {{"mesh.size", "0.5"}}).mesh.size, 0.5);
}

TEST_F(CaseFile, OverrideValuesAreTomlOrBareWords) {
  EXPECT_EQ(load_case("", {{"mesh.element", "\"Q1\""}}).element, fem::ElementKind::Q1);
  EXPECT_EQ(load_case("", {{"mesh.element", "Q1"}}).element, fem::ElementKind::Q1);
  EXPECT_EQ(load_case("", {{"process.type", "drawing"}}).process.type,
            physics::ProcessType::Drawing);
  EXPECT_EQ(load_case("", {{"integration.volumetric", "3"}}).volumetric_points, 3);
  const Case die_only = load_case("", {{"friction.on", "[\"die\"]"}});
  EXPECT_FALSE(die_only.friction.on_container);
  EXPECT_TRUE(die_only.friction.on_die);
  const Case nowhere = load_case("", {{"friction.on", "[]"}});
  EXPECT_FALSE(nowhere.friction.on_container || nowhere.friction.on_die);
}

TEST_F(CaseFile, OverrideErrorsNameSetAndTheKey) {
  auto check = [](const Override& assignment, const std::string& key, const std::string& part) {
    const InputError error = load_error("", {assignment});
    EXPECT_EQ(error.file, "--set");
    EXPECT_EQ(error.line, 0);
    EXPECT_EQ(error.key, key);
    EXPECT_TRUE(has_text(error.what(), part));
  };
  check({"friction.muu", "0.1"}, "friction.muu", "did you mean `friction.mu`?");
  // The example is a key of that section (the nearest by edit distance).
  check({"friction", "0.1"}, "friction", "e.g. `friction.");
  check({"friction.mu", "-1"}, "friction.mu", "0 ≤ value ≤ 10");
  check({"mesh.size", "fine"}, "mesh.size", "got string \"fine\"");
  check({"mesh.element", "Q3"}, "mesh.element", "\"Q1\", \"Q2\"");
  check({"friction.on", "[die]"}, "friction.on", "expected a list of strings");
  check({"geometry.exit_half_height", "12"}, "geometry.exit_half_height", "entry_half_height");
}

TEST_F(CaseFile, EnumChoicesMapToTheirEnumerators) {
  using physics::ProcessType, physics::RamCondition, physics::ViscousStrain;
  EXPECT_EQ(load_case("", {{"process.type", "extrusion"}}).process.type, ProcessType::Extrusion);
  EXPECT_EQ(load_case("", {{"process.ram", "sticking"}}).process.ram, RamCondition::Sticking);
  EXPECT_EQ(load_case("", {{"process.ram", "sliding"}}).process.ram, RamCondition::Sliding);
  EXPECT_EQ(load_case("", {{"mesh.element", "Q2"}}).element, fem::ElementKind::Q2);
  EXPECT_EQ(load_case("", {{"formulation.viscous_strain", "deviatoric"}}).viscous_strain,
            ViscousStrain::Deviatoric);
  EXPECT_EQ(load_case("", {{"formulation.viscous_strain", "full"}}).viscous_strain,
            ViscousStrain::Full);
}

TEST_F(CaseFile, JsonUsesCaseFileNamesAndDefaults) {
  const nlohmann::json json = case_to_json(load_case("", {}));
  EXPECT_EQ(json["process"],
            nlohmann::json::parse(R"({"type": "extrusion", "speed": 1.0, "ram": "sliding"})"));
  EXPECT_EQ(json["penalty"], nlohmann::json::parse(R"({"d": 1e-3, "dN": 1e-6, "dT": 1e-6})"));
  EXPECT_EQ(json["friction"]["on"], nlohmann::json::parse(R"(["container", "die"])"));
  EXPECT_EQ(json["integration"]["volumetric"], 2);
  EXPECT_TRUE(json["integration"]["volumetric"].is_number_integer());
  EXPECT_EQ(json["source"], "<default>");
}

TEST_F(CaseFile, JsonRoundTripsEveryKey) {
  // A non-default value for every key, written as it would be on the command line.
  const std::vector<Override> values = {
      {"process.type", "\"drawing\""},
      {"process.speed", "2.5"},
      {"process.ram", "\"sticking\""},
      {"geometry.container_length", "12.0"},
      {"geometry.entry_half_height", "8.0"},
      {"geometry.exit_half_height", "4.0"},
      {"geometry.exit_length", "6.0"},
      {"geometry.die", "\"polyline\""},
      {"geometry.die_angle", "20.0"},
      {"geometry.die_radius", "6.0"},
      {"geometry.die_profile", "[[0.0, 8.0], [2.0, 6.0], [5.0, 4.0]]"},
      {"geometry.land_length", "1.0"},
      {"geometry.symmetry", "\"axisymmetric\""},
      // The solid-channel keys at their defaults: a plane (axisymmetric) case refuses
      // other values (their round trip in 3D: test_solid_keys.cpp).
      {"geometry.dimension", "2"},
      {"geometry.section", "\"slab\""},
      {"geometry.thickness", "1.0"},
      {"geometry.entry_half_width", "10.0"},
      {"geometry.exit_half_width", "5.0"},
      // The profile's keys at their defaults too (a profile is 3D; its keys' checks:
      // tests/gmsh/test_profile_die_cli.cpp); bearing_length is a list in JSON.
      {"geometry.profile", "[]"},
      {"geometry.profile_file", "\"\""},
      {"geometry.profile_symmetry", "\"none\""},
      {"geometry.billet_radius", "10.0"},
      {"geometry.bearing_length", "[1.0]"},
      {"mesh.bearing_size", "0.0"},
      {"mesh.cad_file", "\"\""},
      {"mesh.cell", "\"quadrilateral\""},
      {"mesh.element", "\"Q1\""},
      {"mesh.size", "0.5"},
      {"mesh.source", "\"file\""},
      {"mesh.file", "\"meshes/die.msh\""},
      {"mesh.boundaries", "{ram = \"rear\", wall = \"container\"}"},
      {"integration.volumetric", "1"},
      {"material.A", "2.0"},
      {"material.alpha", "0.2"},
      {"material.rate1", "0.01"},
      {"material.rate2", "100.0"},
      {"material.law", "\"hensel_spittel\""},
      {"material.K", "0.7"},
      {"material.m", "0.3"},
      {"material.sigma0", "2.2"},
      {"material.hs_A", "250.0"},
      {"material.hs_m1", "-0.003"},
      {"material.hs_m2", "0.12"},
      {"material.hs_m3", "0.1"},
      {"material.hs_m4", "-0.02"},
      {"material.hs_m8", "0.0001"},
      {"material.temperature", "650.0"},
      {"material.strain", "0.4"},
      {"material.st_alpha", "0.05"},
      {"material.st_n", "4.5"},
      {"material.st_Q", "150000.0"},
      {"material.st_A", "20000000.0"},
      {"material.st_R", "8.3"},
      {"formulation.viscous_strain", "\"deviatoric\""},
      // default: "mixed" is refused with axisymmetric
      // (its JSON is checked in test_formulation_keys.cpp)
      {"formulation.type", "\"penalty\""},
      {"formulation.pressure", "\"P0\""},
      // "saddle_point" needs the mixed formulation, which other values here exclude.
      {"formulation.discontinuous_pressure", "\"condensed\""},
      {"formulation.augmentation", "100.0"},
      {"formulation.contact_augmentation", "1000.0"},
      {"formulation.uzawa_tolerance", "1e-06"},
      {"formulation.uzawa_max_steps", "7"},
      {"contact.normals", "\"nodes\""},
      {"contact.corner_angle", "30.0"},
      {"friction.law", "\"hybrid\""},
      {"friction.mu", "0.15"},
      {"friction.m", "0.4"},
      {"friction.radius", "0.5"},
      {"friction.on", "[\"die\"]"},
      {"friction.regularization", "\"none\""},
      {"friction.augmentation", "10.0"},
      {"friction.newton_augmentation", "1000.0"},
      // default: "exact" is refused with the secant method below (test_formulation_keys.cpp)
      {"friction.stick", "\"augmented\""},
      {"penalty.d", "0.01"},
      {"penalty.dN", "1e-05"},
      {"penalty.dT", "1e-07"},
      {"solver.tolerance", "1e-06"},
      {"solver.max_iterations", "42"},
      {"solver.initial_rate", "0.5"},
      {"solver.linear", "\"umfpack\""},
      {"solver.method", "\"secant\""},
      {"solver.acceleration", "\"anderson\""},
      {"solver.acceleration_depth", "3"},
      {"solver.newton_start", "0.2"},
      {"solver.coarse_levels", "2"},
      // thermal.enabled stays false: hybrid friction above is refused with it (its
      // switch itself: test_thermal_keys.cpp).
      {"thermal.enabled", "false"}, // a switch: a JSON and TOML boolean
      {"thermal.temperature_unit", "\"kelvin\""},
      {"thermal.billet_temperature", "700.0"},
      {"thermal.density", "2.0"},
      {"thermal.heat_capacity", "3.0"},
      {"thermal.conductivity", "4.0"},
      {"thermal.taylor_quinney", "0.95"},
      {"thermal.friction_share", "0.25"},
      {"thermal.tool_temperature", "680.0"},
      {"thermal.heat_transfer", "5.0"},
      {"thermal.free_surface_transfer", "0.5"},
      {"thermal.ambient_temperature", "300.0"},
      {"thermal.max_temperature", "900.0"},
      {"thermal.coupling_tolerance", "1e-05"},
      {"thermal.max_coupling_iterations", "12"},
      // Empty: options are refused unless solver.linear = "petsc", which a build
      // without PETSc refuses in turn.
      {"solver.petsc_options", "\"\""},
      {"solver.load_error", "\"linearized\""},
      // adapt.target_error stays 0: adaptivity is refused with the secant method above.
      {"adapt.target_error", "0.0"},
      {"adapt.max_cycles", "5"},
      {"adapt.max_dofs", "12345"},
      {"adapt.fraction", "0.3"},
      {"adapt.coarsen_fraction", "0.02"},
      {"verification.solution", "\"smooth\""},
      {"verification.distortion", "\"random\""},
      {"verification.amplitude", "0.2"},
      {"verification.seed", "7"}};
  ASSERT_EQ(values.size(), case_keys().size()) << "a key was added: give it a value here";
  const nlohmann::json json = case_to_json(load_case("", values));
  std::size_t n_keys = 0;
  for (const auto& [section, table] : json.items())
    if (table.is_object()) n_keys += table.size();
  EXPECT_EQ(n_keys, case_keys().size());
  std::vector<Override> from_json;
  for (const auto& [name, text] : values) {
    const std::string section = name.substr(0, name.find('.')),
                      leaf = name.substr(name.find('.') + 1);
    ASSERT_TRUE(json.contains(section) && json[section].contains(leaf)) << name;
    if (json[section][leaf].is_object()) {
      // A table key: a JSON object, given back as a TOML inline table.
      EXPECT_EQ(json[section][leaf],
                nlohmann::json::parse(R"({"ram": "rear", "wall": "container"})"));
      std::string table;
      for (const auto& [entry, value] : json[section][leaf].items())
        table += (table.empty() ? "{" : ", ") + entry + " = " + value.dump();
      from_json.emplace_back(name, table + "}");
      continue;
    }
    EXPECT_EQ(json[section][leaf], nlohmann::json::parse(text)) << name;
    from_json.emplace_back(name, json[section][leaf].dump());
  }
  EXPECT_EQ(nlohmann::json(case_to_json(load_case("", from_json))), json);
}

} // namespace
} // namespace formflow::io
