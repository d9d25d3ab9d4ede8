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
        problem.mesh().facets[point.facet].label == mesh::BoundaryLabel::Die ? die : container;
    zones.length += point.weight;
    if (point.sticking)
      zones.stick_length += point.weight;
  }
}

template void contact_zones<2>(const assembly::FormingProblem<2>&,
                               const std::vector<assembly::ContactPoint<2>>&, ContactZones&,
                               ContactZones&);
template void contact_zones<3>(const assembly::FormingProblem<3>&,
                               const std::vector<assembly::ContactPoint<3>>&, ContactZones&,
                               ContactZones&);

} // namespace formflow::post
