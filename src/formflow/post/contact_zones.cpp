// SPDX-License-Identifier: MIT
// Stick and slip lengths of the contact parts (in a distributed run: over the rank's own
// faces, summed over the ranks).
#include "formflow/post/post_process.hpp"

#include <array>

namespace formflow::post {

template <int dim>
void contact_zones(const assembly::FormingProblem<dim>& problem,
                   const std::vector<assembly::ContactPoint<dim>>& contact, ContactZones& container,
                   ContactZones& die) {
  container = {};
  die = {};
  const auto& discretisation = problem.discretisation();
  for (const auto& point : contact) {
    // A distributed run: the faces of the rank's own cells here, the sums over the ranks
    // below (each Γ3 face belongs to the one cell it bounds).
    const mesh::BoundaryFacet& facet = discretisation.mesh().facets[point.facet];
    if (!discretisation.assembles(facet.cell)) continue;
    ContactZones& zones = facet.label == mesh::BoundaryLabel::Die ? die : container;
    // Lengths along the profile: in axisymmetry the quadrature weight carries
    // the radius (integrals are per radian), which a length must not.
    Real length = point.weight;
    if constexpr (dim == 2)
      if (discretisation.axisymmetric()) length /= point.position[1];
    zones.length += length;
    if (point.sticking) zones.stick_length += length;
  }
  if (const auto& distribution = discretisation.distribution(); distribution.distributed()) {
    std::array<Real, 4> sums{container.length, container.stick_length, die.length,
                             die.stick_length};
    distribution.sum_over_ranks(sums);
    container.length = sums[0], container.stick_length = sums[1];
    die.length = sums[2], die.stick_length = sums[3];
  }
}

template void contact_zones<2>(const assembly::FormingProblem<2>&,
                               const std::vector<assembly::ContactPoint<2>>&, ContactZones&,
                               ContactZones&);
template void contact_zones<3>(const assembly::FormingProblem<3>&,
                               const std::vector<assembly::ContactPoint<3>>&, ContactZones&,
                               ContactZones&);

} // namespace formflow::post
