// SPDX-License-Identifier: MIT
// A Gmsh background field from sizes at the nodes of another mesh.
#include "formflow/mesh/gmsh_sized_channel.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/mesh/gmsh_mesh.hpp"

#include <gmsh.h>

#include <array>

namespace formflow::mesh {

Mesh<2> make_sized_gmsh_channel_mesh(const ChannelGeometry& geometry,
                                     const std::vector<Point<2>>& die_face,
                                     const Mesh<2>& background, const VectorX& node_sizes,
                                     int order) {
  FF_ASSERT(node_sizes.size() == background.n_nodes(), "one size per background node");
  FF_ASSERT(node_sizes.allFinite() && node_sizes.minCoeff() > 0, "positive sizes");
  const Real largest = node_sizes.maxCoeff(), smallest = node_sizes.minCoeff();
  const auto field = [&] {
    // The background's cells as quadrangles of a list-based view ("SQ": the four
    // corners' x, then y, then z, then the four values), corners counter-clockwise.
    const int n = background.nodes_per_side();
    const std::array<int, 4> corners = {0, n - 1, n * n - 1, n * (n - 1)};
    std::vector<double> data;
    data.reserve(static_cast<std::size_t>(background.n_cells()) * 16);
    for (Index cell = 0; cell < background.n_cells(); ++cell) {
      for (int axis = 0; axis < 2; ++axis)
        for (int corner : corners)
          data.push_back(background.nodes(axis, background.cells(corner, cell)));
      for (int k = 0; k < 4; ++k) data.push_back(0.0);
      for (int corner : corners) data.push_back(node_sizes[background.cells(corner, cell)]);
    }
    const int view = gmsh::view::add("target size");
    gmsh::view::addListData(view, "SQ", static_cast<int>(background.n_cells()), data);
    const int tag = gmsh::model::mesh::field::add("PostView");
    gmsh::model::mesh::field::setNumber(tag, "ViewTag", view);
    gmsh::model::mesh::field::setAsBackgroundMesh(tag);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", largest);
    gmsh::option::setNumber("Mesh.MeshSizeMin", smallest);
  };
  GmshSession session;
  build_channel_model(session, geometry, die_face, largest, order, field);
  try {
    return mesh_from_gmsh_model(session, {}, order);
  } catch (const MeshFileError& error) {
    throw InternalError("Gmsh adapted channel mesh: " + error.message);
  }
}

} // namespace formflow::mesh
