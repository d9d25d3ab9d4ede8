// SPDX-License-Identifier: MIT
// Conversion of a Gmsh model (hexa-8/hexa-27 cells, physical surface groups) to Mesh<3>.
#include "formflow/mesh/gmsh_solid_mesh.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/gmsh_model_reading.hpp"

#include <Eigen/LU>
#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace formflow::mesh {

namespace {

using Subject = MeshFileError::Subject;

/// Gmsh node k of a hexahedron of `order` → our lexicographic node, from the
/// reference coordinates Gmsh gives (the cube [−1, 1]³): no table to get wrong.
std::vector<int> hex_node_map(int order) {
  std::string name;
  int dim = 0, element_order = 0, n_nodes = 0, n_primary = 0;
  std::vector<double> reference;
  gmsh::model::mesh::getElementProperties(order == 1 ? gmsh_reading::hexa8 : gmsh_reading::hexa27,
                                          name, dim, element_order, n_nodes, reference, n_primary);
  const int n = order + 1;
  std::vector<int> map(static_cast<std::size_t>(n_nodes));
  std::vector<bool> taken(static_cast<std::size_t>(n * n * n), false);
  for (int k = 0; k < n_nodes; ++k) {
    int local = 0;
    for (int d = 2; d >= 0; --d) {
      const double xi = reference[3 * static_cast<std::size_t>(k) + static_cast<std::size_t>(d)];
      local = local * n + static_cast<int>(std::lround((xi + 1.0) / 2.0 * order));
    }
    FF_ASSERT(local >= 0 && local < n * n * n && !taken[static_cast<std::size_t>(local)],
              "Gmsh hexahedron reference nodes are not a lattice");
    taken[static_cast<std::size_t>(local)] = true;
    map[static_cast<std::size_t>(k)] = local;
  }
  return map;
}

/// The 3D elements as Gmsh node tags in our lexicographic order, one row of
/// (order + 1)³ tags per cell.
std::vector<std::size_t> read_solid_cells(int order) {
  std::vector<int> entity_types;
  std::vector<std::vector<std::size_t>> entity_elements, entity_nodes;
  gmsh::model::mesh::getElements(entity_types, entity_elements, entity_nodes, 3, -1);
  // One entry per element type, whatever the number of volumes that hold them.
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  for (std::size_t k = 0; k < entity_types.size(); ++k) {
    const auto at = std::find(types.begin(), types.end(), entity_types[k]);
    const std::size_t index = static_cast<std::size_t>(at - types.begin());
    if (at == types.end()) {
      types.push_back(entity_types[k]);
      element_tags.emplace_back();
      node_tags.emplace_back();
    }
    element_tags[index].insert(element_tags[index].end(), entity_elements[k].begin(),
                               entity_elements[k].end());
    node_tags[index].insert(node_tags[index].end(), entity_nodes[k].begin(), entity_nodes[k].end());
  }
  if (types.empty())
    throw MeshFileError(Subject::File, "",
                        "the mesh has no 3D elements, and geometry.dimension = 3 needs hexahedra",
                        "mesh the volume (gmsh -3) into hexahedra and keep it in a physical "
                        "volume group, or set geometry.dimension = 2 for a plane mesh");
  const std::string q2_hint = "write complete second-order hexahedra: gmsh -order 2 with "
                              "Mesh.SecondOrderIncomplete = 0";
  for (std::size_t k = 0; k < types.size(); ++k) {
    const int type = types[k];
    if (type == gmsh_reading::hexa8 || type == gmsh_reading::hexa27) continue;
    const std::string found = fmt::format("{} elements of type \"{}\"", element_tags[k].size(),
                                          gmsh_reading::element_type_name(type));
    if (type == gmsh_reading::hexa20)
      throw MeshFileError(Subject::Element, "",
                          found + ": 20-node serendipity hexahedra are not supported; formflow "
                                  "needs 8-node (Q1) or 27-node (Q2) hexahedra",
                          q2_hint);
    throw MeshFileError(Subject::Element, "",
                        found + ": formflow needs hexahedra (8-node for Q1, 27-node for Q2)",
                        "mesh the volume with hexahedra only: a transfinite or extruded volume "
                        "with Recombine (Mesh.RecombineAll = 1, Mesh.Recombine3DAll = 1)");
  }
  if (types.size() > 1)
    throw MeshFileError(Subject::Element, "", "the mesh mixes 8-node and 27-node hexahedra",
                        "use one element order throughout");
  const int file_order = types.front() == gmsh_reading::hexa8 ? 1 : 2;
  if (file_order != order)
    throw MeshFileError(
        Subject::Element, "",
        fmt::format("mesh.element = \"Q{}\" needs {}-node hexahedra; the mesh has {}-node "
                    "ones (Q{})",
                    order, order == 1 ? 8 : 27, file_order == 1 ? 8 : 27, file_order),
        order == 1 ? "set mesh.element = \"Q2\", or write a first-order mesh"
                   : "set mesh.element = \"Q1\", or " + q2_hint);
  const std::vector<int> map = hex_node_map(order);
  const std::vector<std::size_t>& gmsh_nodes = node_tags.front();
  const std::size_t per_cell = map.size();
  std::vector<std::size_t> cells(gmsh_nodes.size());
  for (std::size_t first = 0; first < gmsh_nodes.size(); first += per_cell)
    for (std::size_t k = 0; k < per_cell; ++k)
      cells[first + static_cast<std::size_t>(map[k])] = gmsh_nodes[first + k];
  return cells;
}

/// Mirrors left-handed cells in ξ (a .msh writer may number a hexahedron's
/// bottom face clockwise seen from inside): the sign of det J at the centre of
/// the trilinear map of the corners decides. Whether a cell is tangled is left
/// to the Jacobian check of the caller.
void orient_right_handed(Mesh<3>& mesh) {
  const int n = mesh.nodes_per_side();
  const auto corner = [&](Index cell, int i, int j, int k) -> Point<3> {
    return mesh.nodes.col(mesh.cells((k * n + j) * n + i, cell));
  };
  const int e = n - 1;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
    for (int a = 0; a <= e; a += e)
      for (int b = 0; b <= e; b += e) {
        jacobian.col(0) += corner(cell, e, a, b) - corner(cell, 0, a, b);
        jacobian.col(1) += corner(cell, a, e, b) - corner(cell, a, 0, b);
        jacobian.col(2) += corner(cell, a, b, e) - corner(cell, a, b, 0);
      }
    if (jacobian.determinant() >= 0) continue;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n / 2; ++i)
          std::swap(mesh.cells((k * n + j) * n + i, cell),
                    mesh.cells((k * n + j) * n + n - 1 - i, cell));
  }
}

} // namespace

int lexicographic_of_gmsh_hex_node(int order, int gmsh_node) {
  return hex_node_map(order).at(static_cast<std::size_t>(gmsh_node));
}

Mesh<3> solid_mesh_from_gmsh_model(const GmshSession& session,
                                   const std::vector<PhysicalBoundary>& boundaries, int order) {
  return session.call([&] {
    const std::vector<std::size_t> cell_tags = read_solid_cells(order);
    Mesh<3> mesh;
    mesh.order = order;
    const Index per_cell = (order + 1) * (order + 1) * (order + 1);
    mesh.cells.resize(per_cell, static_cast<Index>(cell_tags.size()) / per_cell);
    const auto index_of = gmsh_reading::number_nodes(cell_tags, mesh);
    orient_right_handed(mesh);
    gmsh_reading::label_facets(boundaries, mesh, index_of);
    return mesh;
  });
}

Mesh<3> read_gmsh_solid_mesh(const std::string& path,
                             const std::vector<PhysicalBoundary>& boundaries, int order) {
  // As read_gmsh_mesh: Gmsh sees only a private copy of bytes checked to be a mesh.
  GmshSession session;
  gmsh_reading::open_checked_msh(session, path);
  return solid_mesh_from_gmsh_model(session, boundaries, order);
}

void add_solid_mesh_to_gmsh_model(const GmshSession& session, const Mesh<3>& mesh) {
  session.call([&] {
    const int order = mesh.order;
    const std::vector<int> map = hex_node_map(order);
    const int volume = gmsh::model::addDiscreteEntity(3);
    std::vector<std::size_t> tags;
    std::vector<double> coordinates;
    for (Index node = 0; node < mesh.n_nodes(); ++node) {
      tags.push_back(static_cast<std::size_t>(node) + 1);
      for (int d = 0; d < 3; ++d) coordinates.push_back(mesh.nodes(d, node));
    }
    gmsh::model::mesh::addNodes(3, volume, tags, coordinates);
    std::vector<std::size_t> element_tags, element_nodes;
    std::size_t next_element = 1;
    for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
      element_tags.push_back(next_element++);
      for (const int local : map)
        element_nodes.push_back(static_cast<std::size_t>(mesh.cells(local, cell)) + 1);
    }
    gmsh::model::mesh::addElementsByType(volume,
                                         order == 1 ? gmsh_reading::hexa8 : gmsh_reading::hexa27,
                                         element_tags, element_nodes);
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {volume}), "domain");

    const int n = mesh.nodes_per_side();
    for (int k = 0; k < n_boundary_labels; ++k) {
      const auto label = static_cast<BoundaryLabel>(k);
      std::vector<std::size_t> face_tags, face_nodes;
      for (const BoundaryFacet& facet : mesh.facets) {
        if (facet.label != label) continue;
        const std::vector<int> local = face_local_nodes<3>(n, facet.local_face);
        face_tags.push_back(next_element++);
        for (int g = 0; g < n * n; ++g) // Gmsh's quadrilateral order from our lexicographic one
          face_nodes.push_back(
              static_cast<std::size_t>(
                  mesh.cells(local[static_cast<std::size_t>(lexicographic_of_gmsh_node(order, g))],
                             facet.cell)) +
              1);
      }
      if (face_tags.empty()) continue;
      const int surface = gmsh::model::addDiscreteEntity(2);
      gmsh::model::mesh::addElementsByType(
          surface, order == 1 ? gmsh_reading::quad4 : gmsh_reading::quad9, face_tags, face_nodes);
      gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}),
                                   std::string(label_name(label)));
    }
  });
}

} // namespace formflow::mesh
