// SPDX-License-Identifier: MIT
// mesh.source = "gmsh" with geometry.dimension = 3: the slab and the square-die
// rectangle meshed by Gmsh in hexahedra, their geometry and parts exact, and
// their ram reaction the structured generator's within the discretisation error.
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/quadrature.hpp"
#include "formflow/mesh/gmsh_solid_channel.hpp"
#include "support/approx.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using mesh::BoundaryLabel;
using testing::quoted;
using testing::read_text;

fem::CellValues<3>::Gradients cell_coordinates(const mesh::Mesh<3>& mesh, Index cell) {
  fem::CellValues<3>::Gradients coordinates(3, mesh.nodes_per_cell());
  for (int a = 0; a < mesh.nodes_per_cell(); ++a)
    coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
  return coordinates;
}

/// Volume of the mesh (every cell's Jacobian checked positive) and area of each part.
std::pair<Real, std::map<BoundaryLabel, Real>> measures(const mesh::Mesh<3>& mesh) {
  fem::CellValues<3> values(mesh.order, fem::gauss_rule<3>(mesh.order + 1));
  Real volume = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    EXPECT_TRUE(values.reinit(cell_coordinates(mesh, cell))) << "cell " << cell << " inverted";
    for (int q = 0; q < values.n_points(); ++q) volume += values.JxW(q);
  }
  fem::FacetValues<3> facet(mesh.order, fem::gauss_rule<2>(mesh.order + 1));
  std::map<BoundaryLabel, Real> areas;
  for (const auto& f : mesh.facets) {
    facet.reinit(cell_coordinates(mesh, f.cell), f.local_face);
    for (int q = 0; q < facet.n_points(); ++q) areas[f.label] += facet.JxW(q);
  }
  return {volume, areas};
}

mesh::ChannelGeometry small_channel() {
  mesh::ChannelGeometry geometry;
  geometry.container_length = 1;
  geometry.entry_half_height = 1;
  geometry.exit_half_height = 0.5;
  geometry.exit_length = 1;
  return geometry;
}

/// Relative rounding of a measure summed over the mesh's cells: each cell's
/// Gauss-rule sum of Jacobians carries a few ε of its coordinates' rounding (Gmsh
/// computes the nodes in doubles), and the cells' sums add up: 64 ε per cell, bounded
/// by the cell count (no conditioning enters: a sum of positive terms).
Real measure_rounding(const mesh::Mesh<3>& mesh) {
  return 64.0 * static_cast<Real>(mesh.n_cells()) * std::numeric_limits<Real>::epsilon();
}

TEST(GmshSolidChannel, SlabHasTheChannelVolumeAndParts) {
  mesh::ChannelGeometry geometry = small_channel();
  geometry.die = mesh::DieShape::Wedge; // a tilted die face: labels by curve, not by plane
  geometry.die_angle = 45;
  mesh::SolidChannel slab;
  slab.thickness = 0.5;
  for (const int order : {1, 2}) {
    SCOPED_TRACE(order);
    const mesh::Mesh<3> mesh =
        mesh::make_gmsh_solid_channel_mesh(geometry, slab, 0.25, order, false);
    const auto [volume, areas] = measures(mesh);
    const Real rounding = measure_rounding(mesh);
    // Plane faces: the measures are exact up to rounding. Plane area: container
    // 1 × 1, the die's trapezoid (45°: 0.5 long in x, heights 1 → 0.5), exit 1 × 0.5.
    const Real plane_area = 1.0 + 0.5 * (1.0 + 0.5) * 0.5 + 1.0 * 0.5;
    EXPECT_TRUE(testing::approx(volume, plane_area * slab.thickness, rounding));
    const std::map<BoundaryLabel, Real> expected = {
        {BoundaryLabel::Rear, 1.0 * 0.5},
        {BoundaryLabel::Container, 1.0 * 0.5},
        {BoundaryLabel::Die, std::sqrt(2.0) * 0.5 * 0.5},
        {BoundaryLabel::FreeExit, 1.0 * 0.5},
        {BoundaryLabel::Front, 0.5 * 0.5},
        {BoundaryLabel::Symmetry, 2.5 * 0.5 + 2 * plane_area}};
    EXPECT_EQ(areas.size(), expected.size());
    for (const auto& [label, area] : expected)
      EXPECT_TRUE(testing::approx(areas.at(label), area, rounding)) << mesh::label_name(label);
  }
}

TEST(GmshSolidChannel, RectangleHasTheBarVolumeAndParts) {
  mesh::ChannelGeometry geometry = small_channel();
  geometry.land_length = 0.25;
  mesh::SolidChannel bar;
  bar.section = mesh::ChannelSection::Rectangle;
  bar.entry_half_width = 1.5; // not a multiple of the size: Gmsh needs none
  bar.exit_half_width = 0.5;
  for (const int order : {1, 2}) {
    SCOPED_TRACE(order);
    const mesh::Mesh<3> mesh = mesh::make_gmsh_solid_channel_mesh(geometry, bar, 0.3, order, false);
    const auto [volume, areas] = measures(mesh);
    const Real rounding = measure_rounding(mesh);
    const Real container = 1.0 * 1.0 * 1.5, exit = 1.25 * 0.5 * 0.5;
    EXPECT_TRUE(testing::approx(volume, container + exit, rounding));
    const Real die_face = 1.0 * 1.5 - 0.5 * 0.5, land = 0.25 * (0.5 + 0.5);
    const std::map<BoundaryLabel, Real> expected = {
        {BoundaryLabel::Rear, 1.5},
        {BoundaryLabel::Container, 1.0 * 1.5 + 1.0 * 1.0},
        {BoundaryLabel::Die, die_face + land},
        {BoundaryLabel::FreeExit, 1.0 * (0.5 + 0.5)},
        {BoundaryLabel::Front, 0.25},
        {BoundaryLabel::Symmetry, (1.0 * 1.5 + 1.25 * 0.5) + (1.0 * 1.0 + 1.25 * 0.5)}};
    EXPECT_EQ(areas.size(), expected.size());
    for (const auto& [label, area] : expected)
      EXPECT_TRUE(testing::approx(areas.at(label), area, rounding)) << mesh::label_name(label);
  }
}

TEST(GmshSolidChannel, DrawingFreesTheContainerWall) {
  const mesh::Mesh<3> mesh =
      mesh::make_gmsh_solid_channel_mesh(small_channel(), mesh::SolidChannel{}, 0.5, 1, true);
  std::map<BoundaryLabel, int> count;
  for (const auto& f : mesh.facets) ++count[f.label];
  EXPECT_EQ(count.count(BoundaryLabel::Container), 0u);
  EXPECT_GT(count[BoundaryLabel::FreeEntry], 0);
}

/// ram_reaction of the case `text` run through the binary.
double ram_reaction(const testing::ScratchDirectory& scratch, const std::string& text) {
  const fs::path case_path = scratch / "case.toml";
  std::ofstream(case_path) << text;
  const fs::path out = scratch / "out";
  fs::remove_all(out);
  const testing::CliResult result = testing::run_cli(
      "run " + quoted(case_path.string()) + " -q -o " + quoted(out.string()), scratch.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(read_text(out / "summary.json"))
      .at("pressure")
      .at("ram_reaction")
      .get<double>();
}

/// The Gmsh mesh's load against the structured generator's. Both are
/// discretisations of one continuous problem: p_g(h) − p_s(h) = e_g − e_s, the
/// two meshes' errors. The structured error at h is estimated from its change
/// under one refinement, E = |p_s(h) − p_s(h/2)| / (1 − 2^−1) (first order, the
/// square die's corner singularity: docs/validation.md). Gmsh's cells are of the
/// same target size, unstructured, so its error is allowed twice the structured
/// one: |p_g − p_s| ≤ E + 2E. The solver tolerance (1e-8) is far below E.
void expect_gmsh_within_discretisation(const std::string& physics, Real size) {
  testing::ScratchDirectory scratch("formflow-gmsh-solid");
  const auto mesh_block = [&](const std::string& source, Real h) {
    return physics + "[mesh]\nelement = \"Q1\"\nsource = \"" + source +
           "\"\nsize = " + std::to_string(h) + "\n\n[solver]\ntolerance = 1e-8\n";
  };
  const double structured = ram_reaction(scratch, mesh_block("structured", size));
  const double refined = ram_reaction(scratch, mesh_block("structured", size / 2));
  const double gmsh = ram_reaction(scratch, mesh_block("gmsh", size));
  const double estimate = std::abs(structured - refined) / (1 - 0.5);
  ::testing::Test::RecordProperty("structured", std::to_string(structured));
  ::testing::Test::RecordProperty("refined", std::to_string(refined));
  ::testing::Test::RecordProperty("gmsh", std::to_string(gmsh));
  std::printf("structured %.6f, structured h/2 %.6f, gmsh %.6f: |gmsh - structured| = %.3g, "
              "3E = %.3g\n",
              structured, refined, gmsh, std::abs(gmsh - structured), 3 * estimate);
  EXPECT_GT(estimate, 0.0);
  EXPECT_LE(std::abs(gmsh - structured), 3 * estimate);
}

const std::string slab_physics = "[geometry]\ndimension = 3\nthickness = 0.5\n"
                                 "container_length = 1\nentry_half_height = 1\n"
                                 "exit_half_height = 0.5\nexit_length = 1\n\n"
                                 "[friction]\nmu = 0.1\n\n";

TEST(GmshSolidChannel, SlabLoadIsTheStructuredOneWithinTheDiscretisationError) {
  expect_gmsh_within_discretisation(slab_physics, 0.25);
}

TEST(GmshSolidChannel, RectangleLoadIsTheStructuredOneWithinTheDiscretisationError) {
  expect_gmsh_within_discretisation(
      "[geometry]\ndimension = 3\nsection = \"rectangle\"\ncontainer_length = 1\n"
      "entry_half_height = 1\nexit_half_height = 0.5\nexit_length = 1\n"
      "entry_half_width = 1\nexit_half_width = 0.5\n\n[friction]\nmu = 0.1\n\n",
      0.25);
}

} // namespace
} // namespace formflow
