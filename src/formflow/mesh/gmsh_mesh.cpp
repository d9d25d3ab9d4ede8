// SPDX-License-Identifier: MIT
// Conversion of a Gmsh model (quad-4/quad-9 or tri-3/tri-6 cells, physical curve groups) to
// Mesh<2>.
#include "formflow/mesh/gmsh_mesh.hpp"

#include "formflow/mesh/gmsh_model_reading.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>

namespace formflow::mesh {

namespace {

using Subject = MeshFileError::Subject;

// Gmsh numbers quadrilateral nodes corners first (counter-clockwise), then the
// mid-edge nodes (bottom, right, top, left), then the centre — the VTK 9/28
// order. Ours is lexicographic (fem/lagrange.hpp):
//
//   Gmsh quad-4   quad-9              ours Q1    Q2
//   3 --- 2       3 --- 6 --- 2       2 --- 3    6 --- 7 --- 8
//   |     |       |     |     |       |     |    |     |     |
//   |     |       7 --- 8 --- 5       |     |    3 --- 4 --- 5
//   0 --- 1       0 --- 4 --- 1       0 --- 1    0 --- 1 --- 2
//
// Gmsh node k goes to our local node lexicographic_of_gmsh_qN[k]. A unit test
// checks these tables against Gmsh's own reference coordinates.
constexpr std::array<int, 4> lexicographic_of_gmsh_q1 = {0, 1, 3, 2};
constexpr std::array<int, 9> lexicographic_of_gmsh_q2 = {0, 2, 8, 6, 1, 5, 7, 3, 4};

/// What the cells of `shape` are called, per order, in the messages.
struct PlaneCellWords {
  const char* cells;     ///< "quadrilaterals"
  const char* first;     ///< "4-node"
  const char* second;    ///< "9-node"
  const char* element_1; ///< mesh.element of the first order
  const char* element_2;
};

PlaneCellWords plane_cell_words(CellShape shape) {
  if (shape == CellShape::Simplex) return {"triangles", "3-node", "6-node", "P1b", "P2"};
  return {"quadrilaterals", "4-node", "9-node", "Q1", "Q2"};
}

/// The 2D elements as Gmsh node tags in our local order (lexicographic for
/// quadrilaterals; Gmsh's own, which is VTK's and ours, for triangles), one row of
/// `per_cell` tags per cell.
std::vector<std::size_t> read_plane_cells(int order, CellShape shape) {
  const bool simplex = shape == CellShape::Simplex;
  const PlaneCellWords words = plane_cell_words(shape);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  // A solid mesh's boundary faces are not a plane mesh: say what the file is.
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 3, -1);
  if (!types.empty())
    throw MeshFileError(
        Subject::File, "",
        fmt::format("the mesh has 3D elements (\"{}\"), and geometry.dimension = 2 "
                    "needs a plane mesh of {}",
                    gmsh_reading::element_type_name(types.front()), words.cells),
        "set geometry.dimension = 3 for a mesh of solid cells, or give a plane mesh");
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, -1);
  if (types.empty())
    throw MeshFileError(Subject::File, "", "the mesh has no 2D elements",
                        "mesh the surface (gmsh -2) and keep it in a physical surface group");
  const std::string q2_hint = "write complete second-order elements: gmsh -order 2 with "
                              "Mesh.SecondOrderIncomplete = 0";
  const int first_type = simplex ? gmsh_reading::triangle3 : gmsh_reading::quad4;
  const int second_type = simplex ? gmsh_reading::triangle6 : gmsh_reading::quad9;
  for (std::size_t k = 0; k < types.size(); ++k) {
    const int type = types[k];
    if (type == first_type || type == second_type) continue;
    const std::string found = fmt::format("{} elements of type \"{}\"", element_tags[k].size(),
                                          gmsh_reading::element_type_name(type));
    if (type == gmsh_reading::quad8 && !simplex)
      throw MeshFileError(Subject::Element, "",
                          found + ": 8-node serendipity quadrilaterals are not supported", q2_hint);
    const bool other_shape = type == (simplex ? gmsh_reading::quad4 : gmsh_reading::triangle3) ||
                             type == (simplex ? gmsh_reading::quad9 : gmsh_reading::triangle6);
    if (other_shape)
      throw MeshFileError(Subject::Cell, "",
                          fmt::format("{}: mesh.cell = \"{}\" needs {}", found,
                                      simplex ? "triangle" : "quadrilateral", words.cells),
                          simplex ? "set mesh.cell = \"quadrilateral\" for this mesh"
                                  : "set mesh.cell = \"triangle\" for this mesh, or recombine "
                                    "it into quadrilaterals (Mesh.RecombineAll = 1)");
    throw MeshFileError(Subject::Element, "",
                        fmt::format("{}: formflow needs {}", found, words.cells),
                        simplex ? "mesh the surface with 3- or 6-node triangles"
                                : "recombine the surface mesh into quadrilaterals "
                                  "(Mesh.RecombineAll = 1, Mesh.RecombinationAlgorithm = 3 for an "
                                  "all-quad mesh)");
  }
  if (types.size() > 1)
    throw MeshFileError(
        Subject::Element, "",
        fmt::format("the mesh mixes {} and {} {}", words.first, words.second, words.cells),
        "use one element order throughout");
  const int file_order = types.front() == first_type ? 1 : 2;
  if (file_order != order)
    throw MeshFileError(
        Subject::Element, "",
        fmt::format("mesh.element = \"{}\" needs {} {}; the mesh has {} ones",
                    order == 1 ? words.element_1 : words.element_2,
                    order == 1 ? words.first : words.second, words.cells,
                    file_order == 1 ? words.first : words.second),
        order == 1
            ? fmt::format("set mesh.element = \"{}\", or write a first-order mesh", words.element_2)
            : fmt::format("set mesh.element = \"{}\", or {}", words.element_1, q2_hint));
  const std::vector<std::size_t>& gmsh_nodes = node_tags.front();
  if (simplex) return gmsh_nodes; // tri-3/tri-6: vertices, then edges (0,1), (1,2), (2,0)
  const std::size_t per_cell = order == 1 ? 4 : 9;
  std::vector<std::size_t> cells(gmsh_nodes.size());
  for (std::size_t first = 0; first < gmsh_nodes.size(); first += per_cell)
    for (std::size_t k = 0; k < per_cell; ++k) {
      const int local = lexicographic_of_gmsh_node(order, static_cast<int>(k));
      cells[first + static_cast<std::size_t>(local)] = gmsh_nodes[first + k];
    }
  return cells;
}

/// Mirrors clockwise cells (negative corner area) so that every cell is
/// counter-clockwise: Gmsh orients elements by the surface normal, which is −z
/// for a surface whose curve loop runs clockwise. Quadrilaterals are mirrored in ξ;
/// triangles swap vertices 1 and 2 (and the midpoints of edges (0,1) and (2,0)).
/// Whether a cell is tangled is left to the Jacobian check of the caller.
void orient_counter_clockwise(Mesh<2>& mesh) {
  const int n = mesh.nodes_per_side();
  const std::vector<int> ring = mesh.is_simplex()
                                    ? std::vector<int>{0, 1, 2}
                                    : std::vector<int>{0, n - 1, n * n - 1, n * (n - 1)};
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Real twice_area = 0.0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point<2> a = mesh.nodes.col(mesh.cells(ring[k], cell));
      const Point<2> b = mesh.nodes.col(mesh.cells(ring[(k + 1) % ring.size()], cell));
      twice_area += a.x() * b.y() - b.x() * a.y();
    }
    if (twice_area >= 0) continue;
    if (mesh.is_simplex()) {
      std::swap(mesh.cells(1, cell), mesh.cells(2, cell));
      if (mesh.order == 2) std::swap(mesh.cells(3, cell), mesh.cells(5, cell));
      continue;
    }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n / 2; ++i)
        std::swap(mesh.cells(j * n + i, cell), mesh.cells(j * n + n - 1 - i, cell));
  }
}

} // namespace

int lexicographic_of_gmsh_node(int order, int gmsh_node) {
  return order == 1 ? lexicographic_of_gmsh_q1.at(static_cast<std::size_t>(gmsh_node))
                    : lexicographic_of_gmsh_q2.at(static_cast<std::size_t>(gmsh_node));
}

Mesh<2> mesh_from_gmsh_model(const GmshSession& session,
                             const std::vector<PhysicalBoundary>& boundaries, int order,
                             CellShape shape) {
  return session.call([&] {
    const std::vector<std::size_t> cell_tags = read_plane_cells(order, shape);
    Mesh<2> mesh;
    mesh.order = order;
    mesh.shape = shape;
    const Index per_cell = nodes_per_cell<2>(mesh.cell_type());
    mesh.cells.resize(per_cell, static_cast<Index>(cell_tags.size()) / per_cell);
    const auto index_of = gmsh_reading::number_nodes(cell_tags, mesh);
    orient_counter_clockwise(mesh);
    gmsh_reading::label_facets(boundaries, mesh, index_of);
    return mesh;
  });
}

Mesh<2> read_gmsh_mesh(const std::string& path, const std::vector<PhysicalBoundary>& boundaries,
                       int order, CellShape shape) {
  // Gmsh would run a file that is not a mesh as a script: it reads only a private
  // copy of bytes checked to be MSH (mesh/gmsh_model_reading.hpp).
  GmshSession session;
  gmsh_reading::open_checked_msh(session, path);
  return mesh_from_gmsh_model(session, boundaries, order, shape);
}

void write_gmsh_mesh(const GmshSession& session, const std::string& path, bool binary) {
  session.call([&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::write(path);
  });
}

} // namespace formflow::mesh
