// SPDX-License-Identifier: MIT
// formulation.* keys and the exact constraints: what is accepted, what is refused
// (key, file, line, hint).
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_json.hpp"
#include "formflow/io/problem_shape.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace formflow::io {
namespace {

namespace fs = std::filesystem;

::testing::AssertionResult formulation_hint_has_text(const std::string& text,
                                                     const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

InputError refusal(const std::string& path, const std::vector<Override>& overrides) {
  try {
    load_case(path, overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "load_case did not throw InputError";
  return InputError("", -1, "", "");
}

TEST(FormulationKeys, MixedWithExactConstraintsIsAccepted) {
  const Case case_ = load_case("", {{"formulation.type", "mixed"},
                                    {"formulation.pressure", "P1disc"},
                                    {"penalty.d", "0"},
                                    {"penalty.dN", "0"}});
  EXPECT_EQ(case_.formulation.type, assembly::FormulationType::Mixed);
  EXPECT_EQ(case_.formulation.pressure, fem::PressureSpace::P1disc);
  EXPECT_EQ(case_.penalty.d, 0.0);
  EXPECT_EQ(case_.penalty.d_n, 0.0);
}

TEST(FormulationKeys, MixedIsWrittenToTheResolvedCase) {
  const nlohmann::json json = case_to_json(load_case("", {{"formulation.type", "mixed"}}));
  EXPECT_EQ(json["formulation"]["type"], "mixed");
  EXPECT_EQ(json["formulation"]["pressure"], "P1disc");
}

TEST(FormulationKeys, ExactContactIsAcceptedWithThePenaltyFormulation) {
  EXPECT_EQ(load_case("", {{"penalty.dN", "0"}}).penalty.d_n, 0.0);
}

TEST(FormulationKeys, ExactIncompressibilityNeedsTheMixedFormulation) {
  const InputError error = refusal("", {{"penalty.d", "0"}});
  EXPECT_EQ(error.key, "penalty.d");
  EXPECT_EQ(error.file, "--set");
  EXPECT_TRUE(formulation_hint_has_text(error.hint, "formulation.type = \"mixed\""));
}

TEST(FormulationKeys, NegativePenaltyIsOutOfRange) {
  EXPECT_EQ(refusal("", {{"penalty.d", "-1e-3"}}).key, "penalty.d");
}

TEST(FormulationKeys, TaylorHoodIsAcceptedWithQ2AndExactConstraints) {
  const Case case_ = load_case("", {{"formulation.type", "mixed"},
                                    {"formulation.pressure", "Q1"},
                                    {"mesh.element", "Q2"},
                                    {"penalty.d", "0"},
                                    {"penalty.dN", "0"}});
  EXPECT_EQ(case_.formulation.pressure, fem::PressureSpace::Q1);
  EXPECT_EQ(case_.penalty.d, 0.0);
}

TEST(FormulationKeys, UnstableOrUnimplementedPairsAreRefused) {
  const InputError q1_q1 = refusal(
      "", {{"formulation.type", "mixed"}, {"formulation.pressure", "Q1"}, {"mesh.element", "Q1"}});
  EXPECT_EQ(q1_q1.key, "mesh.element");
  EXPECT_TRUE(formulation_hint_has_text(q1_q1.message, "Q1 velocity"));
  const InputError locking = refusal(
      "",
      {{"formulation.type", "mixed"}, {"formulation.pressure", "P1disc"}, {"mesh.element", "Q1"}});
  EXPECT_EQ(locking.key, "mesh.element"); // set last: the one to change
  EXPECT_TRUE(formulation_hint_has_text(locking.hint, "P0"));
  const InputError checkerboard = refusal("", {{"mesh.element", "Q1"},
                                               {"formulation.type", "mixed"},
                                               {"formulation.pressure", "P0"},
                                               {"penalty.d", "0"}});
  EXPECT_EQ(checkerboard.key, "penalty.d");
  EXPECT_TRUE(formulation_hint_has_text(checkerboard.message, "inf-sup"));
}

TEST(FormulationKeys, CombinationsNotYetSupportedAreRefused) {
  // The mixed formulation's divergence has the hoop rate (test_axisymmetric_divergence.cpp).
  EXPECT_NO_THROW(
      load_case("", {{"formulation.type", "mixed"}, {"geometry.symmetry", "axisymmetric"}}));
  const InputError exact_friction =
      refusal("", {{"friction.regularization", "none"}, {"penalty.dN", "0"}});
  EXPECT_EQ(exact_friction.key, "penalty.dN");
  EXPECT_TRUE(formulation_hint_has_text(exact_friction.hint, "regularized"));
  const InputError friction_taylor_hood = refusal("", {{"formulation.type", "mixed"},
                                                       {"formulation.pressure", "Q1"},
                                                       {"friction.regularization", "none"}});
  EXPECT_EQ(friction_taylor_hood.key, "friction.regularization");
  EXPECT_TRUE(formulation_hint_has_text(friction_taylor_hood.message, "Taylor–Hood"));
}

TEST(FormulationKeys, ExactStickNeedsExactFrictionNodalPointsAndNewton) {
  const Case accepted = load_case("", {{"friction.regularization", "none"},
                                       {"contact.normals", "nodes"},
                                       {"friction.stick", "exact"}});
  EXPECT_EQ(accepted.friction_stick, StickEnforcement::Exact);
  EXPECT_EQ(load_case("", {}).friction_stick, StickEnforcement::Auto);
  const InputError regularised =
      refusal("", {{"contact.normals", "nodes"}, {"friction.stick", "exact"}});
  EXPECT_EQ(regularised.key, "friction.stick");
  EXPECT_TRUE(formulation_hint_has_text(regularised.hint, "friction.regularization = \"none\""));
  // An explicit pair that conflicts is refused, never overridden.
  const InputError faces = refusal("", {{"friction.regularization", "none"},
                                        {"contact.normals", "faces"},
                                        {"friction.stick", "exact"}});
  EXPECT_EQ(faces.key, "friction.stick");
  EXPECT_TRUE(formulation_hint_has_text(faces.hint, "contact.normals = \"nodes\""));
  const InputError secant = refusal("", {{"friction.regularization", "none"},
                                         {"contact.normals", "nodes"},
                                         {"friction.stick", "exact"},
                                         {"solver.method", "secant"}});
  EXPECT_EQ(secant.key, "solver.method");
  EXPECT_TRUE(formulation_hint_has_text(secant.hint, "solver.method = \"newton\""));
  EXPECT_EQ(refusal("", {{"friction.stick", "penalty"}}).key, "friction.stick");
}

TEST(FormulationKeys, RefusalInAFileNamesItsLine) {
  const fs::path path =
      fs::temp_directory_path() / ("formflow-formulation-" + std::to_string(getpid()) + ".toml");
  std::ofstream(path) << "[formulation]\ntype = \"penalty\"\n\n[penalty]\nd = 0\n";
  const InputError error = refusal(path.string(), {});
  fs::remove(path);
  EXPECT_EQ(error.key, "penalty.d");
  EXPECT_EQ(error.line, 5);
}

// friction.stick = "auto" (the default): the semismooth Newton on nodal points for the
// exact law under Newton; what the user gave is honoured; elsewhere today's paths.
TEST(FormulationKeys, TheExactLawUnderNewtonGetsExactStickOnNodesByDefault) {
  using assembly::ContactNormals;
  const StickChoice exact = stick_choice(load_case("", {{"friction.regularization", "none"}}));
  EXPECT_EQ(exact.stick, StickEnforcement::Exact);
  EXPECT_EQ(exact.normals, ContactNormals::Nodes);
  EXPECT_FALSE(exact.stick_given);
  EXPECT_FALSE(exact.normals_given);
  const Case explicit_exact =
      load_case("", {{"friction.regularization", "none"}, {"friction.stick", "exact"}});
  EXPECT_EQ(stick_choice(explicit_exact).normals, ContactNormals::Nodes);
  EXPECT_TRUE(problem_shape(explicit_exact).nodal_contact);

  // Given faces are honoured: the augmented loop on face points, with a warning.
  const Case faces =
      load_case("", {{"friction.regularization", "none"}, {"contact.normals", "faces"}});
  EXPECT_EQ(stick_choice(faces).stick, StickEnforcement::Augmented);
  EXPECT_EQ(stick_choice(faces).normals, ContactNormals::Faces);
  ASSERT_EQ(faces.warnings.size(), 1u);
  EXPECT_TRUE(formulation_hint_has_text(faces.warnings[0], "--set: contact.normals = \"faces\""));
  // The old path by key: augmented stick keeps the face points.
  const StickChoice augmented = stick_choice(
      load_case("", {{"friction.regularization", "none"}, {"friction.stick", "augmented"}}));
  EXPECT_EQ(augmented.stick, StickEnforcement::Augmented);
  EXPECT_EQ(augmented.normals, ContactNormals::Faces);
  EXPECT_TRUE(load_case("", {{"friction.regularization", "none"}, {"friction.stick", "augmented"}})
                  .warnings.empty());

  // Where exact stick is not available: the secant loop, the regularised law.
  const StickChoice secant = stick_choice(
      load_case("", {{"friction.regularization", "none"}, {"solver.method", "secant"}}));
  EXPECT_EQ(secant.stick, StickEnforcement::Augmented);
  EXPECT_EQ(secant.normals, ContactNormals::Faces);
  const StickChoice regularised = stick_choice(load_case("", {}));
  EXPECT_EQ(regularised.stick, StickEnforcement::Augmented);
  EXPECT_EQ(regularised.normals, ContactNormals::Faces);
  EXPECT_EQ(stick_choice(load_case("", {{"contact.normals", "nodes"}})).normals,
            ContactNormals::Nodes);
}

} // namespace
} // namespace formflow::io
