// SPDX-License-Identifier: MIT
// Die geometries that are valid pass `formflow check`; the bad ones are in
// test_validation.cpp's table of bad cases (exit 2, file:line, key and hint).
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using formflow::testing::quoted;

TEST(DieValidation, GoodPolylineAndArcPassCheck) {
  const formflow::testing::ScratchDirectory scratch("formflow-die");
  const std::string check =
      "check " + quoted(std::string(FORMFLOW_SOURCE_DIR) + "/cases/paper-q2-2x2-mesh2.toml");
  auto run = [&scratch](const std::string& arguments) {
    return formflow::testing::run_cli(arguments, scratch.path());
  };
  const auto polyline = run(check + " --set geometry.die=polyline"
                                    " --set 'geometry.die_profile=[[0, 10], [4, 7.5], [9.5, 5]]'"
                                    " --set geometry.land_length=2");
  EXPECT_EQ(polyline.exit_code, 0) << polyline.err;
  const auto arc = run(check + " --set geometry.die=arc --set geometry.die_radius=5"
                               " --set geometry.symmetry=axisymmetric --set process.type=drawing");
  EXPECT_EQ(arc.exit_code, 0) << arc.err;
  // A profile entry that is not an [x, y] pair is a type error, exit 2.
  const auto pair = run(check + " --set 'geometry.die_profile=[[0, 10, 3]]'");
  EXPECT_EQ(pair.exit_code, 2) << pair.err;
  EXPECT_TRUE(formflow::testing::has_text(pair.err, "geometry.die_profile"));
}

} // namespace
