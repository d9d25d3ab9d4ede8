// SPDX-License-Identifier: MIT
// Conversion of a Gmsh model (hexa-8/hexa-27 cells, physical surface groups) to Mesh<3>.
#include "formflow/mesh/gmsh_solid_mesh.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/msh_file.hpp"

#include <Eigen/LU>
#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

namespace formflow::mesh {

namespace {

using Subject = MeshFileError::Subject;

// Gmsh element type numbers (.msh format documentation).
constexpr int gmsh_quad4 = 3, gmsh_quad9 = 10, gmsh_hexa8 = 5, gmsh_hexa27 = 12, gmsh_hexa20 = 17;

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

/// Gmsh node k of a hexahedron of `order` → our lexicographic node, from the
/// reference coordinates Gmsh gives (the cube [−1, 1]³): no table to get wrong.
std::vector<int> hex_node_map(int order) {
  std::string name;
  int dim = 0, element_order = 0, n_nodes = 0, n_primary = 0;
  std::vector<double> reference;
  gmsh::model::mesh::getElementProperties(order == 1 ? gmsh_hexa8 : gmsh_hexa27, name, dim,
                                          element_order, n_nodes, reference, n_primary);
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
std::vector<std::size_t> read_cells(int order) {
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
    if (type == gmsh_hexa8 || type == gmsh_hexa27) continue;
    const std::string found =
        fmt::format("{} elements of type \"{}\"", element_tags[k].size(), element_type_name(type));
    if (type == gmsh_hexa20)
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
  const int file_order = types.front() == gmsh_hexa8 ? 1 : 2;
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

/// Nodes used by the cells, numbered in ascending Gmsh tag order; fills the
/// coordinates and the connectivity.
std::unordered_map<std::size_t, Index> number_nodes(const std::vector<std::size_t>& cell_tags,
                                                    Mesh<3>& mesh) {
  std::vector<std::size_t> used = cell_tags;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, Index> index_of;
  for (std::size_t k = 0; k < used.size(); ++k) index_of[used[k]] = static_cast<Index>(k);

  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
  mesh.nodes.resize(3, static_cast<Index>(used.size()));
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const auto found = index_of.find(tags[k]);
    if (found == index_of.end()) continue;
    mesh.nodes.col(found->second) =
        Point<3>(coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]);
  }
  const int per_cell = mesh.nodes_per_cell();
  for (std::size_t k = 0; k < cell_tags.size(); ++k)
    mesh.cells(static_cast<Index>(k) % per_cell, static_cast<Index>(k) / per_cell) =
        index_of.at(cell_tags[k]);
  return index_of;
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

/// A face by its four corner nodes, sorted.
using FaceKey = std::array<Index, 4>;
FaceKey face_key(std::array<Index, 4> corners) {
  std::sort(corners.begin(), corners.end());
  return corners;
}

/// The corners of local face `face` of `cell`.
FaceKey cell_face_key(const Mesh<3>& mesh, Index cell, int face) {
  const int n = mesh.nodes_per_side();
  const std::vector<int> local = face_local_nodes<3>(n, face);
  return face_key({mesh.cells(local[0], cell), mesh.cells(local[n - 1], cell),
                   mesh.cells(local[n * (n - 1)], cell), mesh.cells(local[n * n - 1], cell)});
}

/// The faces used by one cell only, in cell order, still without labels.
std::vector<BoundaryFacet> boundary_faces(const Mesh<3>& mesh,
                                          std::map<FaceKey, std::size_t>& by_face) {
  std::map<FaceKey, std::pair<int, BoundaryFacet>> uses;
  std::vector<FaceKey> order;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int face = 0; face < 6; ++face) {
      const FaceKey key = cell_face_key(mesh, cell, face);
      auto [entry, inserted] =
          uses.try_emplace(key, 0, BoundaryFacet{cell, face, BoundaryLabel::Rear});
      if (inserted) order.push_back(key);
      ++entry->second.first;
    }
  std::vector<BoundaryFacet> facets;
  for (const FaceKey& key : order) {
    const auto& [count, facet] = uses.at(key);
    if (count != 1) continue;
    by_face[key] = facets.size();
    facets.push_back(facet);
  }
  return facets;
}

std::string face_text(const Mesh<3>& mesh, const FaceKey& face) {
  Point<3> centre = Point<3>::Zero();
  for (const Index node : face) centre += mesh.nodes.col(node) / 4.0;
  return fmt::format("the face with centre ({:.6g}, {:.6g}, {:.6g})", centre.x(), centre.y(),
                     centre.z());
}

/// The corner nodes (as mesh indices) of every face element of the physical surface group `tag`.
std::vector<FaceKey> group_faces(int tag, const std::unordered_map<std::size_t, Index>& index_of,
                                 const std::string& name) {
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(2, tag, entities);
  std::vector<FaceKey> faces;
  for (const int entity : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, entity);
    for (std::size_t k = 0; k < types.size(); ++k) {
      if (types[k] != gmsh_quad4 && types[k] != gmsh_quad9)
        throw MeshFileError(Subject::Group, name,
                            fmt::format("physical surface \"{}\" has {} elements of type \"{}\": "
                                        "the faces of hexahedra are quadrilaterals",
                                        name, element_tags[k].size(), element_type_name(types[k])),
                            "mesh the boundary surfaces with (recombined) quadrilaterals");
      const std::size_t per_element = types[k] == gmsh_quad4 ? 4 : 9;
      // Gmsh lists a quadrilateral's four corners first, then its inner nodes.
      for (std::size_t first = 0; first < node_tags[k].size(); first += per_element) {
        FaceKey corners{};
        for (std::size_t c = 0; c < 4; ++c) {
          const auto found = index_of.find(node_tags[k][first + c]);
          if (found == index_of.end())
            throw MeshFileError(Subject::Group, name,
                                fmt::format("physical surface \"{}\" has an element whose nodes "
                                            "belong to no hexahedron",
                                            name),
                                "map only surfaces on the boundary of the meshed volume");
          corners[c] = found->second;
        }
        faces.push_back(face_key(corners));
      }
    }
  }
  return faces;
}

/// Physical surface groups by name (tag); the names of other dimensions' groups
/// with their dimension.
std::map<std::string, int> physical_surfaces(std::map<std::string, int>& other_dimensions) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::map<std::string, int> surfaces;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) name = fmt::format("#{}", tag); // unnamed groups: only their tag
    if (dim == 2)
      surfaces[name] = tag;
    else
      other_dimensions[name] = dim;
  }
  return surfaces;
}

void label_facets(const std::vector<PhysicalBoundary>& boundaries, Mesh<3>& mesh,
                  const std::unordered_map<std::size_t, Index>& index_of) {
  std::map<FaceKey, std::size_t> by_face;
  mesh.facets = boundary_faces(mesh, by_face);
  std::map<std::string, int> other_dimensions;
  const std::map<std::string, int> surfaces = physical_surfaces(other_dimensions);
  std::map<std::string, BoundaryLabel> mapped;
  for (const PhysicalBoundary& entry : boundaries) mapped[entry.name] = entry.label;
  if (boundaries.empty()) // no map: the surfaces named like a part are that part
    for (const auto& [name, tag] : surfaces)
      if (const auto label = label_from_name(name)) mapped[name] = *label;

  for (const auto& [name, label] : mapped) {
    if (surfaces.count(name)) continue;
    std::string present;
    for (const auto& [surface, tag] : surfaces) present += (present.empty() ? "" : ", ") + surface;
    const std::string message =
        other_dimensions.count(name)
            ? fmt::format("physical group \"{}\" is of dimension {}, not a surface (a solid "
                          "mesh's boundary parts are surfaces)",
                          name, other_dimensions.at(name))
            : fmt::format("no physical group named \"{}\" in the mesh", name);
    throw MeshFileError(Subject::Group, name, message,
                        present.empty() ? "the mesh has no named physical surfaces"
                                        : "physical surfaces in the mesh: " + present);
  }

  std::vector<std::string> label_source(mesh.facets.size());
  std::vector<bool> labelled(mesh.facets.size(), false);
  for (const auto& [name, tag] : surfaces) {
    const std::vector<FaceKey> faces = group_faces(tag, index_of, name);
    const auto entry = mapped.find(name);
    if (entry == mapped.end()) {
      const auto on_boundary = std::find_if(faces.begin(), faces.end(),
                                            [&](const FaceKey& f) { return by_face.count(f) > 0; });
      if (on_boundary == faces.end()) continue; // an inner surface
      throw MeshFileError(Subject::Boundaries, name,
                          fmt::format("physical surface \"{}\" lies on the boundary (e.g. {}) but "
                                      "is not mapped to a boundary part",
                                      name, face_text(mesh, *on_boundary)),
                          fmt::format("add `\"{}\" = PART` to [mesh.boundaries], PART one of {}",
                                      name, parts_list()));
    }
    for (const FaceKey& face : faces) {
      const auto facet = by_face.find(face);
      if (facet == by_face.end())
        throw MeshFileError(Subject::Group, name,
                            fmt::format("physical surface \"{}\" has {} inside the mesh, not on "
                                        "its boundary",
                                        name, face_text(mesh, face)),
                            "map only surfaces on the boundary of the meshed volume");
      BoundaryFacet& target = mesh.facets[facet->second];
      if (labelled[facet->second] && target.label != entry->second)
        throw MeshFileError(Subject::Group, name,
                            fmt::format("{} is in physical surface \"{}\" ({}) and in \"{}\" ({})",
                                        face_text(mesh, face), name, label_name(entry->second),
                                        label_source[facet->second], label_name(target.label)),
                            "put each boundary face in one part only");
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
  throw MeshFileError(
      Subject::Boundaries, "",
      fmt::format("{} boundary faces are in no mapped physical surface, e.g. {}", missing,
                  face_text(mesh, cell_face_key(mesh, facet.cell, facet.local_face))),
      "put every boundary surface in a named physical group of the .msh and map "
      "its name in [mesh.boundaries]");
}

} // namespace

int lexicographic_of_gmsh_hex_node(int order, int gmsh_node) {
  return hex_node_map(order).at(static_cast<std::size_t>(gmsh_node));
}

Mesh<3> solid_mesh_from_gmsh_model(const GmshSession& session,
                                   const std::vector<PhysicalBoundary>& boundaries, int order) {
  return session.call([&] {
    const std::vector<std::size_t> cell_tags = read_cells(order);
    Mesh<3> mesh;
    mesh.order = order;
    const Index per_cell = (order + 1) * (order + 1) * (order + 1);
    mesh.cells.resize(per_cell, static_cast<Index>(cell_tags.size()) / per_cell);
    const auto index_of = number_nodes(cell_tags, mesh);
    orient_right_handed(mesh);
    label_facets(boundaries, mesh, index_of);
    return mesh;
  });
}

Mesh<3> read_gmsh_solid_mesh(const std::string& path,
                             const std::vector<PhysicalBoundary>& boundaries, int order) {
  // As read_gmsh_mesh: Gmsh sees only a private copy of bytes checked to be a mesh.
  const PrivateMshCopy copy(read_msh_bytes(path));
  GmshSession session;
  try {
    session.call([&] { gmsh::open(copy.path()); });
  } catch (const GmshFailure& failure) {
    std::string message = failure.what();
    for (auto at = message.find(copy.path()); at != std::string::npos;
         at = message.find(copy.path(), at + path.size()))
      message.replace(at, copy.path().size(), path);
    throw MeshFileError(Subject::File, "", fmt::format("Gmsh cannot read {}: {}", path, message),
                        "give a Gmsh .msh file (format 4.1 or 2.2, ASCII or binary)");
  }
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
    gmsh::model::mesh::addElementsByType(volume, order == 1 ? gmsh_hexa8 : gmsh_hexa27,
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
      gmsh::model::mesh::addElementsByType(surface, order == 1 ? gmsh_quad4 : gmsh_quad9, face_tags,
                                           face_nodes);
      gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}),
                                   std::string(label_name(label)));
    }
  });
}

} // namespace formflow::mesh
