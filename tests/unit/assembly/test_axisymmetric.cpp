// SPDX-License-Identifier: MIT
// Axisymmetric forms (y = r): hoop rate, r-weighted viscous and volumetric
// energies against hand-integrated fields, and the driven "height" ∫ r dr.
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/physics/kinematics.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace formflow::testing {
namespace {

using namespace assembly;
using Nodes = fem::CellValues<2>::Gradients;
using Field = std::function<Point<2>(const Point<2>&)>;

/// An off-axis cell with curved (Q2) geometry, r ∈ (0.5, 1.7).
Nodes off_axis_cell(int order) {
  const int n = order + 1;
  Nodes nodes(2, n * n);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const double s = static_cast<double>(a) / order, t = static_cast<double>(b) / order;
      nodes.col(b * n + a) = Point<2>(0.2 + 1.5 * s + 0.1 * t, 0.5 + 1.1 * t + 0.1 * s * s);
    }
  return nodes;
}

VectorX interpolate(const Nodes& nodes, const Field& field) {
  VectorX u(nodes.cols() * 2);
  for (Index a = 0; a < nodes.cols(); ++a) u.segment<2>(2 * a) = field(nodes.col(a));
  return u;
}

/// ∫ integrand(ε̇) r dA by the same quadrature, from the field's exact strain rate.
double integrate(const fem::CellValues<2>& values,
                 const std::function<double(const Point<2>&)>& f) {
  double sum = 0.0;
  for (int q = 0; q < values.n_points(); ++q) sum += f(values.point(q)) * values.JxW(q);
  return sum;
}

TEST(Axisymmetric, VolumetricPenaltyEnergyOfARadialField) {
  for (int order : {1, 2}) {
    fem::CellValues<2> values(order, fem::gauss_rule<2>(order + 1));
    values.reinit(off_axis_cell(order));
    values.weight_by_radius();
    MatrixX k = MatrixX::Zero(values.n_nodes() * 2, values.n_nodes() * 2);
    const double d = 1e-3;
    add_volumetric_penalty_axisymmetric(values, d, k);
    // u = (0, r): ε̇_V = ∂u_r/∂r + u_r/r = 2, interpolated exactly by Q1 and Q2.
    const VectorX u =
        interpolate(off_axis_cell(order), [](const Point<2>& p) { return Point<2>(0.0, p.y()); });
    const double exact = integrate(values, [&](const Point<2>&) { return 4.0 / d; });
    EXPECT_TRUE(approx(u.dot(k * u), exact, 1e-12));
    // u = (2x, −r): isochoric (2 − 1 − 1 = 0), no penalty energy.
    const VectorX w = interpolate(off_axis_cell(order),
                                  [](const Point<2>& p) { return Point<2>(2 * p.x(), -p.y()); });
    EXPECT_TRUE(approx(w.dot(k * w), 0.0, 0, 1e-9 * exact));
  }
}

TEST(Axisymmetric, ViscousEnergyIncludesTheHoopRate) {
  for (int order : {1, 2})
    for (auto strain : {physics::ViscousStrain::Full, physics::ViscousStrain::Deviatoric}) {
      fem::CellValues<2> values(order, fem::gauss_rule<2>(order + 1));
      values.reinit(off_axis_cell(order));
      values.weight_by_radius();
      const std::vector<Real> viscosity(values.n_points(), 1.7);
      MatrixX k = MatrixX::Zero(values.n_nodes() * 2, values.n_nodes() * 2);
      add_viscous_term<2>(values, viscosity, strain, k);
      add_hoop_viscous_term(values, viscosity, strain, k);
      // u = (x, r): ε̇ = diag(1, 1, 1) with the hoop rate u_r/r = 1: ε̇:ε̇ = 3, ė = 0.
      const VectorX u = interpolate(off_axis_cell(order), [](const Point<2>& p) { return p; });
      const double density = strain == physics::ViscousStrain::Full ? 3.0 : 0.0;
      const double exact =
          integrate(values, [&](const Point<2>&) { return 2.0 / 3.0 * 1.7 * density; });
      EXPECT_TRUE(approx(u.dot(k * u), exact, 1e-12, 1e-12));
      // u = (0, r): ε̇ = diag(0, 1, 1): ε̇:ε̇ = 2, ė:ė = 2 − 4/3 = 2/3.
      const VectorX v =
          interpolate(off_axis_cell(order), [](const Point<2>& p) { return Point<2>(0.0, p.y()); });
      const double v_density = strain == physics::ViscousStrain::Full ? 2.0 : 2.0 / 3.0;
      const double v_exact =
          integrate(values, [&](const Point<2>&) { return 2.0 / 3.0 * 1.7 * v_density; });
      EXPECT_TRUE(approx(v.dot(k * v), v_exact, 1e-12));
    }
}

TEST(Axisymmetric, KernelsMatchTheStrainRateOfTheProblem) {
  // A wedge-die channel, Q2: the assembled a-form of a nonlinear field equals
  // ⅔ ν ∫ ε̇:ε̇ r dA evaluated with FormingProblem::strain_rate_at.
  mesh::ChannelGeometry geometry{1.0, 1.0, 0.8, 1.0};
  geometry.die = mesh::DieShape::Wedge;
  geometry.die_angle = 20.0;
  const mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.25, 2);
  assembly::ProblemSettings settings;
  settings.symmetry = physics::Symmetry::Axisymmetric;
  const assembly::FormingProblem<2> problem(m, settings);
  fem::CellValues<2> values(2, problem.full_rule());
  Nodes coordinates, velocities;
  const Field field = [](const Point<2>& p) {
    return Point<2>(p.x() * p.y(), 0.3 * p.y() * p.x() * p.x());
  };
  VectorX u(problem.n_dofs());
  for (Index n = 0; n < m.n_nodes(); ++n) u.segment<2>(2 * n) = field(m.nodes.col(n));
  for (Index cell : {Index{0}, m.n_cells() - 1}) {
    problem.gather(cell, &u, coordinates, velocities);
    problem.reinit(values, coordinates);
    const std::vector<Real> viscosity(values.n_points(), 1.0);
    MatrixX k = MatrixX::Zero(18, 18);
    add_viscous_term<2>(values, viscosity, physics::ViscousStrain::Full, k);
    add_hoop_viscous_term(values, viscosity, physics::ViscousStrain::Full, k);
    const Eigen::Map<const VectorX> local(velocities.data(), 18);
    double direct = 0.0;
    for (int q = 0; q < values.n_points(); ++q) {
      const Tensor3 rate = problem.strain_rate_at(values, velocities, q);
      EXPECT_TRUE(
          approx(rate(2, 2), (velocities * values.shape(q))[1] / values.point(q)[1], 1e-14, 1e-14));
      direct += 2.0 / 3.0 * rate.cwiseProduct(rate).sum() * values.JxW(q);
    }
    EXPECT_TRUE(approx(local.dot(k * local), direct, 1e-12));
  }
}

TEST(Axisymmetric, DrivenHeightIsTheIntegralOfR) {
  mesh::ChannelGeometry geometry{1.0, 1.0, 0.5, 1.0};
  geometry.die = mesh::DieShape::Wedge;
  geometry.die_angle = 30.0;
  const mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.25, 1);
  assembly::ProblemSettings settings;
  settings.symmetry = physics::Symmetry::Axisymmetric;
  // Extrusion: the ram r ∈ [0, 1], ∫ r dr = 1/2 (force / this = force / πR² per 2π).
  EXPECT_TRUE(approx(assembly::FormingProblem<2>(m, settings).driven_height(), 0.5, 1e-14));
  settings.process.type = physics::ProcessType::Drawing;
  EXPECT_TRUE(approx(assembly::FormingProblem<2>(m, settings).driven_height(), 0.125, 1e-14));
  settings.symmetry = physics::Symmetry::Plane;
  EXPECT_TRUE(approx(assembly::FormingProblem<2>(m, settings).driven_height(), 0.5, 1e-14));
}

} // namespace
} // namespace formflow::testing
