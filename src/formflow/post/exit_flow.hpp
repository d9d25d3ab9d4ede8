// SPDX-License-Identifier: MIT
// The exit section's axial velocities and the balance of the flux through exit and entry.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/post/results.hpp"

namespace formflow::post {

/// The flow of `u` through the "front" facets (the exit) and the "rear" ones (the
/// entry), measured with the face rule of the problem (r-weighted in axisymmetry). The
/// axial velocity is u_x, the extrusion direction of every generated channel; its
/// min and max are taken at the exit facets' nodes, its mean is the flux-weighted
/// ∫ u_x dA / ∫ dA. `present` is false when the mesh has no exit or no entry facet.
template <int dim>
ExitFlow exit_flow(const assembly::FormingProblem<dim>& problem, const VectorX& u);

} // namespace formflow::post
