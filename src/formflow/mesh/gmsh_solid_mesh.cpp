// SPDX-License-Identifier: MIT
// Conversion of a Gmsh model (hexa-8/hexa-27 or tetra-4/tetra-10 cells, physical surface groups)
// to Mesh<3>.
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

/// Gmsh's reference coordinates of the nodes of element type `type` (x, y, z per node).
std::vector<double> gmsh_reference_nodes(int type, int& n_nodes) {
  std::string name;
  int dim = 0, element_order = 0, n_primary = 0;
  std::vector<double> reference;
  gmsh::model::mesh::getElementProperties(type, name, dim, element_order, n_nodes, reference,
                                          n_primary);
  return reference;
}

/// Gmsh node k of a hexahedron of `order` → our lexicographic node, from the
/// reference coordinates Gmsh gives (the cube [−1, 1]³): no table to get wrong.
std::vector<int> hex_node_map(int order) {
  int n_nodes = 0;
  const std::vector<double> reference =
      gmsh_reference_nodes(order == 1 ? gmsh_reading::hexa8 : gmsh_reading::hexa27, n_nodes);
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

/// What the cells of `shape` are called, per order, in the messages.
struct SolidCellWords {
  const char* cells;     ///< "hexahedra"
  const char* first;     ///< "8-node"
  const char* second;    ///< "27-node"
  const char* element_1; ///< mesh.element of the first order
  const char* element_2;
  int first_type, second_type;
};

SolidCellWords solid_cell_words(CellShape shape) {
  if (shape == CellShape::Simplex)
    return {"tetrahedra",         "4-node", "10-node", "P1b", "P2", gmsh_reading::tetra4,
            gmsh_reading::tetra10};
  return {"hexahedra", "8-node", "27-node", "Q1", "Q2", gmsh_reading::hexa8, gmsh_reading::hexa27};
}

/// Gmsh node k of a tetrahedron of `order` → our local node (mesh/cell_type.hpp), from the
/// reference coordinates Gmsh gives (the unit simplex): a vertex, or the midpoint of the
/// edge of the two vertices it lies between. (Gmsh's tetra-10 lists the edges (0,1),
/// (1,2), (2,0), (3,0), (3,2), (3,1); ours, VTK's, end in (1,3), (2,3).)
std::vector<int> tetra_node_map(int order) {
  int n_nodes = 0;
  const std::vector<double> reference =
      gmsh_reference_nodes(order == 1 ? gmsh_reading::tetra4 : gmsh_reading::tetra10, n_nodes);
  const auto vertex = [](int v) {
    return v == 0 ? Point<3>(Point<3>::Zero()) : Point<3>(Point<3>::Unit(v - 1));
  };
  std::vector<int> map(static_cast<std::size_t>(n_nodes), -1);
  for (int k = 0; k < n_nodes; ++k) {
    const Point<3> xi(reference[3 * static_cast<std::size_t>(k)],
                      reference[3 * static_cast<std::size_t>(k) + 1],
                      reference[3 * static_cast<std::size_t>(k) + 2]);
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        if ((xi - 0.5 * (vertex(a) + vertex(b))).norm() < 1e-9)
          map[static_cast<std::size_t>(k)] = a == b ? a : simplex_edge_midpoint<3>(a, b);
    FF_ASSERT(map[static_cast<std::size_t>(k)] >= 0,
              "Gmsh tetrahedron reference nodes are not its vertices and edge midpoints");
  }
  return map;
}

/// The 3D elements as Gmsh node tags in our local order (lexicographic for hexahedra,
/// mesh/cell_type.hpp's for tetrahedra), one row of nodes_per_cell tags per cell.
std::vector<std::size_t> read_solid_cells(int order, CellShape shape) {
  const bool simplex = shape == CellShape::Simplex;
  const SolidCellWords words = solid_cell_words(shape);
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
                        fmt::format("the mesh has no 3D elements, and geometry.dimension = 3 "
                                    "needs {}",
                                    words.cells),
                        fmt::format("mesh the volume (gmsh -3) into {} and keep it in a physical "
                                    "volume group, or set geometry.dimension = 2 for a plane mesh",
                                    words.cells));
  const std::string q2_hint = "write complete second-order elements: gmsh -order 2 with "
                              "Mesh.SecondOrderIncomplete = 0";
  for (std::size_t k = 0; k < types.size(); ++k) {
    const int type = types[k];
    if (type == words.first_type || type == words.second_type) continue;
    const std::string found = fmt::format("{} elements of type \"{}\"", element_tags[k].size(),
                                          gmsh_reading::element_type_name(type));
    if (type == gmsh_reading::hexa20 && !simplex)
      throw MeshFileError(Subject::Element, "",
                          found + ": 20-node serendipity hexahedra are not supported; formflow "
                                  "needs 8-node (Q1) or 27-node (Q2) hexahedra",
                          q2_hint);
    const bool other_shape = simplex
                                 ? (type == gmsh_reading::hexa8 || type == gmsh_reading::hexa27)
                                 : (type == gmsh_reading::tetra4 || type == gmsh_reading::tetra10);
    if (other_shape)
      throw MeshFileError(Subject::Cell, "",
                          fmt::format("{}: mesh.cell = \"{}\" needs {}", found,
                                      simplex ? "tetrahedron" : "hexahedron", words.cells),
                          simplex ? "set mesh.cell = \"hexahedron\" for this mesh"
                                  : "set mesh.cell = \"tetrahedron\" for this mesh");
    throw MeshFileError(
        Subject::Element, "",
        fmt::format("{}: formflow needs {} ({} for {}, {} for {})", found, words.cells, words.first,
                    words.element_1, words.second, words.element_2),
        simplex ? "mesh the volume with tetrahedra only (no prisms or pyramids)"
                : "mesh the volume with hexahedra only: a transfinite or extruded volume "
                  "with Recombine (Mesh.RecombineAll = 1, Mesh.Recombine3DAll = 1)");
  }
  if (types.size() > 1)
    throw MeshFileError(
        Subject::Element, "",
        fmt::format("the mesh mixes {} and {} {}", words.first, words.second, words.cells),
        "use one element order throughout");
  const int file_order = types.front() == words.first_type ? 1 : 2;
  if (file_order != order)
    throw MeshFileError(
        Subject::Element, "",
        fmt::format("mesh.element = \"{}\" needs {} {}; the mesh has {} ones ({})",
                    order == 1 ? words.element_1 : words.element_2,
                    order == 1 ? words.first : words.second, words.cells,
                    file_order == 1 ? words.first : words.second,
                    file_order == 1 ? words.element_1 : words.element_2),
        order == 1
            ? fmt::format("set mesh.element = \"{}\", or write a first-order mesh", words.element_2)
            : fmt::format("set mesh.element = \"{}\", or {}", words.element_1, q2_hint));
  const std::vector<std::size_t>& gmsh_nodes = node_tags.front();
  const std::vector<int> map = simplex ? tetra_node_map(order) : hex_node_map(order);
  const std::size_t per_cell = map.size();
  std::vector<std::size_t> cells(gmsh_nodes.size());
  for (std::size_t first = 0; first < gmsh_nodes.size(); first += per_cell)
    for (std::size_t k = 0; k < per_cell; ++k)
      cells[first + static_cast<std::size_t>(map[k])] = gmsh_nodes[first + k];
  return cells;
}

/// Swaps vertices 1 and 2 of left-handed tetrahedra (and the midpoints that follow them:
/// (0,1) ↔ (2,0), (1,3) ↔ (2,3)). Whether a cell is tangled is left to the caller.
void orient_tetrahedra(Mesh<3>& mesh) {
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Eigen::Matrix3d edges;
    for (int k = 0; k < 3; ++k)
      edges.col(k) = mesh.nodes.col(mesh.cells(k + 1, cell)) - mesh.nodes.col(mesh.cells(0, cell));
    if (edges.determinant() >= 0) continue;
    std::swap(mesh.cells(1, cell), mesh.cells(2, cell));
    if (mesh.order == 2) {
      std::swap(mesh.cells(4, cell), mesh.cells(6, cell));
      std::swap(mesh.cells(8, cell), mesh.cells(9, cell));
    }
  }
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
                                   const std::vector<PhysicalBoundary>& boundaries, int order,
                                   CellShape shape) {
  return session.call([&] {
    const std::vector<std::size_t> cell_tags = read_solid_cells(order, shape);
    Mesh<3> mesh;
    mesh.order = order;
    mesh.shape = shape;
    const Index per_cell = nodes_per_cell<3>(mesh.cell_type());
    mesh.cells.resize(per_cell, static_cast<Index>(cell_tags.size()) / per_cell);
    const auto index_of = gmsh_reading::number_nodes(cell_tags, mesh);
    if (shape == CellShape::Simplex)
      orient_tetrahedra(mesh);
    else
      orient_right_handed(mesh);
    gmsh_reading::label_facets(boundaries, mesh, index_of);
    return mesh;
  });
}

Mesh<3> read_gmsh_solid_mesh(const std::string& path,
                             const std::vector<PhysicalBoundary>& boundaries, int order,
                             CellShape shape) {
  // As read_gmsh_mesh: Gmsh sees only a private copy of bytes checked to be a mesh.
  GmshSession session;
  gmsh_reading::open_checked_msh(session, path);
  return solid_mesh_from_gmsh_model(session, boundaries, order, shape);
}

void add_solid_mesh_to_gmsh_model(const GmshSession& session, const Mesh<3>& mesh) {
  FF_ASSERT(!mesh.bubbles, "a .msh has no bubble nodes: write the mesh before they are added");
  session.call([&] {
    const int order = mesh.order;
    const bool simplex = mesh.is_simplex();
    const std::vector<int> map = simplex ? tetra_node_map(order) : hex_node_map(order);
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
    const int cell_type = simplex ? (order == 1 ? gmsh_reading::tetra4 : gmsh_reading::tetra10)
                                  : (order == 1 ? gmsh_reading::hexa8 : gmsh_reading::hexa27);
    gmsh::model::mesh::addElementsByType(volume, cell_type, element_tags, element_nodes);
    gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {volume}), "domain");

    const int n = mesh.nodes_per_side();
    const int face_type = simplex ? (order == 1 ? gmsh_reading::triangle3 : gmsh_reading::triangle6)
                                  : (order == 1 ? gmsh_reading::quad4 : gmsh_reading::quad9);
    for (int k = 0; k < n_boundary_labels; ++k) {
      const auto label = static_cast<BoundaryLabel>(k);
      std::vector<std::size_t> face_tags, face_nodes;
      for (const BoundaryFacet& facet : mesh.facets) {
        if (facet.label != label) continue;
        face_tags.push_back(next_element++);
        const std::vector<int> local = mesh.face_nodes(facet.local_face);
        if (simplex) { // a tetrahedron's face nodes are in Gmsh's triangle order already
          for (const int a : local)
            face_nodes.push_back(static_cast<std::size_t>(mesh.cells(a, facet.cell)) + 1);
          continue;
        }
        for (int g = 0; g < n * n; ++g) // Gmsh's quadrilateral order from our lexicographic one
          face_nodes.push_back(
              static_cast<std::size_t>(
                  mesh.cells(local[static_cast<std::size_t>(lexicographic_of_gmsh_node(order, g))],
                             facet.cell)) +
              1);
      }
      if (face_tags.empty()) continue;
      const int surface = gmsh::model::addDiscreteEntity(2);
      gmsh::model::mesh::addElementsByType(surface, face_type, face_tags, face_nodes);
      gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}),
                                   std::string(label_name(label)));
    }
  });
}

} // namespace formflow::mesh
