// SPDX-License-Identifier: MIT
// Nodal contact normals (assembly/contact_normals.hpp): the face normal on a
// straight wall, the bisector at a kink between equal faces (and the faces' own
// normals beyond contact.corner_angle), the radius on a circle.
#include "formflow/assembly/contact_normals.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/fem/dof_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace formflow::testing {
namespace {

/// A strip of `n_cells` cells of order `order` along a curve: the top side of
/// column s (s = 0 … n_cells, fractional for Q2 mid nodes) is top(s), the bottom
/// side bottom(s); the top faces (local face 3) are die contact faces.
mesh::Mesh<2> strip(int n_cells, int order, const std::function<Point<2>(Real)>& top,
                    const std::function<Point<2>(Real)>& bottom) {
  mesh::Mesh<2> mesh;
  mesh.order = order;
  const int n_columns = n_cells * order + 1, n_rows = order + 1;
  mesh.nodes.resize(2, n_columns * n_rows);
  for (int j = 0; j < n_rows; ++j)
    for (int i = 0; i < n_columns; ++i) {
      const Real s = static_cast<Real>(i) / order, t = static_cast<Real>(j) / order;
      mesh.nodes.col(j * n_columns + i) = (1.0 - t) * bottom(s) + t * top(s);
    }
  mesh.cells.resize(n_rows * n_rows, n_cells);
  for (int c = 0; c < n_cells; ++c) {
    for (int jj = 0; jj < n_rows; ++jj)
      for (int ii = 0; ii < n_rows; ++ii)
        mesh.cells(jj * n_rows + ii, c) = jj * n_columns + c * order + ii;
    mesh.facets.push_back({c, 3, mesh::BoundaryLabel::Die});
  }
  return mesh;
}

std::vector<Index> all_facets(const mesh::Mesh<2>& mesh) {
  std::vector<Index> facets(mesh.facets.size());
  for (std::size_t f = 0; f < facets.size(); ++f) facets[f] = static_cast<Index>(f);
  return facets;
}

/// The node of nodal-rule point q of top face `cell` (top row, left to right).
Index top_node(const mesh::Mesh<2>& mesh, Index cell, int q) {
  return mesh.cells(mesh.order * (mesh.order + 1) + q, cell);
}

TEST(ContactNormals, StraightWallGivesTheFaceNormalAtEveryNode) {
  for (int order : {1, 2}) {
    // Unequal columns (s²) so that the length weights differ from face to face.
    const auto mesh = strip(
        4, order, [](Real s) { return Point<2>(0.5 * s * s + s, 2.0 + 0.25 * (0.5 * s * s + s)); },
        [](Real s) { return Point<2>(0.5 * s * s + s, 0.0); });
    const auto normals = assembly::nodal_contact_normals<2>(mesh, all_facets(mesh), 45.0);
    ASSERT_EQ(normals.size(), 4u * (order + 1));
    const Point<2> expected = Point<2>(-0.25, 1.0).normalized();
    for (const Point<2>& normal : normals)
      EXPECT_NEAR((normal - expected).norm(), 0.0, 1e-12) << order;
  }
}

TEST(ContactNormals, KinkBetweenEqualFacesGivesTheBisectorOrBothFaceNormals) {
  const Real turn = 15.0 * std::numbers::pi / 180.0;
  // Top: horizontal for s ≤ 1, then turned down by `turn`, each face of length 1.
  auto top = [turn](Real s) {
    return s <= 1.0 ? Point<2>(s, 2.0)
                    : Point<2>(1.0 + (s - 1.0) * std::cos(turn), 2.0 - (s - 1.0) * std::sin(turn));
  };
  auto bottom = [](Real s) { return Point<2>(s, 0.0); };
  for (int order : {1, 2}) {
    const auto mesh = strip(2, order, top, bottom);
    const int n_q = order + 1;
    const Point<2> first(0.0, 1.0), second(std::sin(turn), std::cos(turn));
    const Point<2> bisector(std::sin(turn / 2), std::cos(turn / 2));

    const auto averaged = assembly::nodal_contact_normals<2>(mesh, all_facets(mesh), 45.0);
    ASSERT_EQ(top_node(mesh, 0, n_q - 1), top_node(mesh, 1, 0)); // the shared corner node
    EXPECT_NEAR((averaged[n_q - 1] - bisector).norm(), 0.0, 1e-12) << order;
    EXPECT_NEAR((averaged[n_q] - bisector).norm(), 0.0, 1e-12) << order;
    EXPECT_NEAR((averaged[0] - first).norm(), 0.0, 1e-12) << order; // one face only
    EXPECT_NEAR((averaged[2 * n_q - 1] - second).norm(), 0.0, 1e-12) << order;

    // A 15° turn is a corner for corner_angle = 10°: each face keeps its normal.
    const auto cornered = assembly::nodal_contact_normals<2>(mesh, all_facets(mesh), 10.0);
    EXPECT_NEAR((cornered[n_q - 1] - first).norm(), 0.0, 1e-12) << order;
    EXPECT_NEAR((cornered[n_q] - second).norm(), 0.0, 1e-12) << order;
  }
}

TEST(ContactNormals, NodesOnACircleGetTheRadialDirection) {
  // Quarter annulus 1 ≤ r ≤ 2, clockwise in s so that the cells are positively
  // oriented; the outer arc (nodes exactly on r = 2) is the contact face.
  const int n_cells = 8;
  const Real step = std::numbers::pi / 2 / n_cells;
  auto polar = [step](Real radius) {
    return [radius, step](Real s) {
      const Real angle = std::numbers::pi / 2 - s * step;
      return Point<2>(radius * std::cos(angle), radius * std::sin(angle));
    };
  };
  for (int order : {1, 2}) {
    const auto mesh = strip(n_cells, order, polar(2.0), polar(1.0));
    const auto normals = assembly::nodal_contact_normals<2>(mesh, all_facets(mesh), 45.0);
    const int n_q = order + 1;
    for (Index cell = 0; cell < n_cells; ++cell)
      for (int q = 0; q < n_q; ++q) {
        const Point<2> radial = mesh.nodes.col(top_node(mesh, cell, q)).normalized();
        const bool chain_end = (cell == 0 && q == 0) || (cell == n_cells - 1 && q == n_q - 1);
        // Interior nodes: symmetric faces (Q1) or the symmetric parabola's midpoint
        // (Q2), radial up to round-off; the two chain ends see one face only: a Q1
        // chord is off by half its angle, a Q2 parabola by O(step²).
        const Real tolerance = chain_end ? (order == 1 ? 0.51 * step : 0.1 * step * step) : 1e-12;
        EXPECT_NEAR((normals[cell * n_q + q] - radial).norm(), 0.0, tolerance)
            << "order " << order << " cell " << cell << " point " << q;
      }
  }
}

TEST(ContactNormals, ProblemEvaluatesContactAtTheNodesWithTheNodalNormals) {
  // The kink of the test above in a FormingProblem with contact.normals = nodes:
  // the Γ3 points are the face nodes, their weights the lumped face lengths, and
  // u_N, u_T and −σ_N = u_N/d_N use the nodal normal (the bisector at the kink).
  const Real turn = 15.0 * std::numbers::pi / 180.0;
  auto top = [turn](Real s) {
    return s <= 1.0 ? Point<2>(s, 2.0)
                    : Point<2>(1.0 + (s - 1.0) * std::cos(turn), 2.0 - (s - 1.0) * std::sin(turn));
  };
  for (int order : {1, 2}) {
    const auto mesh = strip(2, order, top, [](Real s) { return Point<2>(s, 0.0); });
    assembly::ProblemSettings settings;
    settings.contact.normals = assembly::ContactNormals::Nodes;
    assembly::DirichletConstraints none;
    none.prescribed.assign(static_cast<std::size_t>(mesh.n_nodes() * 2), false);
    none.values = VectorX::Zero(mesh.n_nodes() * 2);
    const assembly::FormingProblem<2> problem(mesh, settings, none, {});
    ASSERT_TRUE(problem.contact_points_at_nodes());

    VectorX u(mesh.n_nodes() * 2);
    for (Index node = 0; node < mesh.n_nodes(); ++node)
      u.segment<2>(fem::dof_of<2>(node, 0)) = Point<2>(1.0, 0.0);
    const auto state = problem.contact_state(u);
    const auto normals = assembly::nodal_contact_normals<2>(mesh, all_facets(mesh), 60.0);
    ASSERT_EQ(state.size(), normals.size());
    const int n_q = order + 1;
    Real length = 0.0;
    for (std::size_t k = 0; k < state.size(); ++k) {
      const auto& point = state[k];
      const Index node = top_node(mesh, static_cast<Index>(k) / n_q, static_cast<int>(k) % n_q);
      EXPECT_NEAR((point.position - mesh.nodes.col(node)).norm(), 0.0, 1e-12);
      EXPECT_NEAR((point.normal - normals[k]).norm(), 0.0, 1e-15);
      EXPECT_NEAR(point.normal_velocity, normals[k].x(), 1e-15); // u = (1, 0)
      EXPECT_NEAR(point.tangential_velocity.dot(point.normal), 0.0, 1e-15);
      EXPECT_NEAR(point.contact_pressure, point.normal_velocity / settings.penalty.d_n, 1e-6);
      length += point.weight;
    }
    EXPECT_NEAR(length, 2.0, 1e-12); // two faces of length 1
    // The corner node slides: u_N there is u·(bisector), sin(7.5°), not 0 or sin 15°.
    EXPECT_NEAR(state[n_q - 1].normal_velocity, std::sin(turn / 2), 1e-12);
  }
}

} // namespace
} // namespace formflow::testing
