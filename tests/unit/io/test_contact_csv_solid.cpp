// SPDX-License-Identifier: MIT
// contact.csv of a solid run: x, y, z and no arc length; a plane run's file is unchanged.
#include "formflow/core/error.hpp"
#include "formflow/io/csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace formflow::testing {

namespace {

std::vector<post::ContactSample> two_samples() {
  post::ContactSample wall;
  wall.arc_length = 7.5; // a plane run's s; a solid run has none to write
  wall.x = 0.25, wall.y = 1.0, wall.z = 0.75;
  wall.contact_pressure = 2.5, wall.friction_stress = 0.5, wall.slip_velocity = 1.25;
  post::ContactSample die = wall;
  die.z = -0.125, die.sticking = true, die.part = 1;
  return {wall, die};
}

TEST(SolidContactCsv, ThreeCoordinatesNoArcLength) {
  EXPECT_EQ(io::contact_csv(two_samples(), solvers::StopReason::Converged, 3),
            "x,y,z,contact_pressure,friction_stress,slip_velocity,state,part\n"
            "0.25,1,0.75,2.5,0.5,1.25,slip,container\n"
            "0.25,1,-0.125,2.5,0.5,1.25,stick,die\n");
}

TEST(SolidContactCsv, PlaneFileKeepsItsColumns) {
  EXPECT_EQ(io::contact_csv(two_samples()),
            "s,x,y,contact_pressure,friction_stress,slip_velocity,state,part\n"
            "7.5,0.25,1,2.5,0.5,1.25,slip,container\n"
            "7.5,0.25,1,2.5,0.5,1.25,stick,die\n");
}

TEST(SolidContactCsv, NonFiniteZIsAnInternalError) {
  auto samples = two_samples();
  samples[1].z = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_THROW(io::contact_csv(samples, solvers::StopReason::Converged, 3), InternalError);
}

} // namespace

} // namespace formflow::testing
