// SPDX-License-Identifier: MIT
// Hot forming with Tresca and hybrid friction: the shear yield k = σ_p/√3 at each Γ3
// point is the law's at that point's temperature (FormingProblem::set_contact_temperatures).
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace formflow::testing {
namespace {

using namespace assembly;

TEST(ContactTemperature, TrescaShearYieldIsTheLawAtThePointsTemperature) {
  mesh::ChannelGeometry geometry{1.0, 1.0, 0.6, 1.0};
  geometry.die = mesh::DieShape::Arc; // the wedge-like mesh of test_geometry_cache.cpp
  geometry.die_radius = 1.0;
  geometry.land_length = 0.25;
  const mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.125, 1);
  ProblemSettings settings;
  // Hensel–Spittel with m8 = 0: σ_p = A e^(m1 T) ε̄̇^m3, so k(T₁)/k(T₀) = e^(m1 (T₁ − T₀))
  // at every point whatever its strain rate.
  physics::HenselSpittel law;
  law.A = 400, law.m1 = -2.5e-3, law.m3 = 0.12, law.temperature = 450;
  settings.law.model = law;
  settings.friction.law = physics::FrictionLaw::Tresca;
  settings.friction.m = 0.5;
  FormingProblem<2> problem(m, settings);
  // A velocity with slip and a strain rate everywhere.
  VectorX u(problem.n_dofs());
  for (Index node = 0; node < m.n_nodes(); ++node) {
    u[2 * node] = 1.0 + 0.3 * m.nodes(1, node);
    u[2 * node + 1] = -0.2 * m.nodes(0, node);
  }
  const auto isothermal = problem.contact_state(u);
  ASSERT_FALSE(isothermal.empty());
  // Its own temperature: the same thresholds as the isothermal law, bit for bit.
  problem.set_contact_temperatures(std::vector<Real>(isothermal.size(), 450.0));
  const auto same = problem.contact_state(u);
  std::vector<Real> hotter(isothermal.size());
  for (std::size_t k = 0; k < hotter.size(); ++k) hotter[k] = 450.0 + 10.0 * (k % 5);
  problem.set_contact_temperatures(hotter);
  const auto hot = problem.contact_state(u);
  int acting = 0;
  for (std::size_t k = 0; k < isothermal.size(); ++k) {
    EXPECT_EQ(same[k].friction_threshold, isothermal[k].friction_threshold);
    if (isothermal[k].friction_threshold == 0) continue; // no friction on this part of Γ3
    ++acting;
    // One exp and a few products apart: 1e-13 relative.
    EXPECT_NEAR(hot[k].friction_threshold / isothermal[k].friction_threshold,
                std::exp(-2.5e-3 * (hotter[k] - 450.0)), 1e-13)
        << "point " << k;
  }
  EXPECT_GT(acting, 0);
}

} // namespace
} // namespace formflow::testing
