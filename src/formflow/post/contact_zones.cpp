// SPDX-License-Identifier: MIT
// Stick and slip lengths of the contact parts.
#include "formflow/post/post_process.hpp"

namespace formflow::post {

template <int dim>
void contact_zones(const assembly::FormingProblem<dim>& problem,
                   const std::vector<assembly::ContactPoint<dim>>& contact, ContactZones& container,
                   ContactZones& die) {
  container = {};
  die = {};
  for (const auto& point : contact) {
    ContactZones& zones =
        problem.discretisation().mesh().facets[point.facet].label == mesh::BoundaryLabel::Die
            ? die
            : container;
    // Lengths along the profile: in axisymmetry the quadrature weight carries
    // the radius (integrals are per radian), which a length must not.
    Real length = point.weight;
    if constexpr (dim == 2)
      if (problem.discretisation().axisymmetric()) length /= point.position[1];
    zones.length += length;
    if (point.sticking) zones.stick_length += length;
  }
}

template void contact_zones<2>(const assembly::FormingProblem<2>&,
                               const std::vector<assembly::ContactPoint<2>>&, ContactZones&,
                               ContactZones&);
template void contact_zones<3>(const assembly::FormingProblem<3>&,
                               const std::vector<assembly::ContactPoint<3>>&, ContactZones&,
                               ContactZones&);

} // namespace formflow::post
