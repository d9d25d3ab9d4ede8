// SPDX-License-Identifier: MIT
// Load measures, power balance, nodal fields and contact profile at a velocity field.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/post/results.hpp"

#include <vector>

namespace formflow::post {

/// Power of every discrete term at `u` (per unit depth), with the viscosity
/// and friction weights evaluated at `u` itself.
template <int dim>
PowerTerms compute_powers(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                          const std::vector<assembly::ContactPoint<dim>>& contact);

/// Area-weighted mean of −σ_H (σ_H = ε̇_V/d at the volumetric points, eq. 3.6)
/// over the cells that have a face labelled `label`.
template <int dim>
Real mean_pressure_of_cells_at(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                               mesh::BoundaryLabel label);

/// Nodal averages of ε̄̇, σ_H and the contact tractions, plus cell means.
template <int dim>
Fields nodal_fields(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                    const std::vector<assembly::ContactPoint<dim>>& contact);

/// Stick/slip lengths of the container wall and the die face.
template <int dim>
void contact_zones(const assembly::FormingProblem<dim>& problem,
                   const std::vector<assembly::ContactPoint<dim>>& contact, ContactZones& container,
                   ContactZones& die);

/// Γ3 samples. Plane problems: ordered by arc length from the end nearest the
/// rear. Solid problems (Γ3 a surface, no arc length): every point, s = 0, in
/// lexicographic order of (x, y, z), so that a file of them is reproducible.
template <int dim>
std::vector<ContactSample> contact_profile(const assembly::FormingProblem<dim>& problem,
                                           const std::vector<assembly::ContactPoint<dim>>& contact);

/// Everything above plus the reaction force from one more assembly K(u): the
/// consistent reaction K_c·(u) u, which equals the total discrete power at a
/// fixed point of the iteration. Exact friction is evaluated with its final `multipliers`.
/// `stick_speed` > 0: a friction point sticks where |u_T| ≤ stick_speed (exact friction
/// by Newton: the slip its stop rule resolves, δ u⁰) instead of by the active set.
template <int dim>
void evaluate_results(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                      Results& results,
                      const assembly::FrictionMultipliers<dim>* multipliers = nullptr,
                      Real stick_speed = 0.0);

} // namespace formflow::post
