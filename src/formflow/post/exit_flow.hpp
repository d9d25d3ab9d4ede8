// SPDX-License-Identifier: MIT
// The exit section's axial velocities and the balance of the flux through exit and entry.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/profile_die.hpp"
#include "formflow/post/results.hpp"

namespace formflow::post {

/// The flow of `u` through the "front" facets (the exit) and the "rear" ones (the
/// entry), measured with the face rule of the problem (r-weighted in axisymmetry). The
/// axial velocity is u_x, the extrusion direction of every generated channel; its
/// min and max are taken at the exit facets' nodes, its mean is the flux-weighted
/// ∫ u_x dA / ∫ dA. `present` is false when the mesh has no exit or no entry facet.
template <int dim>
ExitFlow exit_flow(const assembly::FormingProblem<dim>& problem, const VectorX& u);

/// The exit section of a profile through a flat die split by nearest outline edge: each
/// face quadrature point of the "front" facets, with its mirror images under the die's
/// symmetry (a half or quarter model stands for the whole section), goes to the edge
/// nearest to it; per edge the mean of u_x over its part. An edge no point is nearest to
/// (a short one on a coarse mesh) has area 0 and velocity_mean NaN, written as null.
std::vector<ExitEdge> profile_exit_edges(const assembly::FormingProblem<3>& problem,
                                         const VectorX& u, const mesh::ProfileDie& die);

} // namespace formflow::post
