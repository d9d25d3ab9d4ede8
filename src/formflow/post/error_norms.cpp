// SPDX-License-Identifier: MIT
// Error norms by a higher-order Gauss rule.
#include "formflow/post/error_norms.hpp"
#include "formflow/fem/reference_element.hpp"

#include "formflow/physics/kinematics.hpp"

#include <cmath>

namespace formflow::post {

namespace {

/// ∫ |ε̇(e)|² and ∫ |e|² over Ω with e = u_h − exact (exact may be absent: e = u_h).
template <int dim>
void add_domain_terms(const assembly::FormingProblem<dim>& problem, const VectorX& u_h,
                      const ExactVelocity<dim>* exact, Real& strain_square, Real& l2_square) {
  const auto& mesh = problem.discretisation().mesh();
  const fem::QuadratureRule<dim> rule =
      fem::rule_of_points<dim>(mesh.cell_type(), error_quadrature_points);
  fem::CellValues<dim> values(mesh.cell_type(), rule);
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    problem.discretisation().gather(cell, &u_h, coordinates, velocities);
    values.reinit(coordinates);
    for (int q = 0; q < values.n_points(); ++q) {
      Point<dim> error = velocities * values.shape(q);
      Tensor2<dim> gradient = physics::velocity_gradient<dim>(velocities, values.gradients(q));
      if (exact) {
        error -= exact->velocity(values.point(q));
        gradient -= exact->gradient(values.point(q));
      }
      const Tensor3 rate = physics::strain_rate<dim>(gradient);
      strain_square += rate.cwiseProduct(rate).sum() * values.JxW(q);
      l2_square += error.squaredNorm() * values.JxW(q);
    }
  }
}

/// ∫ (ε̇_V(u_h)/d)² at the volumetric rule: the discrete σ_H against σ_H = 0.
template <int dim>
Real hydrostatic_square(const assembly::FormingProblem<dim>& problem, const VectorX& u_h) {
  const auto& mesh = problem.discretisation().mesh();
  fem::CellValues<dim> values(mesh.cell_type(), problem.discretisation().volumetric_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  Real sum = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    problem.discretisation().gather(cell, &u_h, coordinates, velocities);
    values.reinit(coordinates);
    for (int q = 0; q < values.n_points(); ++q) {
      const Real stress = physics::velocity_gradient<dim>(velocities, values.gradients(q)).trace() /
                          problem.settings().penalty.d;
      sum += stress * stress * values.JxW(q);
    }
  }
  return sum;
}

} // namespace

template <int dim>
ErrorNorms error_norms(const assembly::FormingProblem<dim>& problem, const VectorX& u_h,
                       const ExactVelocity<dim>& exact) {
  Real strain_square = 0.0, l2_square = 0.0;
  add_domain_terms(problem, u_h, &exact, strain_square, l2_square);
  // A manufactured problem has no Γ3 (all of ∂Ω is Dirichlet): no contact term.
  return {std::sqrt(strain_square), std::sqrt(l2_square),
          std::sqrt(hydrostatic_square(problem, u_h))};
}

template <int dim>
ErrorNorms difference_norms(const assembly::FormingProblem<dim>& problem, const VectorX& u_a,
                            const VectorX& u_b) {
  const VectorX difference = u_a - u_b;
  Real strain_square = 0.0, l2_square = 0.0;
  add_domain_terms<dim>(problem, difference, nullptr, strain_square, l2_square);
  for (const auto& point : problem.contact_state(difference))
    strain_square += point.normal_velocity * point.normal_velocity * point.weight; // ∫_Γ3 e_N²
  return {std::sqrt(strain_square), std::sqrt(l2_square), 0.0};
}

template ErrorNorms error_norms<2>(const assembly::FormingProblem<2>&, const VectorX&,
                                   const ExactVelocity<2>&);
template ErrorNorms error_norms<3>(const assembly::FormingProblem<3>&, const VectorX&,
                                   const ExactVelocity<3>&);
template ErrorNorms difference_norms<2>(const assembly::FormingProblem<2>&, const VectorX&,
                                        const VectorX&);
template ErrorNorms difference_norms<3>(const assembly::FormingProblem<3>&, const VectorX&,
                                        const VectorX&);

} // namespace formflow::post
