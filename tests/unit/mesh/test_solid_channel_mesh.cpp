// SPDX-License-Identifier: MIT
// The rectangle and round quarter models (mesh/solid_channel_mesh.hpp): positive
// Jacobians, volumes equal to the exact volume of the discrete geometry, every
// boundary face labelled once where it lies, Q2 nodes on the true circle.
#include "formflow/fem/cell_values.hpp"
#include "formflow/mesh/cross_section_mesh.hpp"
#include "formflow/mesh/facet_axis.hpp"
#include "formflow/mesh/round_square_die_mesh.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace formflow::testing {
namespace {

using mesh::BoundaryLabel;
using mesh::ChannelSection;
using mesh::DieShape;

/// {L_c = 2, H_in = 2, H_out = 1, L_e = 2} at h = 0.5; a 45° wedge has a die of length 1.
mesh::ChannelGeometry small_channel(DieShape die) {
  mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0};
  geometry.die = die;
  geometry.die_angle = 45.0;
  return geometry;
}

mesh::SolidChannel solid(ChannelSection section) {
  mesh::SolidChannel channel;
  channel.section = section;
  channel.entry_half_width = 1.5;
  channel.exit_half_width = 0.5;
  return channel;
}

/// Σ JxW at the full Gauss rule; `valid` false if a Jacobian is not positive at a
/// Gauss point or a node.
Real volume(const mesh::Mesh<3>& mesh, bool& valid) {
  fem::CellValues<3> at_gauss(mesh.order, fem::gauss_rule<3>(mesh.order + 1));
  fem::CellValues<3> at_nodes(mesh.order, fem::nodal_rule<3>(mesh.order + 1));
  fem::CellValues<3>::Gradients coordinates(3, mesh.nodes_per_cell());
  Real total = 0.0;
  valid = true;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    valid = valid && at_gauss.reinit(coordinates) && at_nodes.reinit(coordinates);
    for (int q = 0; q < at_gauss.n_points(); ++q) total += at_gauss.JxW(q);
  }
  return total;
}

/// Faces that belong to one cell only (from the connectivity), sorted node sets → count.
std::map<std::vector<Index>, int> boundary_faces(const mesh::Mesh<3>& mesh) {
  std::map<std::vector<Index>, int> seen;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int face = 0; face < 6; ++face) {
      std::vector<Index> nodes;
      for (int local : mesh::face_local_nodes<3>(mesh.nodes_per_side(), face))
        nodes.push_back(mesh.cells(local, cell));
      std::sort(nodes.begin(), nodes.end());
      ++seen[nodes];
    }
  std::erase_if(seen, [](const auto& entry) { return entry.second != 1; });
  return seen;
}

std::vector<Index> facet_nodes(const mesh::Mesh<3>& mesh, const mesh::BoundaryFacet& facet) {
  std::vector<Index> nodes;
  for (int local : mesh::face_local_nodes<3>(mesh.nodes_per_side(), facet.local_face))
    nodes.push_back(mesh.cells(local, facet.cell));
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

/// The unit quarter disk's area as the mesh represents it, exactly: the arc is
/// cut into n_arc pieces of angle φ; Q1 cells tile the polygon (triangles
/// ½ sin φ from the origin), Q2 cells add a parabolic segment (⅔ chord × sagitta)
/// per piece, the middle node being on the bisector.
Real discrete_quarter_disk(int n_arc, int order) {
  const Real phi = std::numbers::pi / 2 / n_arc;
  const Real polygon = n_arc * 0.5 * std::sin(phi);
  if (order == 1) return polygon;
  return polygon + n_arc * 2.0 / 3.0 * 2 * std::sin(phi / 2) * (1 - std::cos(phi / 2));
}

class SolidChannelMesh
    : public ::testing::TestWithParam<std::tuple<int, ChannelSection, DieShape>> {};

TEST_P(SolidChannelMesh, PositiveCellsExactVolumeAndEveryBoundaryFaceLabelledWhereItLies) {
  const auto [order, section, die] = GetParam();
  const mesh::ChannelGeometry geometry = small_channel(die);
  const mesh::SolidChannel channel = solid(section);
  const Real size = 0.5;
  const mesh::Mesh<3> mesh =
      mesh::make_solid_channel_mesh(geometry, channel, size, order, /*drawing=*/false);
  EXPECT_EQ(static_cast<Real>(mesh.n_cells()),
            mesh::solid_channel_cell_count(geometry, channel, size));

  // The exact volume of the discrete geometry: its maps reproduce y = Y h(x),
  // z = Z w(x) with h, w linear on each column, and the Gauss rules integrate the
  // Jacobians exactly, so only rounding (1e-12 relative) separates the two.
  const Real h_in = 2, h_out = 1, die_length = die == DieShape::Square ? 0.0 : 1.0;
  const Real w_in = 1.5, w_out = 0.5;
  Real expected = 0.0;
  if (section == ChannelSection::Rectangle)
    expected = 2 * h_in * w_in + 2 * h_out * w_out +
               die_length * ((h_in * w_in + h_out * w_out) / 3 + (h_in * w_out + h_out * w_in) / 6);
  else // n_arc = 2 m with m = ⌊(H_in/h)/2⌋ = 2
    expected = discrete_quarter_disk(4, order) *
               (2 * h_in * h_in + 2 * h_out * h_out +
                die_length * (h_in * h_in + h_in * h_out + h_out * h_out) / 3);
  bool valid = false;
  EXPECT_NEAR(volume(mesh, valid), expected, 1e-12 * expected);
  EXPECT_TRUE(valid) << "a hexahedron with a non-positive Jacobian at a Gauss point or node";

  const auto boundary = boundary_faces(mesh);
  EXPECT_EQ(boundary.size(), mesh.facets.size());
  const Real front = mesh.nodes.row(0).maxCoeff(); // 4 + the die's length
  EXPECT_NEAR(front, 4 + die_length, 1e-12);
  std::map<BoundaryLabel, int> per_label;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    const std::vector<Index> nodes = facet_nodes(mesh, facet);
    ASSERT_TRUE(boundary.count(nodes)) << "facet of cell " << facet.cell << " is interior";
    ++per_label[facet.label];
    const auto axis = mesh::facet_normal_axis(mesh, facet);
    Real x_mid = 0.0;
    for (Index node : nodes) x_mid += mesh.nodes(0, node) / nodes.size();
    switch (facet.label) {
    case BoundaryLabel::Rear:
    case BoundaryLabel::Front:
      ASSERT_EQ(axis, 0);
      for (Index node : nodes)
        EXPECT_EQ(mesh.nodes(0, node), facet.label == BoundaryLabel::Rear ? 0.0 : front);
      break;
    case BoundaryLabel::Symmetry: { // on y = 0 or z = 0
      ASSERT_TRUE(axis == 1 || axis == 2);
      for (Index node : nodes) EXPECT_EQ(mesh.nodes(*axis, node), 0.0);
      break;
    }
    // (x_mid is a mean of the face's nodes: 1e-12 covers its rounding.)
    case BoundaryLabel::Container: EXPECT_LT(x_mid, 2.0); break;
    case BoundaryLabel::Die:
      EXPECT_TRUE(x_mid >= 2.0 - 1e-12 && x_mid <= 2.0 + die_length + 1e-12) << x_mid;
      break;
    case BoundaryLabel::FreeExit: EXPECT_GT(x_mid, 2.0 + die_length - 1e-12); break;
    default: ADD_FAILURE() << "unexpected label " << mesh::label_name(facet.label);
    }
    // The round section's outer nodes (Q2 mid-edge nodes too) lie on the circle of
    // radius h(x): h = 2 before the die, 1 after it, 2 − (x − 2) on the 45° cone.
    if (section == ChannelSection::Round && mesh::is_contact(facet.label))
      for (Index node : nodes) {
        const Real x = mesh.nodes(0, node);
        const Real radius = std::clamp(2.0 - (x - 2.0), 1.0, 2.0);
        EXPECT_NEAR(std::hypot(mesh.nodes(1, node), mesh.nodes(2, node)), radius, 1e-14 * 4);
      }
  }
  for (BoundaryLabel label :
       {BoundaryLabel::Rear, BoundaryLabel::Front, BoundaryLabel::Symmetry,
        BoundaryLabel::Container, BoundaryLabel::Die, BoundaryLabel::FreeExit})
    EXPECT_GT(per_label[label], 0) << mesh::label_name(label);

  // Drawing frees the container wall and nothing else.
  const mesh::Mesh<3> drawn = mesh::make_solid_channel_mesh(geometry, channel, size, order, true);
  ASSERT_EQ(drawn.facets.size(), mesh.facets.size());
  for (std::size_t k = 0; k < mesh.facets.size(); ++k)
    EXPECT_EQ(drawn.facets[k].label, mesh.facets[k].label == BoundaryLabel::Container
                                         ? BoundaryLabel::FreeEntry
                                         : mesh.facets[k].label);
}

INSTANTIATE_TEST_SUITE_P(
    Sections, SolidChannelMesh,
    ::testing::Values(std::make_tuple(1, ChannelSection::Rectangle, DieShape::Square),
                      std::make_tuple(2, ChannelSection::Rectangle, DieShape::Square),
                      std::make_tuple(1, ChannelSection::Rectangle, DieShape::Wedge),
                      std::make_tuple(2, ChannelSection::Rectangle, DieShape::Wedge),
                      std::make_tuple(1, ChannelSection::Round, DieShape::Wedge),
                      std::make_tuple(2, ChannelSection::Round, DieShape::Wedge)));

TEST(QuarterDiskSection, OGridCountsAndNoDegenerateCellForAnyRadialCount) {
  for (int n = 1; n <= 9; ++n)
    for (int order : {1, 2}) {
      const mesh::Mesh<2> disk = mesh::make_quarter_disk_section(n, order);
      const int core = std::max(1, n / 2), ring = std::max(1, n - core);
      EXPECT_EQ(disk.n_cells(), core * core + 2 * core * ring);
      fem::CellValues<2> at_nodes(order, fem::nodal_rule<2>(order + 1));
      fem::CellValues<2>::Gradients coordinates(2, disk.nodes_per_cell());
      for (Index cell = 0; cell < disk.n_cells(); ++cell) {
        for (int a = 0; a < disk.nodes_per_cell(); ++a)
          coordinates.col(a) = disk.nodes.col(disk.cells(a, cell));
        EXPECT_TRUE(at_nodes.reinit(coordinates)) << "n = " << n << ", cell " << cell;
      }
    }
}

/// The quarter disk of radius R as an O-grid around the rectangle [0, a_y] × [0, a_z]
/// represents it, exactly: the arc below the corner ray in n_low equal angles
/// (θ_c = atan2(a_z, a_y)), above it in n_high; Q1 tiles the polygon (triangles
/// ½R² sin φ from the origin), Q2 adds a parabolic segment (⅔ chord × sagitta)
/// per piece, its middle node on the bisector.
Real discrete_disk_sector(Real radius, Real from, Real to, int pieces, int order) {
  const Real phi = (to - from) / pieces;
  Real area = pieces * 0.5 * radius * radius * std::sin(phi);
  if (order == 2)
    area += pieces * 2.0 / 3.0 * 2 * radius * std::sin(phi / 2) * radius * (1 - std::cos(phi / 2));
  return area;
}

struct RoundSquareCase {
  int order;
  Real land;
};

class RoundSquareDieMesh : public ::testing::TestWithParam<RoundSquareCase> {};

TEST_P(RoundSquareDieMesh, PositiveCellsExactVolumeAndPartAreas) {
  const auto [order, land] = GetParam();
  // R = 2 → the exit 1 × 0.5 (not square, so the two curved blocks differ), h = 0.5.
  mesh::ChannelGeometry geometry = small_channel(DieShape::Square);
  geometry.land_length = land;
  mesh::SolidChannel channel = solid(ChannelSection::Round);
  const Real size = 0.5, radius = 2, a_y = 1, a_z = 0.5, die_x = 2, exit_length = 2;
  const mesh::Mesh<3> mesh = mesh::make_solid_channel_mesh(geometry, channel, size, order, false);
  EXPECT_EQ(static_cast<Real>(mesh.n_cells()),
            mesh::solid_channel_cell_count(geometry, channel, size));
  // Core 2 × 1 cells, ring round((2 − 0.5)/0.5) = 3 cells: 2 + 3·(2 + 1) = 11 per
  // container column (4 of them), 2 per exit column (4).
  EXPECT_EQ(mesh.n_cells(), 4 * 11 + 4 * 2);

  // Exact volumes of the discrete geometry (the maps are x-independent, the Gauss
  // rules integrate their Jacobians exactly): only rounding, 1e-12 relative.
  const Real corner = std::atan2(a_z, a_y);
  const Real disk = discrete_disk_sector(radius, 0, corner, 1, order) +
                    discrete_disk_sector(radius, corner, std::numbers::pi / 2, 2, order);
  const Real core = a_y * a_z;
  const Real expected = disk * die_x + core * exit_length;
  bool valid = false;
  EXPECT_NEAR(volume(mesh, valid), expected, 1e-12 * expected);
  EXPECT_TRUE(valid) << "a hexahedron with a non-positive Jacobian at a Gauss point or node";

  const auto boundary = boundary_faces(mesh);
  EXPECT_EQ(boundary.size(), mesh.facets.size());
  fem::FacetValues<3> face(order, fem::gauss_rule<2>(order + 1));
  fem::CellValues<3>::Gradients coordinates(3, mesh.nodes_per_cell());
  std::map<std::string, Real> area;
  const Real front = die_x + exit_length;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    const std::vector<Index> nodes = facet_nodes(mesh, facet);
    ASSERT_TRUE(boundary.count(nodes)) << "facet of cell " << facet.cell << " is interior";
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, facet.cell));
    face.reinit(coordinates, facet.local_face);
    Real x_min = front, x_max = 0, r_min = radius, r_max = 0;
    for (Index node : nodes) {
      x_min = std::min(x_min, mesh.nodes(0, node));
      x_max = std::max(x_max, mesh.nodes(0, node));
      const Real r = std::hypot(mesh.nodes(1, node), mesh.nodes(2, node));
      r_min = std::min(r_min, r);
      r_max = std::max(r_max, r);
    }
    std::string part(mesh::label_name(facet.label));
    switch (facet.label) {
    case BoundaryLabel::Rear: EXPECT_EQ(x_max, 0.0); break;
    case BoundaryLabel::Front: EXPECT_EQ(x_min, front); break;
    case BoundaryLabel::Symmetry: {
      const auto axis = mesh::facet_normal_axis(mesh, facet);
      ASSERT_TRUE(axis == 1 || axis == 2);
      for (Index node : nodes) EXPECT_EQ(mesh.nodes(*axis, node), 0.0);
      break;
    }
    case BoundaryLabel::Container: // on the true circle (Q2 mid-edge nodes too)
      EXPECT_LE(x_max, die_x);
      EXPECT_NEAR(r_min, radius, 4e-15 * radius);
      EXPECT_NEAR(r_max, radius, 4e-15 * radius);
      break;
    case BoundaryLabel::Die:
      if (x_max == die_x) { // the flat face x = L_c, outside the exit rectangle
        EXPECT_EQ(x_min, die_x);
        part = "die face";
        for (int q = 0; q < face.n_points(); ++q) {
          EXPECT_NEAR(face.normal(q).x(), 1.0, 1e-14) << "outward normal of the die face is +x";
          const Point<3> p = face.point(q);
          EXPECT_FALSE(p.y() < a_y && p.z() < a_z) << "a die face point inside the exit";
        }
      } else { // the land: the core's outer sides just after the die
        EXPECT_GE(x_min, die_x);
        EXPECT_LE(x_max, die_x + land);
        part = "land";
      }
      break;
    case BoundaryLabel::FreeExit: EXPECT_GE(x_min, die_x + land); break;
    default: ADD_FAILURE() << "unexpected label " << mesh::label_name(facet.label);
    }
    for (int q = 0; q < face.n_points(); ++q) area[part] += face.JxW(q);
  }
  // Part areas, exact for the discrete geometry (flat faces; 1e-12 for rounding).
  const auto expect_area = [&](const std::string& part, Real value) {
    EXPECT_NEAR(area[part], value, 1e-12 * value) << part;
  };
  expect_area("rear", disk);
  expect_area("front", core);
  expect_area("die face", disk - core); // πR²/4 − a_y a_z in the limit of fine arcs
  expect_area("free_exit", (a_y + a_z) * (exit_length - land));
  if (land > 0) expect_area("land", (a_y + a_z) * land);
  expect_area("symmetry", radius * die_x * 2 + (a_y + a_z) * exit_length);
  EXPECT_GT(area["container"], 0.0);

  const mesh::Mesh<3> drawn = mesh::make_solid_channel_mesh(geometry, channel, size, order, true);
  ASSERT_EQ(drawn.facets.size(), mesh.facets.size());
  for (std::size_t k = 0; k < mesh.facets.size(); ++k)
    EXPECT_EQ(drawn.facets[k].label, mesh.facets[k].label == BoundaryLabel::Container
                                         ? BoundaryLabel::FreeEntry
                                         : mesh.facets[k].label);
}

INSTANTIATE_TEST_SUITE_P(Cases, RoundSquareDieMesh,
                         ::testing::Values(RoundSquareCase{1, 0.0}, RoundSquareCase{2, 0.0},
                                           RoundSquareCase{1, 0.5}, RoundSquareCase{2, 0.5}));

TEST(CoreRingSection, NoDegenerateCellForCornersUpToTheCircle) {
  // Corners on and off the diagonal, down to 1 % of the radius from the circle.
  for (const auto& [a_y, a_z] : std::vector<std::pair<Real, Real>>{
           {0.5, 0.5}, {0.8, 0.5}, {0.2, 0.9}, {0.7, 0.7}, {0.99, 0.05}})
    for (int cells = 1; cells <= 3; ++cells)
      for (int ring = 1; ring <= 3; ++ring)
        for (int order : {1, 2}) {
          const mesh::CoreRingSection section =
              mesh::make_core_ring_section(1.0, a_y, a_z, cells, cells + 1, ring, order);
          const mesh::Mesh<2>& disk = section.mesh;
          EXPECT_EQ(disk.n_cells(), cells * (cells + 1) + ring * (2 * cells + 1));
          EXPECT_EQ(static_cast<int>(section.core_sides.size()), 2 * cells + 1);
          fem::CellValues<2> at_nodes(order, fem::nodal_rule<2>(order + 1));
          fem::CellValues<2>::Gradients coordinates(2, disk.nodes_per_cell());
          for (Index cell = 0; cell < disk.n_cells(); ++cell) {
            for (int a = 0; a < disk.nodes_per_cell(); ++a)
              coordinates.col(a) = disk.nodes.col(disk.cells(a, cell));
            EXPECT_TRUE(at_nodes.reinit(coordinates))
                << a_y << " × " << a_z << ", cells " << cells << ", ring " << ring;
          }
        }
}

TEST(SolidLengthsFit, TheRoundSquareDiesExitMustFitTheCircle) {
  const mesh::ChannelGeometry square = small_channel(DieShape::Square); // R = 2, H_out = 1
  mesh::SolidChannel channel = solid(ChannelSection::Round);
  channel.exit_half_width = 1.0; // corner radius 1.41 ≤ 2 − 0.5/2
  EXPECT_TRUE(mesh::solid_lengths_fit(square, channel, 0.5));
  channel.exit_half_width = 1.5; // 1.80: inside, but by less than half a cell of 0.5 …
  EXPECT_FALSE(mesh::solid_lengths_fit(square, channel, 0.5));
  EXPECT_TRUE(mesh::solid_lengths_fit(square, channel, 0.25)); // … and more than of 0.25
  channel.exit_half_width = 1.75;                              // 2.02: outside the circle
  EXPECT_FALSE(mesh::solid_lengths_fit(square, channel, 0.25));
  channel.exit_half_width = 0.75; // 0.75 does not fit h = 0.5
  EXPECT_FALSE(mesh::solid_lengths_fit(square, channel, 0.5));
}

TEST(SolidLengthsFit, TheRectanglesWidthsCountForTheSquareDie) {
  const mesh::ChannelGeometry square = small_channel(DieShape::Square);
  mesh::SolidChannel channel = solid(ChannelSection::Rectangle);
  EXPECT_TRUE(mesh::solid_lengths_fit(square, channel, 0.5));
  EXPECT_FALSE(mesh::solid_lengths_fit(square, channel, 1.0)); // 1.5 and 0.5 do not fit
  channel.section = ChannelSection::Round; // a revolved die: no half width to fit
  EXPECT_TRUE(mesh::solid_lengths_fit(small_channel(DieShape::Wedge), channel, 1.0));
}

} // namespace
} // namespace formflow::testing
