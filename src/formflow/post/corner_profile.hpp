// SPDX-License-Identifier: MIT
// The equivalent strain rate against the distance from a point (the die corner singularity).
#pragma once

#include "formflow/assembly/forming_problem.hpp"

#include <vector>

namespace formflow::post {

/// ε̄̇ in logarithmic annuli around a corner: bin k covers distances
/// [r_min·10^(k/n), r_min·10^((k+1)/n)) with n bins per decade. Only bins that
/// contain quadrature points are kept.
struct CornerProfile {
  std::vector<Real> radius;    ///< geometric centre of the annulus
  std::vector<Real> mean_rate; ///< area-weighted mean ε̄̇ over the material in the annulus
  std::vector<Real> max_rate;  ///< largest ε̄̇ at a quadrature point in the annulus
};

/// The profile of velocity `u` around `corner` from the points of the full
/// (a-term) Gauss rule. Near a re-entrant corner of a rigid-plastic flow
/// ε̄̇ grows like 1/ρ (SPEC §4); a mesh of size h resolves it down to ρ ≈ h.
template <int dim>
CornerProfile corner_profile(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                             const Point<dim>& corner, Real r_min, Real r_max, int bins_per_decade);

} // namespace formflow::post
