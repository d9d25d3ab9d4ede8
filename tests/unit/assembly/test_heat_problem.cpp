// SPDX-License-Identifier: MIT
// The SUPG heat problem against the exact 1D convection–diffusion solution with a step
// source, across Péclet 1…1e4 (issue 18): no oscillation, bounds, observed L² rates.
#include "formflow/assembly/discretisation.hpp"
#include "formflow/assembly/heat_problem.hpp"
#include "formflow/fem/quadrature.hpp"
#include "formflow/mesh/box_mesh.hpp"

#include <Eigen/SparseLU>
#include <gtest/gtest.h>

#include <cmath>

namespace formflow::assembly {
namespace {

// ρc U T′ − κ T″ = q H(L/2 − x), T(0) = 0, T′(L) = 0 (adiabatic outflow), L = 1,
// ρc = U = 1, q = 1, κ = 1/Pe. With λ = Pe and a = q/(ρc U):
// x < ½: T = a x + (a/λ) e^(−λ/2) (1 − e^(λx)); x ≥ ½: T = a/2 + (a/λ)(e^(−λ/2) − 1).
// The layer of width 1/λ sits upstream of the kink at x = ½: what Galerkin FEM turns
// into node-to-node oscillations once the cell Péclet number exceeds 1.
Real exact(Real x, Real peclet) {
  const Real a = 1.0, lambda = peclet;
  if (x < 0.5) return a * x + a / lambda * (std::exp(-lambda * 0.5) - std::exp(lambda * (x - 0.5)));
  return a * 0.5 + a / lambda * (std::exp(-lambda * 0.5) - 1.0);
}

struct Solved {
  VectorX T;
  Real l2_error = 0.0;
  Real max_of_exact = 0.0;
};

Solved solve_1d(int n, Real peclet, int order) {
  const mesh::Mesh<2> mesh = mesh::make_box_mesh({0.0, 0.0}, {1.0, 0.1}, n, 1, order);
  DirichletConstraints none;
  none.prescribed.assign(mesh.n_nodes() * 2, false);
  none.values = VectorX::Zero(mesh.n_nodes() * 2);
  const Discretisation<2> discretisation(mesh, DiscretisationSettings{}, none);
  physics::Thermal thermal;
  thermal.billet_temperature = 0.0;
  thermal.conductivity = 1.0 / peclet;
  const HeatProblem<2> heat(discretisation, thermal);
  VectorX u = VectorX::Zero(mesh.n_nodes() * 2);
  for (Index node = 0; node < mesh.n_nodes(); ++node) u[2 * node] = 1.0;
  HeatSources sources;
  const fem::QuadratureRule<2>& rule = discretisation.full_rule();
  fem::CellValues<2> values(mesh.order, rule);
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation.load_cell(cell, values, nullptr);
    for (int q = 0; q < values.n_points(); ++q)
      sources.deformation.push_back(values.point(q)[0] < 0.5 ? 1.0 : 0.0);
  }
  const HeatSystem system = heat.assemble(u, sources);
  Eigen::SparseLU<SparseMatrix> lu(system.matrix);
  EXPECT_EQ(lu.info(), Eigen::Success);
  Solved solved;
  solved.T = heat.expand(lu.solve(system.rhs));
  // L² error with a 4-point Gauss rule per cell (exact to degree 7, beyond the element's;
  // the step source is aligned with a cell edge for even n).
  fem::CellValues<2> fine(mesh.order, fem::gauss_rule<2>(4));
  typename fem::CellValues<2>::Gradients coordinates, unused;
  Real squared = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation.gather(cell, nullptr, coordinates, unused);
    fine.reinit(coordinates);
    for (int q = 0; q < fine.n_points(); ++q) {
      Real value = 0.0;
      for (int a = 0; a < fine.n_nodes(); ++a)
        value += fine.shape(q)[a] * solved.T[mesh.cells(a, cell)];
      squared += std::pow(value - exact(fine.point(q)[0], peclet), 2) * fine.JxW(q);
    }
  }
  solved.l2_error = std::sqrt(squared / 0.1);
  solved.max_of_exact = exact(1.0, peclet);
  return solved;
}

TEST(HeatProblem, NoOscillationAcrossPecletNumbers) {
  // Bounds of the exact solution: 0 ≤ T ≤ T(1) and T non-decreasing in x. Round-off of an
  // LU solve of this well-conditioned banded system is far below 1e-10 of the scale 0.5.
  const Real round_off = 1e-10;
  for (const Real peclet : {1.0, 10.0, 1e2, 1e3, 1e4})
    for (const int n : {8, 16, 32}) {
      const Solved solved = solve_1d(n, peclet, 1);
      const mesh::Mesh<2> mesh = mesh::make_box_mesh({0.0, 0.0}, {1.0, 0.1}, n, 1, 1);
      for (Index node = 0; node < mesh.n_nodes(); ++node) {
        EXPECT_GE(solved.T[node], -round_off) << "Pe " << peclet << " n " << n;
        EXPECT_LE(solved.T[node], solved.max_of_exact + round_off) << "Pe " << peclet;
      }
      for (int i = 0; i < n; ++i) // bottom row: nodes 0…n along x
        EXPECT_GE(solved.T[i + 1], solved.T[i] - round_off) << "Pe " << peclet << " x " << i;
    }
}

TEST(HeatProblem, NodallyExactWithoutLayerResolution) {
  // SUPG's τ with coth is the 1D nodally exact choice for Q1 and a piecewise-constant
  // source aligned with the nodes: the nodal error is round-off at every Péclet number.
  for (const Real peclet : {1.0, 1e2, 1e4}) {
    const int n = 16;
    const Solved solved = solve_1d(n, peclet, 1);
    for (int i = 0; i <= n; ++i)
      EXPECT_NEAR(solved.T[i], exact(static_cast<Real>(i) / n, peclet), 1e-9)
          << "Pe " << peclet << " node " << i;
  }
}

TEST(HeatProblem, ObservedRatesQ1) {
  // Where the mesh resolves the layer (cell Péclet ≤ 1), Q1's L² error is O(h²); the
  // observed rate over 16 → 32 → 64 must be within 0.15 of 2.
  for (const Real peclet : {1.0, 10.0}) {
    const Real e16 = solve_1d(16, peclet, 1).l2_error, e32 = solve_1d(32, peclet, 1).l2_error,
               e64 = solve_1d(64, peclet, 1).l2_error;
    EXPECT_NEAR(std::log2(e16 / e32), 2.0, 0.15) << "Pe " << peclet;
    EXPECT_NEAR(std::log2(e32 / e64), 2.0, 0.15) << "Pe " << peclet;
  }
}

// A manufactured 2D solution T* = sin(πx/2) cos(πy) on [0,1]², u = (1, 0), ρc = 1,
// κ = 1/Pe. T* = 0 on the rear
// x = 0 and ∂T*/∂n = 0 on the other three sides (the problem's natural conditions), so
// q = ρc ∂T*/∂x − κ ΔT* is the only datum. Returns the L² error on an n × n mesh.
Real manufactured_error(int n, int order, Real peclet) {
  const mesh::Mesh<2> mesh = mesh::make_box_mesh({0.0, 0.0}, {1.0, 1.0}, n, n, order);
  DirichletConstraints none;
  none.prescribed.assign(mesh.n_nodes() * 2, false);
  none.values = VectorX::Zero(mesh.n_nodes() * 2);
  const Discretisation<2> discretisation(mesh, DiscretisationSettings{}, none);
  physics::Thermal thermal;
  thermal.billet_temperature = 0.0;
  thermal.conductivity = 1.0 / peclet;
  const HeatProblem<2> heat(discretisation, thermal);
  VectorX u = VectorX::Zero(mesh.n_nodes() * 2);
  for (Index node = 0; node < mesh.n_nodes(); ++node) u[2 * node] = 1.0;
  const Real pi = std::acos(-1.0);
  const auto exact_t = [pi](const Point<2>& x) {
    return std::sin(pi * x[0] / 2) * std::cos(pi * x[1]);
  };
  HeatSources sources;
  fem::CellValues<2> values(mesh.order, discretisation.full_rule());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation.load_cell(cell, values, nullptr);
    for (int q = 0; q < values.n_points(); ++q) {
      const Point<2>& x = values.point(q);
      const Real dtdx = pi / 2 * std::cos(pi * x[0] / 2) * std::cos(pi * x[1]);
      const Real laplacian = -(pi * pi / 4 + pi * pi) * exact_t(x);
      sources.deformation.push_back(dtdx - thermal.conductivity * laplacian);
    }
  }
  const HeatSystem system = heat.assemble(u, sources);
  Eigen::SparseLU<SparseMatrix> lu(system.matrix);
  const VectorX T = heat.expand(lu.solve(system.rhs));
  fem::CellValues<2> fine(mesh.order, fem::gauss_rule<2>(5));
  typename fem::CellValues<2>::Gradients coordinates, unused;
  Real squared = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation.gather(cell, nullptr, coordinates, unused);
    fine.reinit(coordinates);
    for (int q = 0; q < fine.n_points(); ++q) {
      Real value = 0.0;
      for (int a = 0; a < fine.n_nodes(); ++a) value += fine.shape(q)[a] * T[mesh.cells(a, cell)];
      squared += std::pow(value - exact_t(fine.point(q)), 2) * fine.JxW(q);
    }
  }
  return std::sqrt(squared);
}

TEST(HeatProblem, ManufacturedRatesQ1AndQ2) {
  // Conduction-dominated (Pe = 1). The SUPG residual is the whole residual, −κΔT_h with
  // the shape functions' second derivatives included (HeatProblem::minus_laplacian), so
  // the method is consistent and Q_l converges at l + 1 in L². Without −κΔT_h Q2 was
  // inconsistent by τκ = h²/12 and stalled towards 2 (2.87, 2.66 on 4 → 8 → 16).
  const Real q1_8 = manufactured_error(8, 1, 1.0), q1_16 = manufactured_error(16, 1, 1.0);
  EXPECT_NEAR(std::log2(q1_8 / q1_16), 2.0, 0.15);
  const Real q2_8 = manufactured_error(8, 2, 1.0), q2_16 = manufactured_error(16, 2, 1.0);
  EXPECT_NEAR(std::log2(q2_8 / q2_16), 3.0, 0.15);
  EXPECT_LT(q2_16, q1_16);
}

} // namespace
} // namespace formflow::assembly
