// SPDX-License-Identifier: MIT
// The residual K(u) u assembled from stresses, without a local matrix (Newton line search).
#include "formflow/assembly/kernels/residual_kernels.hpp"

#include "formflow/assembly/kernels/fixed_size.hpp"

namespace formflow::assembly {

namespace {

/// The local vector viewed as dim × n_nodes (column a holds node a's components).
template <int dim>
Eigen::Map<Eigen::Matrix<Real, dim, Eigen::Dynamic>> by_node(CellVector& local_force) {
  return {local_force.data(), dim, local_force.size() / dim};
}

} // namespace

// Σ_b K_ab u_b of add_viscous_term is ⅔ ν (Σ_j ε̇_ij ∂_j φ_a − share ε̇_V ∂_i φ_a):
// with share = ⅓ for the deviatoric form this is ė ∇φ_a (ė_zz meets ε̇_zz(φ) = 0).
namespace {

template <int dim, int n_nodes>
void add_viscous_force_sized(const fem::CellValues<dim>& values, std::span<const Real> viscosity,
                             std::span<const Tensor3> rates, Real volumetric_share,
                             CellVector& local_force) {
  using NodeValues = Eigen::Matrix<Real, dim, n_nodes>;
  const int n = values.n_nodes();
  NodeValues force = NodeValues::Zero(dim, n);
  for (int q = 0; q < values.n_points(); ++q) {
    Tensor2<dim> stress = rates[q].template topLeftCorner<dim, dim>();
    stress.diagonal().array() -= volumetric_share * rates[q].trace();
    force.noalias() += (2.0 / 3.0 * viscosity[q] * values.JxW(q)) * stress *
                       Eigen::Map<const NodeValues>(values.gradients(q).data(), dim, n);
  }
  by_node<dim>(local_force) += force;
}

} // namespace

template <int dim>
void add_viscous_force(const fem::CellValues<dim>& values, std::span<const Real> viscosity,
                       std::span<const Tensor3> rates, physics::ViscousStrain strain,
                       CellVector& local_force) {
  const Real volumetric_share = strain == physics::ViscousStrain::Deviatoric ? 1.0 / 3.0 : 0.0;
  with_node_count<dim>(values.n_nodes(), [&](auto n_nodes) {
    add_viscous_force_sized<dim, decltype(n_nodes)::value>(values, viscosity, rates,
                                                           volumetric_share, local_force);
  });
}

namespace {

template <int dim, int n_nodes>
void add_volumetric_force_sized(const fem::CellValues<dim>& values, Real d,
                                const typename fem::CellValues<dim>::Gradients& velocities,
                                CellVector& local_force) {
  using NodeValues = Eigen::Matrix<Real, dim, n_nodes>;
  const int n = values.n_nodes();
  const Eigen::Map<const NodeValues> u(velocities.data(), dim, n);
  NodeValues force = NodeValues::Zero(dim, n);
  for (int q = 0; q < values.n_points(); ++q) {
    const Eigen::Map<const NodeValues> grad(values.gradients(q).data(), dim, n);
    const Real divergence = u.cwiseProduct(grad).sum(); // Σ_a u_a·∇φ_a
    force.noalias() += (values.JxW(q) / d * divergence) * grad;
  }
  by_node<dim>(local_force) += force;
}

} // namespace

template <int dim>
void add_volumetric_force(const fem::CellValues<dim>& values, Real d,
                          const typename fem::CellValues<dim>::Gradients& velocities,
                          CellVector& local_force) {
  with_node_count<dim>(values.n_nodes(), [&](auto n_nodes) {
    add_volumetric_force_sized<dim, decltype(n_nodes)::value>(values, d, velocities, local_force);
  });
}

template <int dim>
void add_contact_force(const fem::FacetValues<dim>& values, Real d_n,
                       const typename fem::CellValues<dim>::Gradients& velocities,
                       CellVector& local_force) {
  auto force = by_node<dim>(local_force);
  for (int q = 0; q < values.n_points(); ++q) {
    const Point<dim>& normal = values.normal(q);
    const Point<dim> velocity = velocities * values.shape(q);
    const Real normal_velocity = velocity.dot(normal);
    const Point<dim> traction = (normal_velocity / d_n) * normal;
    force.noalias() += (values.JxW(q) * traction) * values.shape(q).transpose();
  }
}

void add_hoop_viscous_force(const fem::CellValues<2>& values, std::span<const Real> viscosity,
                            std::span<const Tensor3> rates, physics::ViscousStrain strain,
                            CellVector& local_force) {
  const Real volumetric_share = strain == physics::ViscousStrain::Deviatoric ? 1.0 / 3.0 : 0.0;
  auto force = by_node<2>(local_force);
  for (int q = 0; q < values.n_points(); ++q) {
    const Real hoop_stress = rates[q](2, 2) - volumetric_share * rates[q].trace();
    const Real factor = 2.0 / 3.0 * viscosity[q] * values.JxW(q) * hoop_stress / values.point(q)[1];
    force.row(1) += factor * values.shape(q).transpose();
  }
}

void add_volumetric_force_axisymmetric(const fem::CellValues<2>& values, Real d,
                                       const fem::CellValues<2>::Gradients& velocities,
                                       CellVector& local_force) {
  auto force = by_node<2>(local_force);
  for (int q = 0; q < values.n_points(); ++q) {
    const auto& grad = values.gradients(q);
    const Real radius = values.point(q)[1];
    const Real volumetric =
        velocities.cwiseProduct(grad).sum() + velocities.row(1).dot(values.shape(q)) / radius;
    const Real factor = values.JxW(q) / d * volumetric;
    force.noalias() += factor * grad;
    force.row(1) += (factor / radius) * values.shape(q).transpose();
  }
}

template void add_viscous_force<2>(const fem::CellValues<2>&, std::span<const Real>,
                                   std::span<const Tensor3>, physics::ViscousStrain, CellVector&);
template void add_viscous_force<3>(const fem::CellValues<3>&, std::span<const Real>,
                                   std::span<const Tensor3>, physics::ViscousStrain, CellVector&);
template void add_volumetric_force<2>(const fem::CellValues<2>&, Real,
                                      const fem::CellValues<2>::Gradients&, CellVector&);
template void add_volumetric_force<3>(const fem::CellValues<3>&, Real,
                                      const fem::CellValues<3>::Gradients&, CellVector&);
template void add_contact_force<2>(const fem::FacetValues<2>&, Real,
                                   const fem::CellValues<2>::Gradients&, CellVector&);
template void add_contact_force<3>(const fem::FacetValues<3>&, Real,
                                   const fem::CellValues<3>::Gradients&, CellVector&);

} // namespace formflow::assembly
