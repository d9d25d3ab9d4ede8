// SPDX-License-Identifier: MIT
// A profile's outline (mesh/profile_die.hpp): what a flat die's opening must be, the
// nearest edge that splits the exit section, and the outline CSV.
#include "formflow/mesh/profile_die.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace formflow::mesh {
namespace {

ProfileDie die_of(std::vector<std::array<Real, 2>> outline,
                  ProfileSymmetry symmetry = ProfileSymmetry::None) {
  ProfileDie die;
  die.outline = std::move(outline);
  die.symmetry = symmetry;
  die.billet_radius = 6.0;
  return die;
}

const std::vector<std::array<Real, 2>> t_section = {{-4, 1},  {-4, 2},   {4, 2},     {4, 1},
                                                    {0.5, 1}, {0.5, -3}, {-0.5, -3}, {-0.5, 1}};

TEST(ProfileOutline, ASimplePolygonInsideTheBilletIsAnOpening) {
  EXPECT_FALSE(profile_outline_problem(die_of({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})));
  // Either way round.
  EXPECT_FALSE(profile_outline_problem(die_of({{-1, -1}, {-1, 1}, {1, 1}, {1, -1}})));
  EXPECT_FALSE(profile_outline_problem(die_of(t_section, ProfileSymmetry::Y)));
}

TEST(ProfileOutline, WhatIsNoOpeningIsNamed) {
  const auto problem = [](ProfileDie die) { return profile_outline_problem(die).value_or(""); };
  EXPECT_NE(problem(die_of({{0, 0}, {1, 0}})).find("at least 3"), std::string::npos);
  // A bow tie: edges 0 and 2 cross.
  EXPECT_NE(problem(die_of({{0, 0}, {2, 2}, {2, 0}, {0, 2}})).find("cross or touch"),
            std::string::npos);
  // A spike that folds back along itself.
  EXPECT_NE(problem(die_of({{0, 0}, {2, 0}, {1, 0}, {1, 1}})).find("fold"), std::string::npos);
  // The first point repeated at the end.
  EXPECT_NE(problem(die_of({{0, 0}, {1, 0}, {1, 1}, {0, 0}})).find("repeated first point"),
            std::string::npos);
  // A corner outside the billet (radius 6).
  EXPECT_NE(problem(die_of({{0, 0}, {5, 0}, {5, 5}})).find("not inside the billet"),
            std::string::npos);
  // A T is symmetric about y = 0, not about z = 0.
  EXPECT_NE(problem(die_of(t_section, ProfileSymmetry::YZ)).find("not symmetric about z = 0"),
            std::string::npos);
  std::vector<std::array<Real, 2>> skewed = t_section;
  skewed[0][0] = -3.9;
  EXPECT_NE(problem(die_of(skewed, ProfileSymmetry::Y)).find("not symmetric about y = 0"),
            std::string::npos);
}

TEST(ProfileOutline, NearestEdgesMirrorWithASymmetricOutline) {
  const ProfileDie die = die_of(t_section, ProfileSymmetry::Y);
  // Edge k's mirror in y = 0 (the T's outline runs round; edge 3 ↔ 7, 4 ↔ 6, 0 ↔ 2).
  const auto mirror = [](std::size_t e) { return (10 - e) % 8; };
  // Near the web's corner (0.5, 1) edges 3 and 4 are both nearest at the shared vertex
  // ((0.45, 1.05) is on its bisector, where even their lines tie); the tie is broken the
  // same way on both sides.
  for (const std::array<Real, 2>& p : std::vector<std::array<Real, 2>>{
           {0.3, 1.2}, {0.45, 1.05}, {2, 1.4}, {0.2, -1}, {3.9, 1.9}, {0.1, -2.95}}) {
    const std::size_t e = nearest_edge(die, p);
    EXPECT_EQ(nearest_edge(die, {-p[0], p[1]}), mirror(e)) << p[0] << ", " << p[1];
  }
  EXPECT_EQ(nearest_edge(die, {0.3, 1.2}), 3u);   // alongside the flange, beyond the web's end
  EXPECT_EQ(nearest_edge(die, {0.45, 1.05}), 3u); // the bisector: the edge along y
  EXPECT_EQ(nearest_edge(die, {0.4, -1}), 4u);
  EXPECT_DOUBLE_EQ(distance_to_edge(die, 4, {0.2, -1}), 0.3);
  ASSERT_EQ(symmetry_images(die, {1, 2}).size(), 2u);
  EXPECT_EQ(symmetry_images(die, {1, 2})[1], (std::array<Real, 2>{-1, 2}));
}

TEST(ProfileOutline, AreaAndModelVolume) {
  ProfileDie die = die_of(t_section, ProfileSymmetry::Y);
  EXPECT_DOUBLE_EQ(outline_area(die), 12.0); // flange 8 + web 4
  die.bearing_length = {1.0, 2.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  EXPECT_DOUBLE_EQ(die.longest_bearing(), 2.0);
  EXPECT_DOUBLE_EQ(die.bearing(1), 2.0);
  // Half of the billet πR²L_c and of the prism A (max bearing + L_e): the same dozen
  // roundings in another order, each within ε of its result (all terms positive), so
  // within 16 ε of the volume.
  const double volume = 0.5 * (std::numbers::pi * 36 * 3 + 12.0 * 3.0);
  EXPECT_NEAR(profile_model_volume(die, 3.0, 1.0), volume,
              16 * std::numeric_limits<double>::epsilon() * volume);
}

TEST(ProfileCsv, PointsHeaderCommentsAndTheLineOfAProblem) {
  const ProfileFileRead read =
      read_profile_csv("y, z\n# an L\n0, 0\n\n4,0\n4 1 # corner\n0;1\n", 100);
  ASSERT_TRUE(read.problem.empty()) << read.problem;
  ASSERT_EQ(read.points.size(), 4u);
  EXPECT_EQ(read.points[2], (std::array<Real, 2>{4, 1}));
  const ProfileFileRead bad = read_profile_csv("y,z\n0,0\n1,0,2\n", 100);
  EXPECT_EQ(bad.line, 3);
  EXPECT_NE(bad.problem.find("two numbers"), std::string::npos);
  const ProfileFileRead second_header = read_profile_csv("y,z\n0,0\nthe end\n", 100);
  EXPECT_EQ(second_header.line, 3); // only the first line may be a header
  const ProfileFileRead too_many = read_profile_csv("0,0\n1,0\n1,1\n", 2);
  EXPECT_EQ(too_many.line, 3);
  EXPECT_EQ(read_profile_csv("0,1e400\n", 10).line, 1); // out of range: not read as a number
}

} // namespace
} // namespace formflow::mesh
