// SPDX-License-Identifier: MIT
// Conversion of a Gmsh model (quad-4/quad-9 cells, physical curve groups) to Mesh<2>.
#include "formflow/mesh/gmsh_mesh.hpp"

#include "formflow/mesh/msh_file.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <map>
#include <unordered_map>

namespace formflow::mesh {

namespace {

using Subject = MeshFileError::Subject;

// Gmsh element type numbers (gmsh.h getElementProperties, .msh format docs).
constexpr int gmsh_line2 = 1, gmsh_line3 = 8, gmsh_quad4 = 3, gmsh_quad9 = 10, gmsh_quad8 = 16;

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

std::string element_type_name(int type) {
  std::string name;
  int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
  std::vector<double> coordinates;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, n_nodes, coordinates, n_primary);
  return name;
}

std::string parts_list() {
  std::string text;
  for (int k = 0; k < n_boundary_labels; ++k)
    text += (k ? ", " : "") + std::string(label_name(static_cast<BoundaryLabel>(k)));
  return text;
}

/// The 2D elements as Gmsh node tags in our lexicographic order, one row of
/// `per_cell` tags per cell.
std::vector<std::size_t> read_cells(int order) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  // A solid mesh's boundary quadrilaterals are not a plane mesh: say what the file is.
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 3, -1);
  if (!types.empty())
    throw MeshFileError(Subject::File, "",
                        fmt::format("the mesh has 3D elements (\"{}\"), and geometry.dimension = 2 "
                                    "needs a plane mesh of quadrilaterals",
                                    element_type_name(types.front())),
                        "set geometry.dimension = 3 for a mesh of hexahedra, or give a plane mesh");
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, -1);
  if (types.empty())
    throw MeshFileError(Subject::File, "", "the mesh has no 2D elements",
                        "mesh the surface (gmsh -2) and keep it in a physical surface group");
  const std::string q2_hint = "write complete second-order elements: gmsh -order 2 with "
                              "Mesh.SecondOrderIncomplete = 0";
  for (std::size_t k = 0; k < types.size(); ++k) {
    const int type = types[k];
    if (type == gmsh_quad4 || type == gmsh_quad9) continue;
    const std::string found =
        fmt::format("{} elements of type \"{}\"", element_tags[k].size(), element_type_name(type));
    if (type == gmsh_quad8)
      throw MeshFileError(Subject::Element, "",
                          found + ": 8-node serendipity quadrilaterals are not supported", q2_hint);
    throw MeshFileError(Subject::Element, "", found + ": formflow needs quadrilaterals",
                        "recombine the surface mesh into quadrilaterals (Mesh.RecombineAll = 1, "
                        "Mesh.RecombinationAlgorithm = 3 for an all-quad mesh)");
  }
  if (types.size() > 1)
    throw MeshFileError(Subject::Element, "", "the mesh mixes 4-node and 9-node quadrilaterals",
                        "use one element order throughout");
  const int file_order = types.front() == gmsh_quad4 ? 1 : 2;
  if (file_order != order)
    throw MeshFileError(
        Subject::Element, "",
        fmt::format("mesh.element = \"Q{}\" needs {}-node quadrilaterals; the mesh has {}-node "
                    "ones (Q{})",
                    order, order == 1 ? 4 : 9, file_order == 1 ? 4 : 9, file_order),
        order == 1 ? "set mesh.element = \"Q2\", or write a first-order mesh"
                   : "set mesh.element = \"Q1\", or " + q2_hint);
  const std::vector<std::size_t>& gmsh_nodes = node_tags.front();
  const std::size_t per_cell = order == 1 ? 4 : 9;
  std::vector<std::size_t> cells(gmsh_nodes.size());
  for (std::size_t first = 0; first < gmsh_nodes.size(); first += per_cell)
    for (std::size_t k = 0; k < per_cell; ++k) {
      const int local = lexicographic_of_gmsh_node(order, static_cast<int>(k));
      cells[first + static_cast<std::size_t>(local)] = gmsh_nodes[first + k];
    }
  return cells;
}

/// Nodes used by the cells, numbered in ascending Gmsh tag order; fills the
/// coordinates and the connectivity and returns the index of each Gmsh tag.
std::unordered_map<std::size_t, Index> number_nodes(const std::vector<std::size_t>& cell_tags,
                                                    Mesh<2>& mesh) {
  std::vector<std::size_t> used = cell_tags;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, Index> index_of;
  for (std::size_t k = 0; k < used.size(); ++k) index_of[used[k]] = static_cast<Index>(k);

  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
  mesh.nodes.resize(2, static_cast<Index>(used.size()));
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const auto found = index_of.find(tags[k]);
    if (found == index_of.end()) continue;
    mesh.nodes.col(found->second) = Point<2>(coordinates[3 * k], coordinates[3 * k + 1]);
  }
  const int per_cell = mesh.nodes_per_cell();
  for (std::size_t k = 0; k < cell_tags.size(); ++k)
    mesh.cells(static_cast<Index>(k) % per_cell, static_cast<Index>(k) / per_cell) =
        index_of.at(cell_tags[k]);
  return index_of;
}

/// Mirrors clockwise cells (negative corner area) in ξ so that every cell is
/// counter-clockwise: Gmsh orients elements by the surface normal, which is −z
/// for a surface whose curve loop runs clockwise. Whether a cell is tangled
/// is left to the Jacobian check of the caller.
void orient_counter_clockwise(Mesh<2>& mesh) {
  const int n = mesh.nodes_per_side();
  const std::array<int, 4> ring = {0, n - 1, n * n - 1, n * (n - 1)};
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Real twice_area = 0.0;
    for (int k = 0; k < 4; ++k) {
      const Point<2> a = mesh.nodes.col(mesh.cells(ring[k], cell));
      const Point<2> b = mesh.nodes.col(mesh.cells(ring[(k + 1) % 4], cell));
      twice_area += a.x() * b.y() - b.x() * a.y();
    }
    if (twice_area >= 0) continue;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n / 2; ++i)
        std::swap(mesh.cells(j * n + i, cell), mesh.cells(j * n + n - 1 - i, cell));
  }
}

using EdgeKey = std::pair<Index, Index>;
EdgeKey edge_key(Index a, Index b) {
  return a < b ? EdgeKey{a, b} : EdgeKey{b, a};
}

/// The faces used by one cell only, in cell order, still without labels.
std::vector<BoundaryFacet> boundary_faces(const Mesh<2>& mesh,
                                          std::map<EdgeKey, std::size_t>& by_edge) {
  std::map<EdgeKey, std::pair<int, BoundaryFacet>> uses;
  std::vector<EdgeKey> order;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int face = 0; face < 4; ++face) {
      const auto local = face_local_nodes<2>(mesh.nodes_per_side(), face);
      const EdgeKey key = edge_key(mesh.cells(local.front(), cell), mesh.cells(local.back(), cell));
      auto [entry, inserted] =
          uses.try_emplace(key, 0, BoundaryFacet{cell, face, BoundaryLabel::Rear});
      if (inserted) order.push_back(key);
      ++entry->second.first;
    }
  std::vector<BoundaryFacet> facets;
  for (const EdgeKey& key : order) {
    const auto& [count, facet] = uses.at(key);
    if (count != 1) continue;
    by_edge[key] = facets.size();
    facets.push_back(facet);
  }
  return facets;
}

std::string segment_text(const Mesh<2>& mesh, const EdgeKey& edge) {
  const Point<2> a = mesh.nodes.col(edge.first), b = mesh.nodes.col(edge.second);
  return fmt::format("({:.6g}, {:.6g})–({:.6g}, {:.6g})", a.x(), a.y(), b.x(), b.y());
}

/// The end nodes (as mesh indices) of every curve element of the physical curve group `tag`.
std::vector<EdgeKey> group_edges(int tag, const std::unordered_map<std::size_t, Index>& index_of,
                                 const std::string& name) {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(1, tag, entities);
  std::vector<EdgeKey> edges;
  for (const int entity : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, 1, entity);
    for (std::size_t k = 0; k < types.size(); ++k) {
      if (types[k] != gmsh_line2 && types[k] != gmsh_line3) continue;
      const std::size_t per_element = types[k] == gmsh_line2 ? 2 : 3;
      // Gmsh lists a curve element's two end nodes first, then its inner nodes.
      for (std::size_t first = 0; first < node_tags[k].size(); first += per_element) {
        const auto a = index_of.find(node_tags[k][first]);
        const auto b = index_of.find(node_tags[k][first + 1]);
        if (a == index_of.end() || b == index_of.end())
          throw MeshFileError(Subject::Group, name,
                              fmt::format("physical curve \"{}\" has an element whose nodes "
                                          "belong to no quadrilateral",
                                          name),
                              "map only curves on the boundary of the meshed surface");
        edges.push_back(edge_key(a->second, b->second));
      }
    }
  }
  return edges;
}

/// Physical curve groups by name: (tag, and whether it is a curve).
std::map<std::string, int> physical_curves(std::map<std::string, int>& other_dimensions) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::map<std::string, int> curves;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) name = fmt::format("#{}", tag); // unnamed groups: only their tag
    if (dim == 1)
      curves[name] = tag;
    else
      other_dimensions[name] = dim;
  }
  return curves;
}

void label_facets(const std::vector<PhysicalBoundary>& boundaries, Mesh<2>& mesh,
                  const std::unordered_map<std::size_t, Index>& index_of) {
  std::map<EdgeKey, std::size_t> by_edge;
  mesh.facets = boundary_faces(mesh, by_edge);
  std::map<std::string, int> other_dimensions;
  const std::map<std::string, int> curves = physical_curves(other_dimensions);
  std::map<std::string, BoundaryLabel> mapped;
  for (const PhysicalBoundary& entry : boundaries) mapped[entry.name] = entry.label;
  if (boundaries.empty()) // no map: the curves named like a part are that part
    for (const auto& [name, tag] : curves)
      if (const auto label = label_from_name(name)) mapped[name] = *label;

  for (const auto& [name, label] : mapped) {
    if (curves.count(name)) continue;
    std::string present;
    for (const auto& [curve, tag] : curves) present += (present.empty() ? "" : ", ") + curve;
    const std::string message =
        other_dimensions.count(name)
            ? fmt::format("physical group \"{}\" is of dimension {}, not a curve", name,
                          other_dimensions.at(name))
            : fmt::format("no physical group named \"{}\" in the mesh", name);
    throw MeshFileError(Subject::Group, name, message,
                        present.empty() ? "the mesh has no named physical curves"
                                        : "physical curves in the mesh: " + present);
  }

  std::vector<std::string> label_source(mesh.facets.size());
  std::vector<bool> labelled(mesh.facets.size(), false);
  for (const auto& [name, tag] : curves) {
    const std::vector<EdgeKey> edges = group_edges(tag, index_of, name);
    const auto entry = mapped.find(name);
    if (entry == mapped.end()) {
      const auto on_boundary = std::find_if(edges.begin(), edges.end(),
                                            [&](const EdgeKey& e) { return by_edge.count(e) > 0; });
      if (on_boundary == edges.end()) continue; // an inner curve (e.g. for mesh grading)
      throw MeshFileError(Subject::Boundaries, name,
                          fmt::format("physical curve \"{}\" lies on the boundary (e.g. {}) but "
                                      "is not mapped to a boundary part",
                                      name, segment_text(mesh, *on_boundary)),
                          fmt::format("add `\"{}\" = PART` to [mesh.boundaries], PART one of {}",
                                      name, parts_list()));
    }
    for (const EdgeKey& edge : edges) {
      const auto facet = by_edge.find(edge);
      if (facet == by_edge.end())
        throw MeshFileError(Subject::Group, name,
                            fmt::format("physical curve \"{}\" has the element {} inside the "
                                        "mesh, not on its boundary",
                                        name, segment_text(mesh, edge)),
                            "map only curves on the boundary of the meshed surface");
      BoundaryFacet& target = mesh.facets[facet->second];
      if (labelled[facet->second] && target.label != entry->second)
        throw MeshFileError(Subject::Group, name,
                            fmt::format("the boundary facet {} is in physical curve \"{}\" "
                                        "({}) and in \"{}\" ({})",
                                        segment_text(mesh, edge), name, label_name(entry->second),
                                        label_source[facet->second], label_name(target.label)),
                            "put each boundary curve in one part only");
      target.label = entry->second;
      labelled[facet->second] = true;
      label_source[facet->second] = name;
    }
  }

  const auto missing = std::count(labelled.begin(), labelled.end(), false);
  if (missing == 0) return;
  const std::size_t first = static_cast<std::size_t>(
      std::find(labelled.begin(), labelled.end(), false) - labelled.begin());
  const BoundaryFacet& facet = mesh.facets[first];
  const auto local = face_local_nodes<2>(mesh.nodes_per_side(), facet.local_face);
  const EdgeKey edge =
      edge_key(mesh.cells(local.front(), facet.cell), mesh.cells(local.back(), facet.cell));
  throw MeshFileError(Subject::Boundaries, "",
                      fmt::format("{} boundary facets are in no mapped physical curve, e.g. {}",
                                  missing, segment_text(mesh, edge)),
                      "put every boundary curve in a named physical group of the .msh and map "
                      "its name in [mesh.boundaries]");
}

} // namespace

int lexicographic_of_gmsh_node(int order, int gmsh_node) {
  return order == 1 ? lexicographic_of_gmsh_q1.at(static_cast<std::size_t>(gmsh_node))
                    : lexicographic_of_gmsh_q2.at(static_cast<std::size_t>(gmsh_node));
}

Mesh<2> mesh_from_gmsh_model(const GmshSession& session,
                             const std::vector<PhysicalBoundary>& boundaries, int order) {
  return session.call([&] {
    const std::vector<std::size_t> cell_tags = read_cells(order);
    Mesh<2> mesh;
    mesh.order = order;
    const Index per_cell = (order + 1) * (order + 1);
    mesh.cells.resize(per_cell, static_cast<Index>(cell_tags.size()) / per_cell);
    const auto index_of = number_nodes(cell_tags, mesh);
    orient_counter_clockwise(mesh);
    label_facets(boundaries, mesh, index_of);
    return mesh;
  });
}

Mesh<2> read_gmsh_mesh(const std::string& path, const std::vector<PhysicalBoundary>& boundaries,
                       int order) {
  // Gmsh would run a file that is not a mesh as a script: check first, then
  // let Gmsh read only a private copy of the checked bytes (mesh/msh_file.hpp).
  const PrivateMshCopy copy(read_msh_bytes(path));
  GmshSession session;
  try {
    session.call([&] { gmsh::open(copy.path()); });
  } catch (const GmshFailure& failure) {
    std::string message = failure.what();
    for (auto at = message.find(copy.path()); at != std::string::npos;
         at = message.find(copy.path(), at + path.size()))
      message.replace(at, copy.path().size(), path); // name the user's file, not the copy
    throw MeshFileError(Subject::File, "", fmt::format("Gmsh cannot read {}: {}", path, message),
                        "give a Gmsh .msh file (format 4.1 or 2.2, ASCII or binary)");
  }
  return mesh_from_gmsh_model(session, boundaries, order);
}

void write_gmsh_mesh(const GmshSession& session, const std::string& path, bool binary) {
  session.call([&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::write(path);
  });
}

} // namespace formflow::mesh
