// SPDX-License-Identifier: MIT
// Every flow law on homogeneous flows with a closed-form answer: plane-strain
// compression u = ε̇(x, −y) and simple shear u = (γ̇ y, 0), prescribed on the whole
// boundary of the channel mesh. The discrete solution must be the homogeneous
// field, σ̄ = σ_p(ε̄̇) must hold at every quadrature point, and the power of the
// boundary reactions must equal σ_p(ε̄̇) ε̄̇ |Ω| (the dissipation of the law).
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/physics/flow_law.hpp"
#include "formflow/physics/kinematics.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "support/approx.hpp"
#include "support/flow_laws.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace formflow::testing {
namespace {

using physics::FlowLaw;

struct LawCase {
  std::string name;
  FlowLaw law;
};

std::vector<LawCase> laws() {
  std::vector<LawCase> list;
  list.push_back({"piecewise_power", FlowLaw{}});
  list.push_back({"norton_hoff", norton_hoff(0.8, 0.2)});
  list.push_back({"linear_viscous", norton_hoff(0.8, 1.0)});
  list.push_back({"hensel_spittel", hensel_spittel()});
  list.push_back({"perfectly_plastic", perfectly_plastic(2.5)});
  return list;
}

/// Solves the penalty problem with u = G x on the whole boundary by the secant
/// iteration, then checks the solution, σ̄ and the reaction power against the closed form.
void check_homogeneous_flow(const FlowLaw& law, int order, const Tensor2<2>& g,
                            physics::ViscousStrain strain) {
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 0.5, order);
  const Index n_dofs = mesh.n_nodes() * 2;
  std::vector<bool> prescribed(n_dofs, false);
  VectorX exact(n_dofs);
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    exact.segment<2>(2 * node) = g * mesh.nodes.col(node);
  for (const mesh::BoundaryFacet& facet : mesh.facets)
    for (int a : mesh::face_local_nodes<2>(mesh.nodes_per_side(), facet.local_face))
      for (int i = 0; i < 2; ++i) prescribed[2 * mesh.cells(a, facet.cell) + i] = true;
  assembly::BlockDofs blocks;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    blocks.add(fem::dofs_of_nodes<2>(mesh.cells.col(cell)));
  const assembly::ScatterPlan plan(n_dofs, prescribed, blocks);
  assembly::LinearSystem system = plan.make_system();
  const fem::QuadratureRule<2> rule = fem::gauss_rule<2>(order + 1);
  fem::CellValues<2> values(order, rule);
  const physics::Penalty penalty;

  // Start from a non-homogeneous interior (u = 0), iterate K(u) u = F.
  VectorX u = VectorX::Zero(n_dofs);
  for (Index dof = 0; dof < n_dofs; ++dof)
    if (prescribed[dof]) u[dof] = exact[dof];
  auto solver = solvers::make_cholmod_solver();
  // The secant iterates approach the homogeneous field linearly (contraction
  // ≈ 1 − α for the paper's law), so iterate to round-off, not a fixed count.
  for (int iteration = 0; iteration < 20000; ++iteration) {
    assembly::ScatterPlan::clear(system);
    for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
      fem::CellValues<2>::Gradients nodes(2, mesh.nodes_per_cell()),
          velocity(2, mesh.nodes_per_cell());
      for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
        nodes.col(a) = mesh.nodes.col(mesh.cells(a, cell));
        velocity.col(a) = u.segment<2>(2 * mesh.cells(a, cell));
      }
      values.reinit(nodes);
      std::vector<Real> viscosity;
      for (int q = 0; q < values.n_points(); ++q)
        viscosity.push_back(
            law.secant_viscosity(physics::equivalent_strain_rate(physics::strain_rate<2>(
                physics::velocity_gradient<2>(velocity, values.gradients(q))))));
      MatrixX local = MatrixX::Zero(2 * mesh.nodes_per_cell(), 2 * mesh.nodes_per_cell());
      assembly::add_viscous_term<2>(values, viscosity, strain, local);
      assembly::add_volumetric_penalty<2>(values, penalty.d, local);
      plan.scatter(cell, local, exact, system);
    }
    if (iteration == 0) {
      ASSERT_TRUE(solver->analyze(system.matrix));
    }
    ASSERT_TRUE(solver->factorize(system.matrix));
    VectorX free_u;
    ASSERT_TRUE(solver->solve(system.rhs, free_u));
    const VectorX next = plan.expand(free_u, exact);
    const Real change = (next - u).norm() / next.norm();
    u = next;
    if (change < 1e-14) break;
  }
  // (1) The homogeneous field, to solver round-off (condition number ~1/d · ν ratio).
  EXPECT_LE((u - exact).cwiseAbs().maxCoeff(), 1e-9 * exact.cwiseAbs().maxCoeff());

  // (2) σ̄ = σ_p(ε̄̇) pointwise, with ε̄̇ of G: s = ⅔ ν ė, σ̄ = √(3/2 s:s).
  const Tensor3 rate = physics::strain_rate<2>(g);
  const Real eps = physics::equivalent_strain_rate(rate);
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    fem::CellValues<2>::Gradients nodes(2, mesh.nodes_per_cell()),
        velocity(2, mesh.nodes_per_cell());
    for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
      nodes.col(a) = mesh.nodes.col(mesh.cells(a, cell));
      velocity.col(a) = u.segment<2>(2 * mesh.cells(a, cell));
    }
    values.reinit(nodes);
    for (int q = 0; q < values.n_points(); ++q) {
      const Tensor3 local_rate =
          physics::strain_rate<2>(physics::velocity_gradient<2>(velocity, values.gradients(q)));
      const Real local_eps = physics::equivalent_strain_rate(local_rate);
      const Tensor3 s = 2.0 / 3.0 * law.secant_viscosity(local_eps) * physics::deviator(local_rate);
      const Real sigma_bar = std::sqrt(1.5 * s.cwiseProduct(s).sum());
      EXPECT_TRUE(approx(sigma_bar, law.yield_stress(eps), 1e-8)) << "cell " << cell << " q " << q;
    }
  }
  // (3) Power of the reactions = ∫ σ:ε̇ = σ_p(ε̄̇) ε̄̇ |Ω| (ε̇_V = 0, so no penalty power).
  const VectorX reactions = system.reaction_rows * u;
  Real power = 0.0;
  for (Index dof = 0; dof < n_dofs; ++dof)
    if (prescribed[dof]) power += reactions[plan.prescribed_index(dof)] * u[dof];
  const Real area = 2.0 * 2.0 + 2.0 * 1.0;
  EXPECT_TRUE(approx(power, law.yield_stress(eps) * eps * area, 1e-8));
}

class HomogeneousFlow : public ::testing::TestWithParam<int> {};

TEST_P(HomogeneousFlow, PlaneStrainCompressionGivesTheYieldStress) {
  for (const LawCase& law : laws())
    // Two rates: inside [rate1, rate2] and on the linear branch below rate1.
    for (Real speed : {0.7, 2e-4}) {
      SCOPED_TRACE(law.name + " rate " + std::to_string(speed));
      Tensor2<2> g;
      g << speed, 0.0, 0.0, -speed;
      check_homogeneous_flow(law.law, GetParam(), g, physics::ViscousStrain::Full);
      check_homogeneous_flow(law.law, GetParam(), g, physics::ViscousStrain::Deviatoric);
    }
}

TEST_P(HomogeneousFlow, SimpleShearGivesTheYieldStress) {
  for (const LawCase& law : laws()) {
    SCOPED_TRACE(law.name);
    Tensor2<2> g;
    g << 0.0, 1.3, 0.0, 0.0; // u = (γ̇ y, 0): ε̄̇ = γ̇/√3
    check_homogeneous_flow(law.law, GetParam(), g, physics::ViscousStrain::Full);
  }
}

INSTANTIATE_TEST_SUITE_P(Q1AndQ2, HomogeneousFlow, ::testing::Values(1, 2));

} // namespace
} // namespace formflow::testing
