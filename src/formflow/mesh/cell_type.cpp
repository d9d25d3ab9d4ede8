// SPDX-License-Identifier: MIT
// Node counts and face node lists of cube and simplex cells.
#include "formflow/mesh/cell_type.hpp"

#include "formflow/mesh/mesh.hpp"

#include <utility>

namespace formflow::mesh {

template <int dim> int simplex_edge_midpoint(int a, int b) {
  if (a > b) std::swap(a, b);
  if constexpr (dim == 2) {
    if (a == 0 && b == 1) return 3;
    if (a == 1 && b == 2) return 4;
    return 5; // (0, 2)
  } else {
    if (b == 3) return 7 + a; // (0,3) 7, (1,3) 8, (2,3) 9
    if (a == 0 && b == 1) return 4;
    if (a == 1 && b == 2) return 5;
    return 6; // (0, 2)
  }
}

template <int dim> int vertices_per_cell(const CellType& type) {
  return type.is_simplex() ? dim + 1 : (1 << dim);
}

template <int dim> int faces_per_cell(const CellType& type) {
  return type.is_simplex() ? dim + 1 : 2 * dim;
}

template <int dim> int nodes_per_cell(const CellType& type) {
  if (!type.is_simplex()) {
    int n = 1;
    for (int d = 0; d < dim; ++d) n *= type.order + 1;
    return n;
  }
  const int vertices = dim + 1;
  const int edges = dim == 2 ? 3 : 6;
  int n = vertices + (type.order == 2 ? edges : 0);
  if (type.bubbles) n += 1 + (type.order == 2 && dim == 3 ? 4 : 0);
  return n;
}

template <int dim> int nodes_per_face(const CellType& type) {
  return static_cast<int>(face_local_nodes<dim>(type, 0).size());
}

template <int dim> std::vector<int> simplex_face_vertices(int local_face) {
  if constexpr (dim == 2) {
    return {local_face, (local_face + 1) % 3};
  } else {
    // Face k is opposite vertex k; each order makes (v1 − v0) × (v2 − v0) point outwards.
    static const int faces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    return {faces[local_face][0], faces[local_face][1], faces[local_face][2]};
  }
}

template <int dim> std::vector<int> face_local_nodes(const CellType& type, int local_face) {
  if (!type.is_simplex()) return face_local_nodes<dim>(type.order + 1, local_face);
  const std::vector<int> vertices = simplex_face_vertices<dim>(local_face);
  if constexpr (dim == 2) {
    // Along the edge, as the 1D Gauss–Lobatto points: first vertex, midpoint, second.
    if (type.order == 1) return vertices;
    return {vertices[0], simplex_edge_midpoint<2>(vertices[0], vertices[1]), vertices[1]};
  } else {
    std::vector<int> nodes = vertices;
    if (type.order == 2) {
      for (int e = 0; e < 3; ++e)
        nodes.push_back(simplex_edge_midpoint<3>(vertices[e], vertices[(e + 1) % 3]));
      if (type.bubbles) nodes.push_back(10 + local_face); // the face's centroid node
    }
    return nodes;
  }
}

std::string_view cell_shape_name(CellShape shape, int dim) {
  if (shape == CellShape::Simplex) return dim == 2 ? "triangle" : "tetrahedron";
  return dim == 2 ? "quadrilateral" : "hexahedron";
}

template int simplex_edge_midpoint<2>(int, int);
template int simplex_edge_midpoint<3>(int, int);
template int vertices_per_cell<2>(const CellType&);
template int vertices_per_cell<3>(const CellType&);
template int faces_per_cell<2>(const CellType&);
template int faces_per_cell<3>(const CellType&);
template int nodes_per_cell<2>(const CellType&);
template int nodes_per_cell<3>(const CellType&);
template int nodes_per_face<2>(const CellType&);
template int nodes_per_face<3>(const CellType&);
template std::vector<int> simplex_face_vertices<2>(int);
template std::vector<int> simplex_face_vertices<3>(int);
template std::vector<int> face_local_nodes<2>(const CellType&, int);
template std::vector<int> face_local_nodes<3>(const CellType&, int);

} // namespace formflow::mesh
