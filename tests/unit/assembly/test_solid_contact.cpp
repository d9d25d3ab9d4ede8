// SPDX-License-Identifier: MIT
// Contact and friction on the surfaces of a solid (3D) mesh, on the slab: the nodal
// normals are the plane channel's (also where the die face meets the z faces), and
// Newton's Jacobian — the 2-vector slip in the tangent plane, the nonlocal σ̄_N over
// a ball of radius h and its dτ_f coupling — matches finite differences of the residual
// at a velocity with out-of-plane slip.
#include "formflow/assembly/contact_normals.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/extruded_mesh.hpp"
#include "support/newton_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace formflow::testing {
namespace {

/// Γ3 facets (indices into mesh.facets) in mesh order.
template <int dim> std::vector<Index> contact_facets(const mesh::Mesh<dim>& mesh) {
  std::vector<Index> facets;
  for (std::size_t f = 0; f < mesh.facets.size(); ++f)
    if (mesh::is_contact(mesh.facets[f].label)) facets.push_back(static_cast<Index>(f));
  return facets;
}

TEST(SolidContact, NodalNormalsOfTheSlabAreThePlaneChannelsAtEveryLevel) {
  // The 30° wedge turns less than contact.corner_angle = 60° from the container, so
  // the junction's normal is averaged; the square die's 90° keeps the face normals.
  for (const mesh::DieShape die : {mesh::DieShape::Wedge, mesh::DieShape::Square})
    for (int order : {1, 2}) {
      mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0};
      geometry.die = die;
      geometry.die_angle = 30.0;
      const mesh::Mesh<2> plane = mesh::make_die_channel_mesh(geometry, 0.5, order);
      const int layers = 2;
      const mesh::Mesh<3> slab =
          mesh::extrude_mesh(plane, 1.0, layers, mesh::BoundaryLabel::Symmetry);
      const std::vector<Index> plane_facets = contact_facets(plane);
      const std::vector<Index> slab_facets = contact_facets(slab);
      ASSERT_EQ(slab_facets.size(), layers * plane_facets.size());
      const auto plane_normals = assembly::nodal_contact_normals<2>(plane, plane_facets, 60.0);
      const auto slab_normals = assembly::nodal_contact_normals<3>(slab, slab_facets, 60.0);
      const int n_side = order + 1;
      ASSERT_EQ(slab_normals.size(), slab_facets.size() * n_side * n_side);
      // Layer-major facets, and face point q = level·n_side + (plane point q mod n_side):
      // the face's in-plane direction is its fastest (mesh/extruded_mesh.hpp).
      Real largest_gap = 0.0;
      for (std::size_t k = 0; k < slab_normals.size(); ++k) {
        const std::size_t position = k / (n_side * n_side) % plane_facets.size();
        const std::size_t q = k % (n_side * n_side) % n_side;
        const Point<2>& expected = plane_normals[position * n_side + q];
        const Point<3> normal = slab_normals[k];
        largest_gap =
            std::max({largest_gap, (normal.head<2>() - expected).norm(), std::abs(normal.z())});
      }
      // Normals from mapped face Jacobians of coordinates ≤ 4: a few ulps.
      EXPECT_LT(largest_gap, 1e-13) << order;
    }
}

/// The plane small extrusion (channel 2 × 2 → 1, Q2, h = 1) extruded over z ∈ [0, 1]
/// in one layer: 111 nodes, u_z = 0 on both z faces, free on the middle level.
mesh::Mesh<3> small_slab() {
  return mesh::extrude_mesh(small_channel_mesh(), 1.0, 1, mesh::BoundaryLabel::Symmetry);
}

class SolidNewton : public ::testing::TestWithParam<assembly::ContactNormals> {};

TEST_P(SolidNewton, JacobianWithOutOfPlaneSlipAndANonlocalPressureMatchesFiniteDifferences) {
  assembly::ProblemSettings settings;
  settings.law = sensitive_law();
  settings.viscous_strain = physics::ViscousStrain::Full;
  settings.contact.normals = GetParam();
  settings.friction.mu = 0.2;
  settings.friction.d_t = 0.05;
  // A ball of radius 0.8 around each Γ3 point reaches the neighbouring points in x, y
  // and z (Q2 Gauss points ≈ 0.39 apart, nodes 0.5): the coupling links them all.
  settings.friction.radius = 0.8;
  settings.penalty.d = 0.1;
  settings.penalty.d_n = 0.1;
  const SmallExtrusionIn<3> extrusion(settings, small_slab());
  // The random velocity moves every free dof, u_z included: the slip on the container
  // (normal y) and die (normal x) faces has a z component.
  Real largest_z_slip = 0.0;
  for (const auto& point : extrusion.problem->contact_state(extrusion.u))
    largest_z_slip = std::max(largest_z_slip, std::abs(point.tangential_velocity.z()));
  EXPECT_GT(largest_z_slip, 0.05); // of a 0.3 × random velocity
  const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
  ASSERT_GT(*std::max_element(thresholds.begin(), thresholds.end()), 0.0);
  MatrixX symmetric;
  const MatrixX exact = extrusion.jacobian(thresholds, &symmetric);
  const MatrixX fd = finite_difference_jacobian(
      [&](const VectorX& free_u) { return extrusion.free_residual(free_u, nullptr); },
      extrusion.free_part(extrusion.u), 1e-6);
  EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
  // The coupling is not empty: without it the Jacobian misses dτ_f and the full form's term.
  EXPECT_GT((symmetric - fd).norm(), 1e3 * fd_tolerance * exact.norm());
}

INSTANTIATE_TEST_SUITE_P(Normals, SolidNewton,
                         ::testing::Values(assembly::ContactNormals::Faces,
                                           assembly::ContactNormals::Nodes),
                         [](const auto& info) {
                           return std::string(info.param == assembly::ContactNormals::Faces
                                                  ? "FaceNormals"
                                                  : "NodalNormals");
                         });

} // namespace
} // namespace formflow::testing
