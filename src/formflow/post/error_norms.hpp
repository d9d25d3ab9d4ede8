// SPDX-License-Identifier: MIT
// Error norms against an exact velocity, and norms of the difference of two solutions.
#pragma once

#include "formflow/assembly/forming_problem.hpp"

#include <functional>

namespace formflow::post {

/// Norms of a velocity error e (SPEC §2, paper eq. 3.1):
/// ‖e‖_V = (∫_Ω ε̇(e):ε̇(e) dx + ∫_Γ3 e_N² dΓ)^½ and ‖e‖_L2 = (∫_Ω e·e dx)^½,
/// plus the L2 norm of the discrete hydrostatic stress error.
struct ErrorNorms {
  Real v_norm = 0.0;
  Real l2 = 0.0;
  /// ‖σ_H,h − σ_H‖_L2 with σ_H,h = ε̇_V(u_h)/d at the volumetric points and the
  /// exact σ_H = 0 of a divergence-free exact field (manufactured solutions); 0 otherwise.
  Real hydrostatic_l2 = 0.0;
};

/// The exact field: velocity and its gradient (∇u)_ij = ∂u_i/∂x_j at a point.
template <int dim> struct ExactVelocity {
  std::function<Point<dim>(const Point<dim>&)> velocity;
  std::function<Tensor2<dim>(const Point<dim>&)> gradient;
};

/// Gauss points per direction of the error quadrature: exact for the
/// polynomial part of a Q2 error up to degree 9, so that quadrature error stays
/// far below the discretisation error being measured.
inline constexpr int error_quadrature_points = 5;

/// ‖u − u_h‖ for the exact field `exact` (a manufactured solution).
template <int dim>
ErrorNorms error_norms(const assembly::FormingProblem<dim>& problem, const VectorX& u_h,
                       const ExactVelocity<dim>& exact);

/// ‖u_a − u_b‖ for two solutions on the same mesh (penalty and regularisation
/// limits: u_d against a reference). The Γ3 term uses the problem's contact faces.
template <int dim>
ErrorNorms difference_norms(const assembly::FormingProblem<dim>& problem, const VectorX& u_a,
                            const VectorX& u_b);

} // namespace formflow::post
