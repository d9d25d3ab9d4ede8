// SPDX-License-Identifier: MIT
// What reading a Gmsh model into a Mesh<dim> does alike in the plane and in solids.
#include "formflow/mesh/gmsh_model_reading.hpp"

#include "formflow/mesh/msh_file.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <array>
#include <map>

namespace formflow::mesh::gmsh_reading {

namespace {

using Subject = MeshFileError::Subject;

/// A boundary facet by its corner nodes, sorted: the two ends of a plane cell's
/// side, the four corners of a solid cell's face.
template <int dim> using FacetKey = std::array<Index, dim == 2 ? 2 : 4>;

/// The words of the messages: what a boundary group and a facet are called.
template <int dim> struct Words {
  static constexpr const char* group = dim == 2 ? "curve" : "surface";
  static constexpr const char* facets = dim == 2 ? "facets" : "faces";
  static constexpr const char* domain = dim == 2 ? "surface" : "volume";
  static constexpr const char* cell = "cell";
};

template <int dim> FacetKey<dim> sorted(FacetKey<dim> corners) {
  std::sort(corners.begin(), corners.end());
  return corners;
}

/// The key of a triangle face: its corners with the least repeated, so that every solid face
/// has a key of four and a triangle's does not depend on the order its corners come in.
FacetKey<3> triangle_key(Index a, Index b, Index c) {
  return sorted<3>({a, b, c, std::min({a, b, c})});
}

/// The corners of local face `face` of `cell` (a triangle face of a tetrahedron: triangle_key).
template <int dim> FacetKey<dim> cell_facet_key(const Mesh<dim>& mesh, Index cell, int face) {
  const std::vector<int> local = mesh.face_nodes(face);
  const auto node = [&](std::size_t k) { return mesh.cells(local[k], cell); };
  if (mesh.is_simplex()) {
    const std::vector<int> corners = simplex_face_vertices<dim>(face);
    if constexpr (dim == 2)
      return sorted<dim>({mesh.cells(corners[0], cell), mesh.cells(corners[1], cell)});
    else
      return triangle_key(mesh.cells(corners[0], cell), mesh.cells(corners[1], cell),
                          mesh.cells(corners[2], cell));
  }
  const int n = mesh.nodes_per_side();
  if constexpr (dim == 2)
    return sorted<dim>({node(0), node(local.size() - 1)});
  else
    return sorted<dim>({node(0), node(static_cast<std::size_t>(n - 1)),
                        node(static_cast<std::size_t>(n * (n - 1))),
                        node(static_cast<std::size_t>(n * n - 1))});
}

/// The facet as the messages name it: a plane side by its ends, a solid face by its centre
/// (the mean of its distinct corners: a triangle's key repeats one).
template <int dim> std::string facet_text(const Mesh<dim>& mesh, const FacetKey<dim>& key) {
  if constexpr (dim == 2) {
    const Point<2> a = mesh.nodes.col(key[0]), b = mesh.nodes.col(key[1]);
    return fmt::format("the segment ({:.6g}, {:.6g})–({:.6g}, {:.6g})", a.x(), a.y(), b.x(), b.y());
  } else {
    Point<3> centre = Point<3>::Zero();
    std::vector<Index> corners(key.begin(), key.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    for (const Index node : corners) centre += mesh.nodes.col(node) / Real(corners.size());
    return fmt::format("the face with centre ({:.6g}, {:.6g}, {:.6g})", centre.x(), centre.y(),
                       centre.z());
  }
}

std::string parts_list() {
  std::string text;
  for (int k = 0; k < n_boundary_labels; ++k)
    text += (k ? ", " : "") + std::string(label_name(static_cast<BoundaryLabel>(k)));
  return text;
}

/// The faces used by one cell only, in cell order, still without labels.
template <int dim>
std::vector<BoundaryFacet> boundary_facets(const Mesh<dim>& mesh,
                                           std::map<FacetKey<dim>, std::size_t>& by_key) {
  std::map<FacetKey<dim>, std::pair<int, BoundaryFacet>> uses;
  std::vector<FacetKey<dim>> order;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int face = 0; face < faces_per_cell<dim>(mesh.cell_type()); ++face) {
      const FacetKey<dim> key = cell_facet_key(mesh, cell, face);
      auto [entry, inserted] =
          uses.try_emplace(key, 0, BoundaryFacet{cell, face, BoundaryLabel::Rear});
      if (inserted) order.push_back(key);
      ++entry->second.first;
    }
  std::vector<BoundaryFacet> facets;
  for (const FacetKey<dim>& key : order) {
    const auto& [count, facet] = uses.at(key);
    if (count != 1) continue;
    by_key[key] = facets.size();
    facets.push_back(facet);
  }
  return facets;
}

/// The corner nodes (as mesh indices) of every element of the physical group `tag`
/// of dimension dim − 1 (lines in the plane; quadrilaterals, or triangles for a mesh of
/// tetrahedra, in a solid).
template <int dim>
std::vector<FacetKey<dim>> group_facets(int tag,
                                        const std::unordered_map<std::size_t, Index>& index_of,
                                        const std::string& name, bool simplex) {
  using W = Words<dim>;
  const bool triangles = dim == 3 && simplex;
  const int first_order = dim == 2 ? line2 : triangles ? triangle3 : quad4;
  const int second_order = dim == 2 ? line3 : triangles ? triangle6 : quad9;
  const char* sides = dim == 2 ? "lines" : triangles ? "triangles" : "quadrilaterals";
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(dim - 1, tag, entities);
  std::vector<FacetKey<dim>> facets;
  for (const int entity : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, dim - 1, entity);
    for (std::size_t k = 0; k < types.size(); ++k) {
      if (types[k] != first_order && types[k] != second_order)
        throw MeshFileError(
            Subject::Group, name,
            fmt::format("physical {} \"{}\" has {} elements of type \"{}\": the sides of a {} "
                        "are {}",
                        W::group, name, element_tags[k].size(), element_type_name(types[k]),
                        W::cell, sides),
            fmt::format("mesh the boundary {}s with {}", W::group,
                        dim == 2 || triangles ? sides : "(recombined) quadrilaterals"));
      std::size_t per_element = 0;
      {
        std::string type_name;
        int element_dim = 0, order = 0, n_nodes = 0, n_primary = 0;
        std::vector<double> reference;
        gmsh::model::mesh::getElementProperties(types[k], type_name, element_dim, order, n_nodes,
                                                reference, n_primary);
        per_element = static_cast<std::size_t>(n_nodes);
      }
      // Gmsh lists an element's corners first, then its inner nodes.
      for (std::size_t first = 0; first < node_tags[k].size(); first += per_element) {
        FacetKey<dim> corners{};
        const std::size_t n_corners = triangles ? 3 : corners.size();
        for (std::size_t c = 0; c < n_corners; ++c) {
          const auto found = index_of.find(node_tags[k][first + c]);
          if (found == index_of.end())
            throw MeshFileError(
                Subject::Group, name,
                fmt::format("physical {} \"{}\" has an element whose nodes "
                            "belong to no {}",
                            W::group, name, W::cell),
                fmt::format("map only {}s on the boundary of the meshed {}", W::group, W::domain));
          corners[c] = found->second;
        }
        if constexpr (dim == 3)
          if (triangles) {
            facets.push_back(triangle_key(corners[0], corners[1], corners[2]));
            continue;
          }
        facets.push_back(sorted<dim>(corners));
      }
    }
  }
  return facets;
}

/// Physical groups of dimension `dim` by name (tag); the names of other dimensions'
/// groups with their dimension. Unnamed groups go by "#tag".
std::map<std::string, int> physical_groups(int dim, std::map<std::string, int>& other_dimensions) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::map<std::string, int> found;
  for (const auto& [group_dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(group_dim, tag, name);
    if (name.empty()) name = fmt::format("#{}", tag);
    if (group_dim == dim)
      found[name] = tag;
    else
      other_dimensions[name] = group_dim;
  }
  return found;
}

/// Every mapped name must be a group of the boundary's dimension.
void check_mapped_names(const std::map<std::string, BoundaryLabel>& mapped,
                        const std::map<std::string, int>& groups,
                        const std::map<std::string, int>& other_dimensions, int dim) {
  const char* group = dim == 2 ? "curve" : "surface";
  for (const auto& [name, label] : mapped) {
    if (groups.count(name)) continue;
    std::string present;
    for (const auto& [other, tag] : groups) present += (present.empty() ? "" : ", ") + other;
    const std::string message =
        other_dimensions.count(name)
            ? fmt::format("physical group \"{}\" is of dimension {}, not a {} (the boundary "
                          "parts of a {}D mesh are {}s)",
                          name, other_dimensions.at(name), group, dim, group)
            : fmt::format("no physical group named \"{}\" in the mesh", name);
    throw MeshFileError(Subject::Group, name, message,
                        present.empty()
                            ? fmt::format("the mesh has no named physical {}s", group)
                            : fmt::format("physical {}s in the mesh: {}", group, present));
  }
}

} // namespace

std::string element_type_name(int type) {
  std::string name;
  int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
  std::vector<double> coordinates;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, n_nodes, coordinates, n_primary);
  return name;
}

void open_checked_msh(const GmshSession& session, const std::string& path) {
  const PrivateMshCopy copy(read_msh_bytes(path));
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
}

template <int dim>
std::unordered_map<std::size_t, Index> number_nodes(const std::vector<std::size_t>& cell_tags,
                                                    Mesh<dim>& mesh) {
  std::vector<std::size_t> used = cell_tags;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, Index> index_of;
  for (std::size_t k = 0; k < used.size(); ++k) index_of[used[k]] = static_cast<Index>(k);

  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
  mesh.nodes.resize(dim, static_cast<Index>(used.size()));
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const auto found = index_of.find(tags[k]);
    if (found == index_of.end()) continue;
    for (int d = 0; d < dim; ++d)
      mesh.nodes(d, found->second) = coordinates[3 * k + static_cast<std::size_t>(d)];
  }
  const int per_cell = mesh.nodes_per_cell();
  for (std::size_t k = 0; k < cell_tags.size(); ++k)
    mesh.cells(static_cast<Index>(k) % per_cell, static_cast<Index>(k) / per_cell) =
        index_of.at(cell_tags[k]);
  return index_of;
}

template <int dim>
void label_facets(const std::vector<PhysicalBoundary>& boundaries, Mesh<dim>& mesh,
                  const std::unordered_map<std::size_t, Index>& index_of) {
  using W = Words<dim>;
  std::map<FacetKey<dim>, std::size_t> by_key;
  mesh.facets = boundary_facets(mesh, by_key);
  std::map<std::string, int> other_dimensions;
  const std::map<std::string, int> groups = physical_groups(dim - 1, other_dimensions);
  std::map<std::string, BoundaryLabel> mapped;
  for (const PhysicalBoundary& entry : boundaries) mapped[entry.name] = entry.label;
  if (boundaries.empty()) // no map: the groups named like a part are that part
    for (const auto& [name, tag] : groups)
      if (const auto label = label_from_name(name)) mapped[name] = *label;
  check_mapped_names(mapped, groups, other_dimensions, dim);

  std::vector<std::string> label_source(mesh.facets.size());
  std::vector<bool> labelled(mesh.facets.size(), false);
  for (const auto& [name, tag] : groups) {
    const std::vector<FacetKey<dim>> keys =
        group_facets<dim>(tag, index_of, name, mesh.is_simplex());
    const auto entry = mapped.find(name);
    if (entry == mapped.end()) {
      const auto on_boundary = std::find_if(keys.begin(), keys.end(),
                                            [&](const auto& key) { return by_key.count(key) > 0; });
      if (on_boundary == keys.end()) continue; // an inner group (e.g. for mesh grading)
      throw MeshFileError(Subject::Boundaries, name,
                          fmt::format("physical {} \"{}\" lies on the boundary (e.g. {}) but is "
                                      "not mapped to a boundary part",
                                      W::group, name, facet_text(mesh, *on_boundary)),
                          fmt::format("add `\"{}\" = PART` to [mesh.boundaries], PART one of {}",
                                      name, parts_list()));
    }
    for (const FacetKey<dim>& key : keys) {
      const auto facet = by_key.find(key);
      if (facet == by_key.end())
        throw MeshFileError(
            Subject::Group, name,
            fmt::format("physical {} \"{}\" has {} inside the mesh, not on its "
                        "boundary",
                        W::group, name, facet_text(mesh, key)),
            fmt::format("map only {}s on the boundary of the meshed {}", W::group, W::domain));
      BoundaryFacet& target = mesh.facets[facet->second];
      if (labelled[facet->second] && target.label != entry->second)
        throw MeshFileError(Subject::Group, name,
                            fmt::format("{} is in physical {} \"{}\" ({}) and in \"{}\" ({})",
                                        facet_text(mesh, key), W::group, name,
                                        label_name(entry->second), label_source[facet->second],
                                        label_name(target.label)),
                            fmt::format("put each boundary {} in one part only", W::group));
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
      fmt::format("{} boundary {} are in no mapped physical {}, e.g. {}", missing, W::facets,
                  W::group, facet_text(mesh, cell_facet_key(mesh, facet.cell, facet.local_face))),
      fmt::format("put every boundary {} in a named physical group of the .msh and map its name "
                  "in [mesh.boundaries]",
                  W::group));
}

template std::unordered_map<std::size_t, Index> number_nodes<2>(const std::vector<std::size_t>&,
                                                                Mesh<2>&);
template std::unordered_map<std::size_t, Index> number_nodes<3>(const std::vector<std::size_t>&,
                                                                Mesh<3>&);
template void label_facets<2>(const std::vector<PhysicalBoundary>&, Mesh<2>&,
                              const std::unordered_map<std::size_t, Index>&);
template void label_facets<3>(const std::vector<PhysicalBoundary>&, Mesh<3>&,
                              const std::unordered_map<std::size_t, Index>&);

} // namespace formflow::mesh::gmsh_reading
