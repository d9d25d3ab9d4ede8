// SPDX-License-Identifier: MIT
// Gmsh triangles as formflow meshes: the generated channel, the .msh round trip of tri-3
// and tri-6, clockwise triangles turned, and the shape a file has against mesh.cell.
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/die_face.hpp"
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/mesh/gmsh_mesh.hpp"
#include "gmsh/gmsh_test_mesh.hpp"
#include "support/approx.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using mesh::BoundaryLabel;
using mesh::CellShape;

/// The test's scratch directory (support/run_cli.hpp); `scratch / name` is a path in it.
class TriangleScratch {
public:
  std::string operator/(const std::string& name) const { return (directory_ / name).string(); }

private:
  testing::ScratchDirectory directory_{"formflow-gmsh-tri"};
};

/// Every cell's Jacobian is positive at the full rule's points and at the nodes.
bool all_cells_valid(const mesh::Mesh<2>& mesh) {
  fem::CellValues<2> at_gauss(mesh.cell_type(), fem::full_rule<2>(mesh.cell_type()));
  fem::CellValues<2> at_nodes(mesh.cell_type(), fem::node_points<2>(mesh.cell_type()));
  fem::CellValues<2>::Gradients coordinates(2, mesh.nodes_per_cell());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    if (!at_gauss.reinit(coordinates) || !at_nodes.reinit(coordinates)) return false;
  }
  return true;
}

/// Σ of the cells' areas (the full rule integrates 1 exactly).
Real total_area(const mesh::Mesh<2>& mesh) {
  fem::CellValues<2> values(mesh.cell_type(), fem::full_rule<2>(mesh.cell_type()));
  fem::CellValues<2>::Gradients coordinates(2, mesh.nodes_per_cell());
  Real area = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    values.reinit(coordinates);
    for (int q = 0; q < values.n_points(); ++q) area += values.JxW(q);
  }
  return area;
}

TEST(GmshTriangles, TheChannelIsTriangulatedWithEveryPartAndItsArea) {
  const mesh::ChannelGeometry geometry;
  // The benchmark channel: 10 × 10 container and 10 × 5 exit (square die, no land).
  const Real area = geometry.container_length * geometry.entry_half_height +
                    geometry.exit_length * geometry.exit_half_height;
  for (const int order : {1, 2}) {
    const mesh::Mesh<2> mesh = mesh::make_gmsh_channel_mesh(
        geometry, mesh::square_die_face(geometry), 1.0, order, CellShape::Simplex);
    ASSERT_TRUE(mesh.is_simplex());
    EXPECT_EQ(mesh.order, order);
    EXPECT_EQ(mesh.cells.rows(), order == 1 ? 3 : 6);
    EXPECT_TRUE(all_cells_valid(mesh));
    // Straight-sided cells: each area is exact; the sum of ~300 of them rounds by
    // ~300 ε ≈ 7e-14 relative.
    EXPECT_TRUE(testing::approx(total_area(mesh), area, 1e-12));
    std::map<BoundaryLabel, int> facets;
    for (const mesh::BoundaryFacet& facet : mesh.facets) ++facets[facet.label];
    for (const BoundaryLabel part :
         {BoundaryLabel::Rear, BoundaryLabel::Symmetry, BoundaryLabel::Front,
          BoundaryLabel::FreeExit, BoundaryLabel::Die, BoundaryLabel::Container})
      EXPECT_GT(facets[part], 0) << mesh::label_name(part);
  }
}

TEST(GmshTriangles, MshRoundTripOfTri3AndTri6GivesTheSameMesh) {
  const TriangleScratch scratch;
  for (const int order : {1, 2}) {
    mesh::Mesh<2> direct;
    {
      mesh::GmshSession session;
      const mesh::ChannelGeometry geometry;
      mesh::build_channel_model(session, geometry, mesh::square_die_face(geometry), 1.25, order, {},
                                CellShape::Simplex);
      direct = mesh::mesh_from_gmsh_model(session, {}, order, CellShape::Simplex);
      mesh::write_gmsh_mesh(session, scratch / "triangles.msh", true);
    }
    const mesh::Mesh<2> read =
        mesh::read_gmsh_mesh(scratch / "triangles.msh", {}, order, CellShape::Simplex);
    ASSERT_EQ(read.n_cells(), direct.n_cells());
    EXPECT_EQ(read.cells, direct.cells);
    EXPECT_EQ((read.nodes - direct.nodes).cwiseAbs().maxCoeff(), 0.0); // binary: exact
    ASSERT_EQ(read.facets.size(), direct.facets.size());
    for (std::size_t k = 0; k < read.facets.size(); ++k)
      EXPECT_EQ(read.facets[k].label, direct.facets[k].label);
  }
}

/// Two triangles of the unit square [0, 1]², listed clockwise, with its four sides named.
testing::TestMesh two_clockwise_triangles() {
  testing::TestMesh mesh;
  mesh.element_type = 2;
  mesh.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.elements = {{1, 3, 2}, {1, 4, 3}}; // clockwise: the normal is −z
  mesh.curves = {
      {"ram", {{{4, 1}}}}, {"axis", {{{1, 2}}}}, {"front", {{{2, 3}}}}, {"wall", {{{3, 4}}}}};
  return mesh;
}

const std::vector<mesh::PhysicalBoundary> square_parts = {{"ram", BoundaryLabel::Rear},
                                                          {"axis", BoundaryLabel::Symmetry},
                                                          {"front", BoundaryLabel::Front},
                                                          {"wall", BoundaryLabel::Container}};

TEST(GmshTriangles, ClockwiseTrianglesAreTurnedCounterClockwise) {
  const TriangleScratch scratch;
  testing::write_test_mesh(two_clockwise_triangles(), scratch / "clockwise.msh");
  const mesh::Mesh<2> mesh =
      mesh::read_gmsh_mesh(scratch / "clockwise.msh", square_parts, 1, CellShape::Simplex);
  ASSERT_EQ(mesh.n_cells(), 2);
  EXPECT_TRUE(all_cells_valid(mesh));
  EXPECT_TRUE(testing::approx(total_area(mesh), 1.0, 1e-14)); // two exact halves: a few ε
  EXPECT_EQ(mesh.facets.size(), 4u);
}

TEST(GmshTriangles, AFileOfTheOtherShapeBlamesMeshCell) {
  const TriangleScratch scratch;
  testing::write_test_mesh(two_clockwise_triangles(), scratch / "triangles.msh");
  try {
    mesh::read_gmsh_mesh(scratch / "triangles.msh", square_parts, 1, CellShape::Cube);
    ADD_FAILURE() << "triangles read as quadrilaterals";
  } catch (const mesh::MeshFileError& error) {
    EXPECT_EQ(error.subject, mesh::MeshFileError::Subject::Cell) << error.message;
    EXPECT_NE(error.hint.find("mesh.cell = \"triangle\""), std::string::npos) << error.hint;
  }
  testing::write_test_mesh(testing::two_squares(), scratch / "squares.msh");
  try {
    mesh::read_gmsh_mesh(scratch / "squares.msh", square_parts, 1, CellShape::Simplex);
    ADD_FAILURE() << "quadrilaterals read as triangles";
  } catch (const mesh::MeshFileError& error) {
    EXPECT_EQ(error.subject, mesh::MeshFileError::Subject::Cell) << error.message;
  }
  // The right shape of the wrong order blames the element.
  try {
    mesh::read_gmsh_mesh(scratch / "triangles.msh", square_parts, 2, CellShape::Simplex);
    ADD_FAILURE() << "tri-3 read as P2";
  } catch (const mesh::MeshFileError& error) {
    EXPECT_EQ(error.subject, mesh::MeshFileError::Subject::Element) << error.message;
    EXPECT_NE(error.message.find("6-node triangles"), std::string::npos) << error.message;
  }
}

} // namespace
} // namespace formflow
