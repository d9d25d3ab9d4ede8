// SPDX-License-Identifier: MIT
// Post-processing that walks the contact boundary, on Gmsh's unstructured mesh.
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/post/post_process.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace formflow {
namespace {

TEST(GeneralMeshPost, ContactProfileFollowsTheWallThenTheDieByArcLength) {
  // On the channel meshed by Gmsh the contact facets come in no particular
  // order or orientation. The profile must still start at the ram end of the
  // container wall and run along the wall (s = x) and down the die face
  // (s = L_c + H_in − y), every sample once.
  const mesh::ChannelGeometry geometry;
  for (const int order : {1, 2}) {
    const mesh::Mesh<2> mesh = mesh::make_gmsh_channel_mesh(geometry, 1.0, order);
    const assembly::FormingProblem<2> problem(mesh, assembly::ProblemSettings{});
    const VectorX velocity = VectorX::Zero(problem.n_dofs());
    const auto contact = problem.contact_state(velocity);
    const std::vector<post::ContactSample> profile = post::contact_profile(problem, contact);
    ASSERT_EQ(profile.size(), contact.size());
    for (std::size_t k = 0; k < profile.size(); ++k) {
      const post::ContactSample& sample = profile[k];
      const bool on_die = sample.part == 1;
      const double expected =
          on_die ? geometry.container_length + geometry.entry_half_height - sample.y : sample.x;
      EXPECT_NEAR(sample.arc_length, expected, 1e-9) << "sample " << k << " order " << order;
      if (k > 0) {
        EXPECT_GT(sample.arc_length, profile[k - 1].arc_length) << "sample " << k;
      }
    }
    EXPECT_EQ(profile.front().part, 0);
    EXPECT_EQ(profile.back().part, 1);
  }
}

} // namespace
} // namespace formflow
