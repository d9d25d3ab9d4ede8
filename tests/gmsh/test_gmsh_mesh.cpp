// SPDX-License-Identifier: MIT
// Gmsh meshes as formflow meshes: node order, generated channel, normals, .msh round trip.
#include "formflow/core/error.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/mesh/gmsh_mesh.hpp"
#include "gmsh/gmsh_test_mesh.hpp"
#include "support/approx.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using mesh::BoundaryLabel;

class ScratchDirectory {
public:
  ScratchDirectory() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("formflow-gmsh-" + std::string(info->name()) + "-" + std::to_string(getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDirectory() { fs::remove_all(path_); }
  fs::path operator/(const std::string& name) const { return path_ / name; }

private:
  fs::path path_;
};

fem::CellValues<2>::Gradients cell_coordinates(const mesh::Mesh<2>& mesh, Index cell) {
  fem::CellValues<2>::Gradients coordinates(2, mesh.nodes_per_cell());
  for (int a = 0; a < mesh.nodes_per_cell(); ++a)
    coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
  return coordinates;
}

/// Total length of the facets of each label, integrated with the face rule.
std::map<BoundaryLabel, Real> part_lengths(const mesh::Mesh<2>& mesh) {
  fem::FacetValues<2> facet(mesh.order, fem::gauss_rule<1>(mesh.order + 1));
  std::map<BoundaryLabel, Real> lengths;
  for (const auto& f : mesh.facets) {
    facet.reinit(cell_coordinates(mesh, f.cell), f.local_face);
    for (int q = 0; q < facet.n_points(); ++q) lengths[f.label] += facet.JxW(q);
  }
  return lengths;
}

TEST(GmshMesh, NodeOrderMatchesGmshReferenceCoordinates) {
  // Gmsh's own reference coordinates of quad-4 and quad-9 nodes, mapped by our
  // table, must land on our lexicographic reference nodes.
  mesh::GmshSession session;
  for (const auto& [type, order] : {std::pair{3, 1}, std::pair{10, 2}}) {
    std::string name;
    int dim = 0, element_order = 0, n_nodes = 0, n_primary = 0;
    std::vector<double> reference;
    gmsh::model::mesh::getElementProperties(type, name, dim, element_order, n_nodes, reference,
                                            n_primary);
    ASSERT_EQ(n_nodes, (order + 1) * (order + 1)) << name;
    for (int k = 0; k < n_nodes; ++k) {
      const Point<2> ours =
          fem::reference_node<2>(order, mesh::lexicographic_of_gmsh_node(order, k));
      EXPECT_EQ(ours.x(), reference[2 * k]) << name << " node " << k;
      EXPECT_EQ(ours.y(), reference[2 * k + 1]) << name << " node " << k;
    }
  }
}

TEST(GmshMesh, GeneratedChannelHasTheBenchmarkGeometryAndParts) {
  const mesh::ChannelGeometry geometry; // the benchmark: 10 × 10 container, 10 × 5 exit
  for (const int order : {1, 2}) {
    const mesh::Mesh<2> mesh = mesh::make_gmsh_channel_mesh(geometry, 1.0, order);
    EXPECT_EQ(mesh.order, order);
    // Not the structured grid, but cells of about the target size: 150 unit
    // squares' worth of area in 100..300 cells.
    EXPECT_GT(mesh.n_cells(), 100);
    EXPECT_LT(mesh.n_cells(), 300);
    fem::CellValues<2> values(order, fem::gauss_rule<2>(order + 1));
    Real area = 0.0;
    for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
      ASSERT_TRUE(values.reinit(cell_coordinates(mesh, cell))) << "cell " << cell << " inverted";
      for (int q = 0; q < values.n_points(); ++q) area += values.JxW(q);
    }
    // Straight edges: the area and lengths are exact up to rounding.
    EXPECT_TRUE(testing::approx(area, 150.0, 1e-12));
    const auto lengths = part_lengths(mesh);
    const std::map<BoundaryLabel, Real> expected = {
        {BoundaryLabel::Rear, 10.0}, {BoundaryLabel::Container, 10.0},
        {BoundaryLabel::Die, 5.0},   {BoundaryLabel::FreeExit, 10.0},
        {BoundaryLabel::Front, 5.0}, {BoundaryLabel::Symmetry, 20.0}};
    EXPECT_EQ(lengths.size(), expected.size());
    for (const auto& [label, length] : expected)
      EXPECT_TRUE(testing::approx(lengths.at(label), length, 1e-12)) << mesh::label_name(label);
  }
}

/// The same cells with the local numbering of cell c turned by c mod 4 quarter
/// turns (a rotation keeps the orientation), the facets' local faces renamed to
/// match: a mesh whose boundary facets use every local face.
mesh::Mesh<2> with_rotated_cells(const mesh::Mesh<2>& mesh) {
  const int n = mesh.nodes_per_side();
  mesh::Mesh<2> rotated = mesh;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int turn = 0; turn < cell % 4; ++turn) {
      const auto before = rotated.cells.col(cell).eval();
      // New lattice node (i, j) is the old node at the rotated position (j, n − 1 − i).
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) rotated.cells(j * n + i, cell) = before((n - 1 - i) * n + j);
    }
  for (auto& facet : rotated.facets) {
    auto ends = [&](const mesh::Mesh<2>& m, int face) {
      const auto local = mesh::face_local_nodes<2>(n, face);
      const Index a = m.cells(local.front(), facet.cell), b = m.cells(local.back(), facet.cell);
      return std::pair{std::min(a, b), std::max(a, b)};
    };
    const auto wanted = ends(mesh, facet.local_face);
    for (int face = 0; face < 4; ++face)
      if (ends(rotated, face) == wanted) {
        facet.local_face = face;
        break;
      }
  }
  return rotated;
}

TEST(GmshMesh, FacetNormalsPointOutOfTheChannelForEveryLocalFace) {
  // Cells of a general mesh meet the boundary with any of their four local
  // faces; the Nanson normal must point outward whichever it is.
  const mesh::Mesh<2> mesh =
      with_rotated_cells(mesh::make_gmsh_channel_mesh(mesh::ChannelGeometry{}, 1.0, 2));
  const std::map<BoundaryLabel, Point<2>> outward = {
      {BoundaryLabel::Rear, Point<2>(-1.0, 0.0)}, {BoundaryLabel::Container, Point<2>(0.0, 1.0)},
      {BoundaryLabel::Die, Point<2>(1.0, 0.0)},   {BoundaryLabel::FreeExit, Point<2>(0.0, 1.0)},
      {BoundaryLabel::Front, Point<2>(1.0, 0.0)}, {BoundaryLabel::Symmetry, Point<2>(0.0, -1.0)}};
  fem::FacetValues<2> facet(2, fem::gauss_rule<1>(3));
  std::set<int> local_faces_seen;
  for (const auto& f : mesh.facets) {
    local_faces_seen.insert(f.local_face);
    facet.reinit(cell_coordinates(mesh, f.cell), f.local_face);
    for (int q = 0; q < facet.n_points(); ++q)
      EXPECT_LT((facet.normal(q) - outward.at(f.label)).norm(), 1e-12)
          << mesh::label_name(f.label) << " facet of cell " << f.cell;
  }
  EXPECT_EQ(local_faces_seen.size(), 4u) << "the mesh should exercise every local face";
}

TEST(GmshMesh, CurvedQ2FacesGiveRadialNormalsAndTheArcLength) {
  // A quarter annulus 1 ≤ r ≤ 2 meshed by Gmsh with quad-9 cells whose mid-side
  // nodes lie on the arcs: the isoparametric normals must be radial (outward
  // on r = 2, inward on r = 1) and the arcs' lengths π and π/2, up to the
  // O(h⁴)-ish geometric error of a quadratic arc of angle ≈ h/r.
  mesh::GmshSession session;
  session.call([] {
    namespace geo = gmsh::model::geo;
    gmsh::model::add("annulus");
    const Real h = 0.25;
    const int centre = geo::addPoint(0, 0, 0, h);
    const int a = geo::addPoint(1, 0, 0, h), b = geo::addPoint(2, 0, 0, h);
    const int c = geo::addPoint(0, 2, 0, h), d = geo::addPoint(0, 1, 0, h);
    const int bottom = geo::addLine(a, b), outer = geo::addCircleArc(b, centre, c);
    const int left = geo::addLine(c, d), inner = geo::addCircleArc(d, centre, a);
    const int surface = geo::addPlaneSurface({geo::addCurveLoop({bottom, outer, left, inner})});
    geo::synchronize();
    for (const auto& [tag, name] : {std::pair{bottom, "bottom"}, std::pair{outer, "outer"},
                                    std::pair{left, "left"}, std::pair{inner, "inner"}})
      gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {tag}), name);
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "domain");
    gmsh::option::setNumber("Mesh.Algorithm", 6);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::model::mesh::generate(2);
    gmsh::model::mesh::setOrder(2);
  });
  const mesh::Mesh<2> mesh = mesh::mesh_from_gmsh_model(session,
                                                        {{"bottom", BoundaryLabel::Symmetry},
                                                         {"outer", BoundaryLabel::Die},
                                                         {"left", BoundaryLabel::Rear},
                                                         {"inner", BoundaryLabel::Container}},
                                                        2);
  fem::FacetValues<2> facet(2, fem::gauss_rule<1>(3));
  for (const auto& f : mesh.facets) {
    if (!mesh::is_contact(f.label)) continue;
    facet.reinit(cell_coordinates(mesh, f.cell), f.local_face);
    const Real sign =
        f.label == BoundaryLabel::Die ? 1.0 : -1.0; // outward: away from / to the centre
    for (int q = 0; q < facet.n_points(); ++q) {
      const Point<2> radial = facet.point(q).normalized();
      EXPECT_LT((facet.normal(q) - sign * radial).norm(), 2e-3) << mesh::label_name(f.label);
    }
  }
  const auto lengths = part_lengths(mesh);
  EXPECT_TRUE(testing::approx(lengths.at(BoundaryLabel::Die), std::numbers::pi, 1e-4));
  EXPECT_TRUE(testing::approx(lengths.at(BoundaryLabel::Container), std::numbers::pi / 2, 1e-4));
}

TEST(GmshMesh, MshFileRoundTripGivesTheSameMesh) {
  // The channel written by Gmsh as .msh 4.1 (ASCII and binary) and read back
  // through the file path must be the mesh converted straight from the model.
  const ScratchDirectory scratch;
  for (const int order : {1, 2}) {
    mesh::Mesh<2> direct;
    {
      mesh::GmshSession session;
      const mesh::ChannelGeometry geometry;
      mesh::build_channel_model(session, geometry, mesh::square_die_face(geometry), 1.25, order);
      direct = mesh::mesh_from_gmsh_model(session, {}, order);
      mesh::write_gmsh_mesh(session, (scratch / "ascii.msh").string(), false);
      mesh::write_gmsh_mesh(session, (scratch / "binary.msh").string(), true);
    }
    for (const std::string name : {"ascii.msh", "binary.msh"}) {
      const mesh::Mesh<2> read = mesh::read_gmsh_mesh((scratch / name).string(), {}, order);
      ASSERT_EQ(read.order, order);
      ASSERT_EQ(read.n_nodes(), direct.n_nodes()) << name;
      ASSERT_EQ(read.n_cells(), direct.n_cells()) << name;
      // Gmsh writes ASCII coordinates with 16 significant digits.
      EXPECT_LT((read.nodes - direct.nodes).cwiseAbs().maxCoeff(), 1e-13) << name;
      EXPECT_EQ(read.cells, direct.cells) << name;
      ASSERT_EQ(read.facets.size(), direct.facets.size()) << name;
      for (std::size_t k = 0; k < read.facets.size(); ++k) {
        EXPECT_EQ(read.facets[k].cell, direct.facets[k].cell);
        EXPECT_EQ(read.facets[k].local_face, direct.facets[k].local_face);
        EXPECT_EQ(read.facets[k].label, direct.facets[k].label);
      }
    }
  }
}

TEST(GmshMesh, ClockwiseCellsAreMirroredToCounterClockwise) {
  // The two squares with both elements listed clockwise (a surface whose
  // normal is −z): the cells must come out with a positive Jacobian and the
  // same boundary parts.
  const ScratchDirectory scratch;
  testing::TestMesh clockwise = testing::two_squares();
  for (auto& element : clockwise.elements) std::reverse(element.begin(), element.end());
  const std::string path = (scratch / "clockwise.msh").string();
  testing::write_test_mesh(clockwise, path);
  const mesh::Mesh<2> mesh = mesh::read_gmsh_mesh(path,
                                                  {{"ram", BoundaryLabel::Rear},
                                                   {"axis", BoundaryLabel::Symmetry},
                                                   {"front", BoundaryLabel::Front},
                                                   {"wall", BoundaryLabel::Container}},
                                                  1);
  ASSERT_EQ(mesh.n_cells(), 2);
  fem::CellValues<2> values(1, fem::gauss_rule<2>(2));
  for (Index cell = 0; cell < 2; ++cell) EXPECT_TRUE(values.reinit(cell_coordinates(mesh, cell)));
  const auto lengths = part_lengths(mesh);
  EXPECT_TRUE(testing::approx(lengths.at(BoundaryLabel::Rear), 1.0, 1e-14));
  EXPECT_TRUE(testing::approx(lengths.at(BoundaryLabel::Symmetry), 2.0, 1e-14));
  EXPECT_TRUE(testing::approx(lengths.at(BoundaryLabel::Container), 2.0, 1e-14));
  EXPECT_TRUE(testing::approx(lengths.at(BoundaryLabel::Front), 1.0, 1e-14));
}

TEST(GmshMesh, OneSessionAtATime) {
  // Gmsh has one global state: a nested session is refused, and a session can
  // be opened again after the previous one closed.
  {
    mesh::GmshSession session;
    EXPECT_THROW(mesh::GmshSession second, InternalError);
  }
  EXPECT_NO_THROW(mesh::GmshSession again);
}

} // namespace
} // namespace formflow
