// SPDX-License-Identifier: MIT
// Cutting the symmetry planes out of a solid mesh.
#include "formflow/io/plot/solid_section.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/facet_axis.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace formflow::io::plot {

namespace {

/// Signed area of a plane cell's corner polygon (lexicographic lattice order; a triangle's
/// vertices are its first three nodes).
Real corner_area(const mesh::Mesh<2>& mesh, const std::vector<Index>& cell, int n_side) {
  const auto node = [&](std::size_t k) { return Point<2>(mesh.nodes.col(cell[k])); };
  const auto at = [&](int a, int b) { return node(static_cast<std::size_t>(b * n_side + a)); };
  const std::vector<Point<2>> ring =
      mesh.is_simplex() ? std::vector<Point<2>>{node(0), node(1), node(2)}
                        : std::vector<Point<2>>{at(0, 0), at(n_side - 1, 0),
                                                at(n_side - 1, n_side - 1), at(0, n_side - 1)};
  Real twice = 0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Point<2>& a = ring[k];
    const Point<2>& b = ring[(k + 1) % ring.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

/// Turns a clockwise section cell: a lattice transposed, a triangle's vertices 1 and 2 swapped
/// (with the midpoints of edges (0,1) and (2,0)).
void turn_counter_clockwise(const mesh::Mesh<2>& plane, std::vector<Index>& cell, int n_side) {
  if (plane.is_simplex()) {
    std::swap(cell[1], cell[2]);
    if (plane.order == 2) std::swap(cell[3], cell[5]);
    return;
  }
  std::vector<Index> transposed(cell.size());
  for (int b = 0; b < n_side; ++b)
    for (int a = 0; a < n_side; ++a) transposed[a * n_side + b] = cell[b * n_side + a];
  cell = std::move(transposed);
}

std::vector<Index> sorted(std::vector<Index> nodes) {
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

} // namespace

PlaneSection symmetry_section(const mesh::Mesh<3>& solid, int normal_axis) {
  FF_ASSERT(normal_axis == 1 || normal_axis == 2, "a symmetry plane y = 0 or z = 0");
  return boundary_section(solid, mesh::BoundaryLabel::Symmetry, normal_axis, 0.0);
}

PlaneSection boundary_section(const mesh::Mesh<3>& solid, mesh::BoundaryLabel part, int normal_axis,
                              Real plane_at) {
  PlaneSection section;
  section.in_plane = normal_axis == 0   ? std::array<int, 2>{1, 2}
                     : normal_axis == 1 ? std::array<int, 2>{0, 2}
                                        : std::array<int, 2>{0, 1};
  mesh::Mesh<2>& plane = section.mesh;
  plane.order = solid.order;
  // A tetrahedron's face is a triangle of its order; a P2+ face also has its centroid node.
  plane.shape = solid.shape;
  plane.bubbles = solid.is_simplex() && solid.bubbles && solid.order == 2;
  const int n_side = solid.nodes_per_side();
  const int plane_edges = mesh::faces_per_cell<2>(plane.cell_type());
  const Real extent = (solid.nodes.rowwise().maxCoeff() - solid.nodes.rowwise().minCoeff()).norm();

  std::unordered_map<Index, Index> plane_node;
  std::vector<std::vector<Index>> cells; // plane node numbers
  std::vector<Index> solid_cell;
  for (const mesh::BoundaryFacet& facet : solid.facets) {
    if (facet.label != part || mesh::facet_normal_axis(solid, facet) != normal_axis) continue;
    const std::vector<int> locals = solid.face_nodes(facet.local_face);
    if (std::abs(solid.nodes(normal_axis, solid.cells(locals.front(), facet.cell)) - plane_at) >
        1e-12 * extent)
      continue; // e.g. the slab's far z face: a symmetry plane, but not the one asked
    std::vector<Index> cell;
    for (int local : locals) {
      const Index node = solid.cells(local, facet.cell);
      const auto [entry, inserted] =
          plane_node.try_emplace(node, static_cast<Index>(section.solid_node.size()));
      if (inserted) section.solid_node.push_back(node);
      cell.push_back(entry->second);
    }
    cells.push_back(std::move(cell));
    solid_cell.push_back(facet.cell);
  }
  plane.nodes.resize(2, static_cast<Index>(section.solid_node.size()));
  for (std::size_t n = 0; n < section.solid_node.size(); ++n)
    plane.nodes.col(n) << solid.nodes(section.in_plane[0], section.solid_node[n]),
        solid.nodes(section.in_plane[1], section.solid_node[n]);
  // Face nodes come in the solid cell's order, which may run clockwise in (u, v).
  for (std::vector<Index>& cell : cells)
    if (corner_area(plane, cell, n_side) < 0) turn_counter_clockwise(plane, cell, n_side);
  const int per_cell = mesh::nodes_per_cell<2>(plane.cell_type());
  plane.cells.resize(per_cell, static_cast<Index>(cells.size()));
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (int a = 0; a < per_cell; ++a) plane.cells(a, c) = cells[c][a];

  // Boundary edges (on one section cell only), labelled by the solid facet of the
  // same solid cell that holds the whole edge (other than the section's own face).
  std::map<std::vector<Index>, int> edge_count;
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (int edge = 0; edge < plane_edges; ++edge) {
      std::vector<Index> nodes;
      for (int local : plane.face_nodes(edge)) nodes.push_back(cells[c][local]);
      ++edge_count[sorted(nodes)];
    }
  std::unordered_multimap<Index, const mesh::BoundaryFacet*> facets_of;
  for (const mesh::BoundaryFacet& facet : solid.facets) facets_of.emplace(facet.cell, &facet);
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (int edge = 0; edge < plane_edges; ++edge) {
      std::vector<Index> solid_nodes, nodes;
      for (int local : plane.face_nodes(edge)) {
        nodes.push_back(cells[c][local]);
        solid_nodes.push_back(section.solid_node[cells[c][local]]);
      }
      if (edge_count[sorted(nodes)] != 1) continue;
      std::optional<mesh::BoundaryLabel> label;
      const auto [first, last] = facets_of.equal_range(solid_cell[c]);
      for (auto it = first; it != last && !label; ++it) {
        const mesh::BoundaryFacet& facet = *it->second;
        std::vector<Index> face;
        for (int local : solid.face_nodes(facet.local_face))
          face.push_back(solid.cells(local, facet.cell));
        std::sort(face.begin(), face.end());
        const bool holds = std::all_of(solid_nodes.begin(), solid_nodes.end(), [&](Index node) {
          return std::binary_search(face.begin(), face.end(), node);
        });
        const bool own_face =
            facet.label == part && mesh::facet_normal_axis(solid, facet) == normal_axis;
        if (holds && !own_face) label = facet.label;
      }
      plane.facets.push_back(
          {static_cast<Index>(c), edge, label.value_or(mesh::BoundaryLabel::FreeExit)});
    }
  return section;
}

post::Results section_results(const post::Results& results, const PlaneSection& section) {
  post::Results out = results;
  const Index n = static_cast<Index>(section.solid_node.size());
  const auto restrict = [&](const VectorX& field) {
    if (field.size() != results.n_nodes) return VectorX();
    VectorX part(n);
    for (Index k = 0; k < n; ++k) part[k] = field[section.solid_node[k]];
    return part;
  };
  const post::Fields& fields = results.fields;
  out.fields.equivalent_strain_rate = restrict(fields.equivalent_strain_rate);
  out.fields.hydrostatic_stress = restrict(fields.hydrostatic_stress);
  out.fields.contact_pressure = restrict(fields.contact_pressure);
  out.fields.friction_stress = restrict(fields.friction_stress);
  out.fields.cell_equivalent_strain_rate.resize(0);
  out.fields.cell_hydrostatic_stress.resize(0);
  out.fields.velocity.resize(2 * n);
  if (fields.velocity.size() == 3 * results.n_nodes)
    for (Index k = 0; k < n; ++k)
      for (int c = 0; c < 2; ++c)
        out.fields.velocity[2 * k + c] =
            fields.velocity[3 * section.solid_node[k] + section.in_plane[c]];
  else
    out.fields.velocity.resize(0);
  out.n_nodes = n;
  out.n_cells = section.mesh.n_cells();
  return out;
}

} // namespace formflow::io::plot
