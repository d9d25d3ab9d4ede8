// SPDX-License-Identifier: MIT
// Cell-wise condensation of discontinuous pressures and the Uzawa multiplier updates.
#include "formflow/assembly/constraint_multipliers.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"

#include <Eigen/LU>

#include <array>
#include <cmath>
#include <numeric>

namespace formflow::assembly {

template <int dim>
ConstraintMultipliers<dim>::ConstraintMultipliers(const mesh::Mesh<dim>& mesh,
                                                  const physics::Penalty& penalty,
                                                  const Formulation& formulation,
                                                  const fem::QuadratureRule<dim>& full_rule,
                                                  Index n_contact_points, bool axisymmetric)
    : mesh_(mesh), penalty_(penalty), formulation_(formulation) {
  FF_ASSERT(!axisymmetric || dim == 2, "axisymmetry is a plane model");
  contact_multiplier_.assign(n_contact_points, 0.0);
  contact_weight_.assign(n_contact_points, 0.0);
  if (!has_pressure_space()) return;
  n_pressure_ = fem::pressure_functions_per_cell<dim>(formulation.pressure);
  if (has_global_pressure()) {
    if (fem::is_discontinuous(formulation.pressure))
      number_cells();
    else
      number_vertices();
  }
  const int n_local = mesh.nodes_per_cell() * dim;
  fem::CellValues<dim> values(mesh.cell_type(), full_rule);
  typename fem::CellValues<dim>::Gradients coordinates(dim, mesh.nodes_per_cell());
  std::vector<VectorX> basis;
  for (const Point<dim>& xi : full_rule.points)
    basis.push_back(fem::tabulate_pressure<dim>(formulation.pressure, xi));
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    values.reinit(coordinates);
    if (axisymmetric) values.weight_by_radius();
    MatrixX divergence = MatrixX::Zero(n_pressure_, n_local);
    MatrixX mass = MatrixX::Zero(n_pressure_, n_pressure_);
    VectorX integral = VectorX::Zero(n_pressure_);
    VectorX divergence_row(n_local);
    for (int q = 0; q < values.n_points(); ++q) {
      // div(φ_a e_i) = ∂_i φ_a: the flattened gradient is the divergence row; in
      // axisymmetry the radial component adds its hoop rate φ_a/r.
      const auto& grad = values.gradients(q);
      divergence_row = Eigen::Map<const VectorX>(grad.data(), n_local);
      if (axisymmetric)
        for (int a = 0; a < mesh.nodes_per_cell(); ++a)
          divergence_row[a * dim + 1] += values.shape(q)[a] / values.point(q)[1];
      divergence.noalias() += values.JxW(q) * basis[q] * divergence_row.transpose(); // ψ div φ dx
      mass.noalias() += values.JxW(q) * basis[q] * basis[q].transpose();             // ψ ψ dx
      integral += values.JxW(q) * basis[q];
    }
    divergence_.push_back(std::move(divergence));
    inverse_mass_.push_back(mass.inverse()); // at most 2^dim × 2^dim, SPD
    mass_.push_back(std::move(mass));
    basis_integral_.push_back(std::move(integral));
  }
  multiplier_.assign(mesh.n_cells(), VectorX::Zero(n_pressure_));
  augmentation_.assign(mesh.n_cells(), 0.0);
  if (has_global_pressure()) {
    basis_at_points_ = std::move(basis);
    viscous_mass_ = mass_; // ν = 2η = 1 until the first assembly
  }
}

template <int dim> void ConstraintMultipliers<dim>::number_cells() {
  n_pressure_dofs_ = mesh_.n_cells() * n_pressure_;
  pressure_dofs_.resize(static_cast<std::size_t>(n_pressure_dofs_));
  std::iota(pressure_dofs_.begin(), pressure_dofs_.end(), Index{0});
  pressure_ = VectorX::Zero(n_pressure_dofs_);
}

template <int dim> VectorX ConstraintMultipliers<dim>::constant_pressure() const {
  if (!fem::is_discontinuous(formulation_.pressure)) return VectorX::Ones(n_pressure_dofs_);
  // The discontinuous bases are monomials whose first is 1 (fem/pressure_space.cpp).
  VectorX constant = VectorX::Zero(n_pressure_dofs_);
  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) constant[cell * n_pressure_] = 1.0;
  return constant;
}

template <int dim>
void ConstraintMultipliers<dim>::record_viscous_mass(Index cell, const fem::CellValues<dim>& full,
                                                     std::span<const Real> viscosity) {
  FF_ASSERT(viscosity.size() == basis_at_points_.size() &&
                full.n_points() == static_cast<int>(viscosity.size()),
            "the viscosities are at the full-rule points the pressure basis was tabulated at");
  MatrixX& mass = viscous_mass_[cell];
  mass.setZero();
  for (int q = 0; q < full.n_points(); ++q)
    mass.noalias() += (full.JxW(q) * 1.5 / viscosity[q]) * basis_at_points_[q] *
                      basis_at_points_[q].transpose(); // 1/(2η) = 3/(2ν)
}

template <int dim> void ConstraintMultipliers<dim>::number_vertices() {
  // Vertex i of the Q1 basis sits at lattice position (bit k of i) · order along
  // direction k of the lexicographic node numbering (fem/lagrange.hpp); the P1 basis
  // function i is simplex vertex i, local node i (fem/simplex_lagrange.hpp).
  FF_ASSERT(mesh_.is_simplex() == (formulation_.pressure == fem::PressureSpace::P1),
            "the continuous pressure is P1 on simplices and Q1 on cubes");
  std::vector<Index> vertex_dof(mesh_.n_nodes(), -1);
  pressure_dofs_.reserve(static_cast<std::size_t>(mesh_.n_cells()) * n_pressure_);
  for (Index cell = 0; cell < mesh_.n_cells(); ++cell)
    for (int i = 0; i < n_pressure_; ++i) {
      int local = 0, stride = 1;
      if (mesh_.is_simplex())
        local = i;
      else
        for (int k = 0; k < dim; ++k, stride *= mesh_.order + 1)
          local += ((i >> k) & 1) * mesh_.order * stride;
      Index& dof = vertex_dof[mesh_.cells(local, cell)];
      if (dof < 0) dof = n_pressure_dofs_++;
      pressure_dofs_.push_back(dof);
    }
  pressure_ = VectorX::Zero(n_pressure_dofs_);
}

template <int dim> VectorX ConstraintMultipliers<dim>::cell_pressure(Index cell) const {
  VectorX local(n_pressure_);
  const auto dofs = cell_pressure_dofs(cell);
  for (int i = 0; i < n_pressure_; ++i) local[i] = pressure_[dofs[i]];
  return local;
}

template <int dim>
VectorX ConstraintMultipliers<dim>::cell_velocity(Index cell, const VectorX& u) const {
  VectorX local(mesh_.nodes_per_cell() * dim);
  for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
    local.template segment<dim>(a * dim) =
        u.template segment<dim>(fem::dof_of<dim>(mesh_.cells(a, cell), 0));
  return local;
}

template <int dim>
Real ConstraintMultipliers<dim>::update(const VectorX& u, std::span<const Real> normal_velocity,
                                        const std::vector<int>& cell_ranks,
                                        const Distribution& distribution) {
  const bool distributed = distribution.distributed();
  FF_ASSERT(!distributed || static_cast<Index>(cell_ranks.size()) == mesh_.n_cells(),
            "a distributed update knows every cell's rank");
  const auto own = [&](Index cell) {
    return !distributed || cell_ranks[cell] == distribution.rank;
  };
  Real change = 0.0;
  if (is_exact_pressure() && !has_global_pressure()) {
    std::array<Real, 2> norms{0.0, 0.0}; // ‖Δλ‖², ‖λ‖² (M-weighted)
    for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
      if (!own(cell)) continue;
      const VectorX step = augmentation_[cell] *
                           (inverse_mass_[cell] * (divergence_[cell] * cell_velocity(cell, u)));
      multiplier_[cell] += step;
      norms[0] += step.dot(mass_[cell] * step);
      norms[1] += multiplier_[cell].dot(mass_[cell] * multiplier_[cell]);
    }
    if (distributed) {
      distribution.sum_over_ranks(norms);
      gather_cell_multipliers(own, distribution);
    }
    change = norms[1] > 0 ? std::sqrt(norms[0] / norms[1]) : 0.0;
  }
  if (is_exact_contact()) {
    FF_ASSERT(normal_velocity.size() == contact_multiplier_.size(), "one u_N per Γ3 point");
    // Each point's weight was recorded by its face's rank (the others hold 0 or an
    // earlier sum): the owner's value, the same on every rank.
    if (distributed && !contact_weights_summed_) {
      distribution.sum_over_ranks(contact_weight_);
      contact_weights_summed_ = true;
    }
    Real change_norm = 0.0, norm = 0.0;
    for (std::size_t k = 0; k < contact_multiplier_.size(); ++k) {
      const Real step = formulation_.contact_augmentation * normal_velocity[k];
      contact_multiplier_[k] += step;
      change_norm += step * step * contact_weight_[k];
      norm += contact_multiplier_[k] * contact_multiplier_[k] * contact_weight_[k];
    }
    if (norm > 0) change = std::max(change, std::sqrt(change_norm / norm));
  }
  return change;
}

template <int dim>
void ConstraintMultipliers<dim>::gather_cell_multipliers(const std::function<bool(Index)>& own,
                                                         const Distribution& distribution) {
  // Every cell's λ_e and r_e from its rank (the others add zeros): the post-processing
  // reads every cell's pressure, and the next assembly its own cells' again.
  const Index n_cells = mesh_.n_cells();
  const Index per_cell = n_pressure_ + 1;
  std::vector<Real> values(static_cast<std::size_t>(n_cells * per_cell), 0.0);
  for (Index cell = 0; cell < n_cells; ++cell) {
    if (!own(cell)) continue;
    Real* slot = values.data() + cell * per_cell;
    for (int i = 0; i < n_pressure_; ++i) slot[i] = multiplier_[cell][i];
    slot[n_pressure_] = augmentation_[cell];
  }
  distribution.sum_over_ranks(values);
  for (Index cell = 0; cell < n_cells; ++cell) {
    const Real* slot = values.data() + cell * per_cell;
    for (int i = 0; i < n_pressure_; ++i) multiplier_[cell][i] = slot[i];
    augmentation_[cell] = slot[n_pressure_];
  }
}

template <int dim>
VectorX ConstraintMultipliers<dim>::cell_pressure_coefficients(
    Index cell, const Eigen::Ref<const VectorX>& velocity) const {
  if (has_global_pressure()) return cell_pressure(cell); // solved for, not a function of u
  const VectorX projected_divergence = inverse_mass_[cell] * (divergence_[cell] * velocity);
  if (is_exact_pressure()) return multiplier_[cell] + augmentation_[cell] * projected_divergence;
  return projected_divergence / penalty_.d; // σ_H = (1/d) P div u (eq. 3.6 in the pressure space)
}

template <int dim>
VectorX ConstraintMultipliers<dim>::pressure_coefficients(Index cell, const VectorX& u) const {
  return cell_pressure_coefficients(cell, cell_velocity(cell, u));
}

template <int dim>
Real ConstraintMultipliers<dim>::pressure_integral(Index cell, const VectorX& u) const {
  return basis_integral_[cell].dot(pressure_coefficients(cell, u));
}

template <int dim>
Real ConstraintMultipliers<dim>::contact_pressure(Index k, Real normal_velocity) const {
  if (is_exact_contact())
    return contact_multiplier_[k] + formulation_.contact_augmentation * normal_velocity;
  return normal_velocity / penalty_.d_n;
}

template class ConstraintMultipliers<2>;
template class ConstraintMultipliers<3>;

} // namespace formflow::assembly
