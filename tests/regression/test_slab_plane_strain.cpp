// SPDX-License-Identifier: MIT
// Issue 15, first Done-when: the 3D slab (the plane channel extruded in z, u_z = 0 and no
// shear on both z faces) is plane strain, so it reproduces the 2D run on the same (x, y)
// mesh — ram reaction, powers and the velocity field — for Q1 1×1 and Q2 2×2, μ = 0 and
// 0.1 with local friction, regularised and exact, sliding and sticking ram, Newton and
// secant, penalty and condensed mixed.
#include "formflow/app/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace formflow::testing {
namespace {

using physics::FrictionRegularization;
using physics::RamCondition;

/// δ of both runs. Why the runs agree to far better than δ: a z-independent field is
/// stationary for the discrete 3D functional (∫ σ_zz ∂_z v_z dz = σ_zz [v_z] = 0 with
/// v_z = 0 on both z faces, σ_xz = σ_yz = 0, and the Gauss rules integrate the
/// z-constant integrands exactly), and the linearised problem at a z-independent
/// iterate has a z-independent solution, so both runs take the same iterates up to
/// rounding and stop at the same iteration. A tight δ makes that iterate the discrete
/// solution itself: 1e-11 for the regularised law (Newton reaches 1e-13). Exact
/// friction also stops on the multipliers' change, whose rounding floor is
/// r·ε·|u|/|λ̂| with r = 100/d_N = 1e8 (measured here: 1.5e-10 to 2.5e-10 in 2D and
/// 3D after 60 iterations): δ = 1e-8 stays 40 times above it. The secant iteration
/// converges linearly (184 iterations to 1e-11 for Q2 here): 1e-9 is tight enough.
constexpr Real newton_tolerance = 1e-11;
constexpr Real secant_tolerance = 1e-9;
constexpr Real exact_tolerance = 1e-8;

/// The relative agreement the issue asks for ("ram reaction within 1e-8").
constexpr Real agreement = 1e-8;

/// Not 1, so that a force or power per unit depth and a solid one differ: the solid
/// powers are the plane ones times this. Two layers of about h = 0.5.
constexpr Real thickness = 0.75;

struct SlabCase {
  fem::ElementKind element;
  Real mu;
  FrictionRegularization regularization;
  RamCondition ram;
  solvers::NonlinearMethod method;
  bool mixed = false; ///< the mixed formulation (3.7) with a condensed P1disc pressure, d > 0
};

/// A small channel {L_c = 2, H_in = 2, H_out = 1, L_e = 2} at h = 0.5: 24 cells in the
/// plane, two layers over the thickness in 3D (dofs: see the table in docs/3d.md), so
/// the whole set runs in seconds.
io::Case make_case(const SlabCase& slab, int dimension) {
  io::Case case_;
  case_.solver.load_error = solvers::LoadErrorMethod::None; // not checked here; costs runs
  case_.mesh.geometry = mesh::ChannelGeometry{2.0, 2.0, 1.0, 2.0};
  case_.mesh.size = 0.5;
  case_.mesh.dimension = dimension;
  case_.mesh.solid.thickness = thickness;
  case_.element = slab.element;
  // The selective rule, the same per direction in the plane and in z.
  case_.volumetric_points = slab.element == fem::ElementKind::Q1 ? 1 : 2;
  case_.friction.mu = slab.mu;
  case_.friction.radius = 0.0; // local: a disk average is not the plane segment average
  case_.friction.regularization = slab.regularization;
  case_.process.ram = slab.ram;
  case_.solver.method = slab.method;
  if (slab.mixed) {
    case_.formulation.type = assembly::FormulationType::Mixed;
    case_.formulation.pressure = fem::PressureSpace::P1disc;
  }
  case_.solver.tolerance = slab.regularization == FrictionRegularization::None ? exact_tolerance
                           : slab.method == solvers::NonlinearMethod::Secant   ? secant_tolerance
                                                                               : newton_tolerance;
  return case_;
}

Real relative_difference(Real a, Real b) {
  return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

class SlabPlaneStrain : public ::testing::TestWithParam<SlabCase> {};

TEST_P(SlabPlaneStrain, ReproducesThePlaneRunOnTheSameMesh) {
  const app::Simulation plane = app::simulate(make_case(GetParam(), 2));
  const app::Simulation solid = app::simulate(make_case(GetParam(), 3));
  ASSERT_EQ(solid.dimension(), 3);
  const post::Results& p = plane.results;
  const post::Results& s = solid.results;
  ASSERT_TRUE(p.converged()) << solvers::stop_reason_name(p.stop_reason);
  ASSERT_TRUE(s.converged()) << solvers::stop_reason_name(s.stop_reason);

  // Pressures are forces over the driven end's measure (a height in 2D, an area in
  // 3D): the same number when the solid force is the plane one times the thickness.
  EXPECT_LT(relative_difference(s.pressure.ram_reaction, p.pressure.ram_reaction), agreement)
      << s.pressure.ram_reaction << " vs " << p.pressure.ram_reaction;
  EXPECT_LT(relative_difference(s.pressure.total_power, p.pressure.total_power), agreement);
  EXPECT_LT(relative_difference(s.pressure.power_balance, p.pressure.power_balance), agreement);
  // Powers are totals over the model: the solid ones are the plane ones times the thickness.
  EXPECT_LT(
      relative_difference(s.power.plastic_dissipation, p.power.plastic_dissipation * thickness),
      agreement);
  if (GetParam().mu > 0) {
    EXPECT_LT(relative_difference(s.power.friction, p.power.friction * thickness), agreement);
  }

  // Node k·n + i of the slab is plane node i at level k (mesh/extruded_mesh.hpp): its
  // (u_x, u_y) is the plane one and u_z vanishes, to the same relative agreement of
  // the process speed.
  const Index n_plane = p.n_nodes;
  ASSERT_EQ(s.n_nodes % n_plane, 0);
  const Real speed = 1.0;
  Real largest_gap = 0.0;
  for (Index node = 0; node < s.n_nodes; ++node) {
    const Index in_plane = node % n_plane;
    for (int axis = 0; axis < 2; ++axis)
      largest_gap = std::max(largest_gap, std::abs(s.fields.velocity[3 * node + axis] -
                                                   p.fields.velocity[2 * in_plane + axis]));
    largest_gap = std::max(largest_gap, std::abs(s.fields.velocity[3 * node + 2]));
  }
  EXPECT_LT(largest_gap, agreement * speed);
  // The same iterates: the same count, or one more where a change sits at δ.
  EXPECT_LE(std::abs(s.iterations - p.iterations), 1) << s.iterations << " vs " << p.iterations;
}

std::vector<SlabCase> slab_cases() {
  std::vector<SlabCase> cases;
  for (fem::ElementKind element : {fem::ElementKind::Q1, fem::ElementKind::Q2})
    for (Real mu : {0.0, 0.1})
      for (FrictionRegularization regularization :
           {FrictionRegularization::Regularized, FrictionRegularization::None})
        for (RamCondition ram : {RamCondition::Sliding, RamCondition::Sticking})
          cases.push_back({element, mu, regularization, ram, solvers::NonlinearMethod::Newton});
  // The paper's method on the frictional case (Q1: Q2's 142 secant iterations at δ =
  // 1e-9 take 3 s here, docs/3d.md has its numbers).
  cases.push_back({fem::ElementKind::Q1, 0.1, FrictionRegularization::Regularized,
                   RamCondition::Sliding, solvers::NonlinearMethod::Secant});
  // The condensed mixed formulation (P1disc in 3D: 4 pressure dofs per hexahedron).
  cases.push_back({fem::ElementKind::Q2, 0.1, FrictionRegularization::Regularized,
                   RamCondition::Sliding, solvers::NonlinearMethod::Newton, true});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SlabPlaneStrain, ::testing::ValuesIn(slab_cases()), [](const auto& info) {
      const SlabCase& c = info.param;
      return std::string(c.element == fem::ElementKind::Q1 ? "Q1" : "Q2") +
             (c.mu > 0 ? "Mu01" : "Mu0") +
             (c.regularization == FrictionRegularization::None ? "Exact" : "Regularized") +
             (c.ram == RamCondition::Sliding ? "Sliding" : "Sticking") +
             (c.method == solvers::NonlinearMethod::Newton ? "Newton" : "Secant") +
             (c.mixed ? "MixedP1disc" : "");
    });

} // namespace
} // namespace formflow::testing
