// SPDX-License-Identifier: MIT
// The coordinate plane of a boundary facet, from its nodes.
#include "formflow/mesh/facet_axis.hpp"

#include <limits>

namespace formflow::mesh {

template <int dim>
std::optional<int> facet_normal_axis(const Mesh<dim>& mesh, const BoundaryFacet& facet) {
  Point<dim> lowest = Point<dim>::Constant(std::numeric_limits<Real>::infinity());
  Point<dim> highest = -lowest;
  for (int local : mesh.face_nodes(facet.local_face)) {
    const Point<dim> node = mesh.nodes.col(mesh.cells(local, facet.cell));
    lowest = lowest.cwiseMin(node);
    highest = highest.cwiseMax(node);
  }
  const Point<dim> spread = highest - lowest;
  const Real extent = spread.maxCoeff();
  for (int axis = 0; axis < dim; ++axis)
    if (spread[axis] <= 1e-9 * extent) return axis;
  return std::nullopt;
}

template std::optional<int> facet_normal_axis<2>(const Mesh<2>&, const BoundaryFacet&);
template std::optional<int> facet_normal_axis<3>(const Mesh<3>&, const BoundaryFacet&);

} // namespace formflow::mesh
