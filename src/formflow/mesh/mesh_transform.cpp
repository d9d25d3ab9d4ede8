// SPDX-License-Identifier: MIT
// Translation and mirroring of a mesh.
#include "formflow/mesh/mesh_transform.hpp"

#include "formflow/core/error.hpp"

namespace formflow::mesh {

template <int dim> Mesh<dim> translated(const Mesh<dim>& mesh, const Point<dim>& shift) {
  Mesh<dim> moved = mesh;
  moved.nodes.colwise() += shift;
  return moved;
}

template <int dim> Mesh<dim> mirrored(const Mesh<dim>& mesh, int axis) {
  FF_ASSERT(axis >= 0 && axis < dim, "mirror axis out of range");
  Mesh<dim> image = mesh;
  image.nodes.row(axis) *= -1.0;
  const int n_side = mesh.nodes_per_side();
  int stride = 1;
  for (int d = 0; d < axis; ++d) stride *= n_side;
  // Local node with lattice index k along `axis` takes the place of n_side − 1 − k.
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int local = 0; local < mesh.nodes_per_cell(); ++local) {
      const int k = (local / stride) % n_side;
      image.cells(local + (n_side - 1 - 2 * k) * stride, cell) = mesh.cells(local, cell);
    }
  for (BoundaryFacet& facet : image.facets)
    if (facet.local_face / 2 == axis) facet.local_face ^= 1;
  return image;
}

template Mesh<2> translated<2>(const Mesh<2>&, const Point<2>&);
template Mesh<3> translated<3>(const Mesh<3>&, const Point<3>&);
template Mesh<2> mirrored<2>(const Mesh<2>&, int);
template Mesh<3> mirrored<3>(const Mesh<3>&, int);

} // namespace formflow::mesh
