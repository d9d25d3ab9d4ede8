// SPDX-License-Identifier: MIT
// The mixed formulation's divergence in axisymmetry (y = r): B u = ∫ ψ (∂_r u_r + u_r/r
// + ∂_z u_z) r dr dz vanishes for an incompressible flow its elements represent exactly,
// and is 2 ∫ ψ r for the uniform radial expansion u_r = r, on every pair of elements; the
// pressure integrals are per radian.
#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/simplex_split.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

namespace formflow::assembly {
namespace {

struct Pair {
  std::string name;
  mesh::Mesh<2> mesh;
  fem::PressureSpace pressure;
};

std::vector<Pair> pairs() {
  // [0, 2] × [0, 1] (x = z axial, y = r radial, the axis at y = 0), cells 0.5 × 0.25.
  const auto box = [](int order) {
    return mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(2.0, 1.0), 4, 4, order);
  };
  return {{"Q2-P1disc", box(2), fem::PressureSpace::P1disc},
          {"Q2-Q1", box(2), fem::PressureSpace::Q1},
          {"P2+-P1disc", mesh::split_into_triangles(box(2), true), fem::PressureSpace::P1disc},
          {"P2-P1", mesh::split_into_triangles(box(2), false), fem::PressureSpace::P1},
          {"P1b-P1", mesh::split_into_triangles(box(1), true), fem::PressureSpace::P1}};
}

/// The nodal interpolant of `velocity`.
VectorX interpolated(const mesh::Mesh<2>& mesh, const std::function<Point<2>(Point<2>)>& velocity) {
  VectorX u(2 * mesh.n_nodes());
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    u.segment<2>(fem::dof_of<2>(node, 0)) = velocity(mesh.nodes.col(node));
  return u;
}

/// B_e u_e per cell with the pair's multipliers (axisymmetric), and its largest term.
std::vector<VectorX> cell_divergences(const Pair& pair, const VectorX& u, Real& scale) {
  Formulation formulation;
  formulation.type = FormulationType::Mixed;
  formulation.pressure = pair.pressure;
  const ConstraintMultipliers<2> multipliers(pair.mesh, physics::Penalty{}, formulation,
                                             fem::full_rule<2>(pair.mesh.cell_type()), 0, true);
  std::vector<VectorX> out;
  scale = 0.0;
  for (Index cell = 0; cell < pair.mesh.n_cells(); ++cell) {
    const MatrixX& divergence = multipliers.cell_divergence(cell);
    VectorX local(divergence.cols());
    for (int a = 0; a < pair.mesh.nodes_per_cell(); ++a)
      local.segment<2>(2 * a) = u.segment<2>(fem::dof_of<2>(pair.mesh.cells(a, cell), 0));
    out.push_back(divergence * local);
    scale = std::max(scale, (divergence.cwiseAbs() * local.cwiseAbs()).maxCoeff());
  }
  return out;
}

/// 64 ε: the round-off bound of one cell's divergence, relative to its scale (below).
constexpr Real divergence_tolerance = 64 * std::numeric_limits<Real>::epsilon();

TEST(AxisymmetricDivergence, IncompressibleFlowHasNoDivergenceOnEveryPair) {
  // u_z = −2z, u_r = r: ∂_r u_r + u_r/r + ∂_z u_z = 1 + 1 − 2 = 0 (the plane divergence,
  // without the hoop rate, would be −1). Linear: every element holds it exactly.
  for (const Pair& pair : pairs()) {
    const VectorX u =
        interpolated(pair.mesh, [](Point<2> p) { return Point<2>(-2 * p.x(), p.y()); });
    Real scale = 0.0;
    for (const VectorX& b : cell_divergences(pair, u, scale))
      // Round-off: the product's sum of ≤ 30 terms (15 nodes × 2 components) rounds by
      // ≤ 30 ε of `scale` (the sum of |B||u|), and each B entry, a sum over ≤ 16 rule
      // points, by ≤ 16 ε of itself: ≤ 46 ε < 64 ε of `scale`.
      EXPECT_LT(b.cwiseAbs().maxCoeff(), divergence_tolerance * scale) << pair.name;
  }
}

TEST(AxisymmetricDivergence, RadialExpansionIsTwiceTheRadiusWeightedBasisIntegral) {
  // u_r = r, u_z = 0: div u = 2, so B u = 2 ∫ ψ_i r dr dz, the r-weighted basis integral.
  for (const Pair& pair : pairs()) {
    Formulation formulation;
    formulation.type = FormulationType::Mixed;
    formulation.pressure = pair.pressure;
    const ConstraintMultipliers<2> multipliers(pair.mesh, physics::Penalty{}, formulation,
                                               fem::full_rule<2>(pair.mesh.cell_type()), 0, true);
    // The measure is per radian: Σ of σ_H ≡ 1's integrals is ∫ r dr dz over the box = 1.
    Real radial_moment = 0.0;
    for (Index cell = 0; cell < pair.mesh.n_cells(); ++cell) {
      const VectorX& integral = multipliers.cell_basis_integral(cell);
      radial_moment += fem::is_discontinuous(pair.pressure) ? integral[0] : integral.sum();
    }
    // 32–64 cells' integrals (r is linear: each rule is exact), each a sum over ≤ 16 points
    // rounding by ≤ 16 ε of itself, summed with ≤ 64 more roundings: ≤ 80 ε < 128 ε of 1.
    EXPECT_NEAR(radial_moment, 1.0, 128 * std::numeric_limits<Real>::epsilon()) << pair.name;
    const VectorX u = interpolated(pair.mesh, [](Point<2> p) { return Point<2>(0.0, p.y()); });
    Real scale = 0.0;
    const std::vector<VectorX> divergences = cell_divergences(pair, u, scale);
    for (Index cell = 0; cell < pair.mesh.n_cells(); ++cell) {
      const VectorX expected = 2.0 * multipliers.cell_basis_integral(cell);
      // The same sums on both sides, each within 46 ε of `scale` as above: their
      // difference within 2 · 46 ε < 2 · 64 ε. Eigen's own loops, no BLAS: the bits do not
      // depend on OPENBLAS_CORETYPE.
      EXPECT_LT((divergences[cell] - expected).cwiseAbs().maxCoeff(),
                2 * divergence_tolerance * scale)
          << pair.name << " cell " << cell;
    }
  }
}

} // namespace
} // namespace formflow::assembly
