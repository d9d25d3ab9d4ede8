// SPDX-License-Identifier: MIT
// Global B and M of the continuous pressure and the fixed-pattern saddle-point matrix.
#include "formflow/assembly/saddle_point_system.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"

#include <algorithm>

namespace formflow::assembly {

namespace {

using Triplets = std::vector<Eigen::Triplet<Real, Index>>;

SparseMatrix from_triplets(Index rows, Index columns, const Triplets& triplets) {
  SparseMatrix matrix(rows, columns);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  matrix.makeCompressed();
  return matrix;
}

} // namespace

template <int dim>
SaddlePointSystem<dim>::SaddlePointSystem(const FormingProblem<dim>& problem,
                                          const ConstraintMultipliers<dim>& multipliers)
    : problem_(problem), multipliers_(multipliers), n_velocity_(problem.plan().n_free()),
      n_pressure_(multipliers.n_pressure_dofs()), d_(multipliers.penalty().d) {
  FF_ASSERT(multipliers.has_global_pressure(), "the saddle-point system is for a global pressure");
  const auto& mesh = problem.mesh();
  const ScatterPlan& plan = problem.plan();
  const Discretisation<dim>& discretisation = problem.discretisation();
  // A distributed run (issue 20): B, M and the pressure rows' loads of this rank's own
  // cells only, its share of the saddle point as A is the velocity's (the ranks' shares
  // add up to the system). A discontinuous pressure dof is one cell's, so one rank's.
  distributed_ = discretisation.distribution().distributed();
  FF_ASSERT(!distributed_ || fem::is_discontinuous(multipliers.pressure_space()),
            "a distributed saddle point needs a discontinuous pressure (app/distributed_run)");
  // What every rank must agree on, from every cell (the same numbers on each, no message):
  // Bᵀ1 on the free dofs and B's largest entry (whether the constant pressure is a null
  // mode) and the pressure weights ∫ ψ_i dx (the zero-mean shift).
  constant_ = multipliers.constant_pressure();
  VectorX constant_work = VectorX::Zero(n_velocity_);
  pressure_weights_ = VectorX::Zero(n_pressure_);
  Real largest = 0;
  Triplets free_entries, prescribed_entries, mass_entries;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    const MatrixX& divergence = multipliers.cell_divergence(cell);
    const MatrixX& mass = multipliers.cell_mass(cell);
    const auto pressure_dofs = multipliers.cell_pressure_dofs(cell);
    const bool own = discretisation.assembles(cell);
    for (Index i = 0; i < divergence.rows(); ++i) {
      for (int a = 0; a < mesh.nodes_per_cell(); ++a)
        for (int k = 0; k < dim; ++k) {
          const Index dof = fem::dof_of<dim>(mesh.cells(a, cell), k);
          const Real value = divergence(i, a * dim + k);
          if (const Index row = plan.free_index(dof); row >= 0) {
            constant_work[row] += value * constant_[pressure_dofs[i]];
            largest = std::max(largest, std::abs(value));
            if (own) free_entries.emplace_back(pressure_dofs[i], row, value);
          } else if (own) {
            prescribed_entries.emplace_back(pressure_dofs[i], dof, value);
          }
        }
      for (Index j = 0; j < mass.cols(); ++j) {
        pressure_weights_[pressure_dofs[i]] += mass(i, j) * constant_[pressure_dofs[j]];
        if (own) mass_entries.emplace_back(pressure_dofs[i], pressure_dofs[j], mass(i, j));
      }
    }
  }
  divergence_free_ = from_triplets(n_pressure_, n_velocity_, free_entries);
  divergence_prescribed_ = from_triplets(n_pressure_, problem.n_dofs(), prescribed_entries);
  mass_ = from_triplets(n_pressure_, n_pressure_, mass_entries);

  // The constant pressure is a null mode iff Bᵀ 1 = 0 on the free dofs (d = 0 only).
  pinned_ = d_ == 0 && constant_work.lpNorm<Eigen::Infinity>() <= 1e-10 * largest;
  // The pin's identity entry belongs to the rank of the pinned dof's cell (cell 0 holds a
  // discontinuous pressure's dof 0): added once over the ranks.
  pin_here_ = pinned_ && (!distributed_ || discretisation.assembles(0));
}

template <int dim> void SaddlePointSystem<dim>::build_whole_matrix(const SparseMatrix& lower) {
  FF_ASSERT(lower.isCompressed(), "slots are offsets into a compressed matrix");
  // Pattern: A (both triangles), B and Bᵀ, the pressure block; values 0 for now.
  Triplets entries;
  for (Index column = 0; column < lower.outerSize(); ++column)
    for (Index k = lower.outerIndexPtr()[column]; k < lower.outerIndexPtr()[column + 1]; ++k) {
      const Index row = lower.innerIndexPtr()[k];
      entries.emplace_back(row, column, 0.0);
      entries.emplace_back(column, row, 0.0);
    }
  Triplets fixed;
  for (Index column = 0; column < divergence_free_.outerSize(); ++column)
    for (SparseMatrix::InnerIterator it(divergence_free_, column); it; ++it) {
      if (pinned_ && it.row() == 0) continue;
      fixed.emplace_back(n_velocity_ + it.row(), column, it.value());
      fixed.emplace_back(column, n_velocity_ + it.row(), it.value());
    }
  if (d_ > 0)
    for (Index column = 0; column < mass_.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(mass_, column); it; ++it)
        fixed.emplace_back(n_velocity_ + it.row(), n_velocity_ + column, -d_ * it.value());
  if (pin_here_) fixed.emplace_back(n_velocity_, n_velocity_, 1.0);
  for (const auto& entry : fixed) entries.emplace_back(entry.row(), entry.col(), 0.0);
  // Distributed with d = 0: a structural zero on the diagonal of the own cells' pressure
  // rows, so that PETSc's numbering gives each pressure row to its cell's rank (a row
  // belongs to the lowest rank whose share has its diagonal).
  if (distributed_ && d_ == 0)
    for (const Index cell : problem_.discretisation().assembled_cells())
      for (const Index dof : multipliers_.cell_pressure_dofs(cell))
        entries.emplace_back(n_velocity_ + dof, n_velocity_ + dof, 0.0);
  const Index size = n_velocity_ + n_pressure_;
  matrix_ = from_triplets(size, size, entries);

  fixed_entries_.reserve(fixed.size());
  for (const auto& entry : fixed)
    fixed_entries_.emplace_back(slot(entry.row(), entry.col()), entry.value());
  for (Index column = 0; column < lower.outerSize(); ++column)
    for (Index k = lower.outerIndexPtr()[column]; k < lower.outerIndexPtr()[column + 1]; ++k) {
      const Index row = lower.innerIndexPtr()[k];
      lower_slot_.push_back(slot(row, column));
      upper_slot_.push_back(row == column ? -1 : slot(column, row));
    }
}

template <int dim> SparseMatrix SaddlePointSystem<dim>::coupling() const {
  if (!pinned_) return divergence_free_;
  SparseMatrix pruned = divergence_free_;
  pruned.prune([](Index row, Index, Real) { return row != 0; }); // δp_0 = 0: no row
  return pruned;
}

template <int dim> SparseMatrix SaddlePointSystem<dim>::pressure_block() const {
  SparseMatrix block(n_pressure_, n_pressure_);
  if (d_ > 0) block = -d_ * mass_;
  if (pin_here_) block.coeffRef(0, 0) = 1.0;
  block.makeCompressed();
  return block;
}

template <int dim> Index SaddlePointSystem<dim>::slot(Index row, Index column) const {
  const Index* begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[column];
  const Index* end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[column + 1];
  const Index* found = std::lower_bound(begin, end, row);
  FF_ASSERT(found != end && *found == row, "entry outside the saddle-point pattern");
  return static_cast<Index>(found - matrix_.innerIndexPtr());
}

template <int dim> void SaddlePointSystem<dim>::fill_matrix(const LinearSystem& velocity) {
  if (matrix_.rows() == 0) build_whole_matrix(velocity.matrix);
  FF_ASSERT(velocity.matrix.nonZeros() == static_cast<Index>(lower_slot_.size()),
            "the velocity matrix keeps the pattern it was built with");
  Real* values = matrix_.valuePtr();
  std::fill(values, values + matrix_.nonZeros(), 0.0);
  for (const auto& [slot, value] : fixed_entries_) values[slot] += value;
  const Real* lower = velocity.matrix.valuePtr();
  for (std::size_t k = 0; k < lower_slot_.size(); ++k) {
    values[lower_slot_[k]] += lower[k];
    if (upper_slot_[k] >= 0) values[upper_slot_[k]] += lower[k];
  }
}

template <int dim>
VectorX SaddlePointSystem<dim>::rhs(const LinearSystem& velocity, const VectorX& pressure) const {
  VectorX rhs(n_velocity_ + n_pressure_);
  rhs.head(n_velocity_) = velocity.rhs;
  // B u − d M (p + δp) = 0 with the prescribed velocities moved across.
  rhs.tail(n_pressure_) = -(divergence_prescribed_ * problem_.constraints().values);
  if (d_ > 0) rhs.tail(n_pressure_) += d_ * (mass_ * pressure);
  if (pinned_) rhs[n_velocity_] = 0.0; // δp_0 = 0
  return rhs;
}

template <int dim>
void SaddlePointSystem<dim>::add_pressure_load(const VectorX& increment,
                                               LinearSystem& velocity) const {
  velocity.rhs -= divergence_free_.transpose() * increment;
  const VectorX prescribed = divergence_prescribed_.transpose() * increment;
  const ScatterPlan& plan = problem_.plan();
  for (Index dof = 0; dof < plan.n_dofs(); ++dof)
    if (const Index row = plan.prescribed_index(dof); row >= 0)
      velocity.prescribed_loads[row] -= prescribed[dof];
}

template <int dim> void SaddlePointSystem<dim>::fix_pressure_level(VectorX& pressure) const {
  if (!pinned_) return;
  pressure -= (pressure_weights_.dot(pressure) / pressure_weights_.dot(constant_)) * constant_;
}

template <int dim> Index SaddlePointSystem<dim>::pressure_block_size() const {
  if (!fem::is_discontinuous(multipliers_.pressure_space())) return 0;
  return static_cast<Index>(multipliers_.cell_pressure_dofs(0).size());
}

template <int dim> SparseMatrix SaddlePointSystem<dim>::schur_preconditioner() const {
  Triplets entries;
  // Own cells only (the viscosities are recorded where a cell is assembled): each cell
  // block is on its pressure dofs' rank, the pin on the rank that has it in the matrix.
  for (const Index cell : problem_.discretisation().assembled_cells()) {
    const MatrixX block = multipliers_.cell_viscous_mass(cell) + d_ * multipliers_.cell_mass(cell);
    const auto dofs = multipliers_.cell_pressure_dofs(cell);
    for (Index i = 0; i < block.rows(); ++i)
      for (Index j = 0; j < block.cols(); ++j)
        if (!pinned_ || (dofs[i] != 0 && dofs[j] != 0))
          entries.emplace_back(dofs[i], dofs[j], -block(i, j));
  }
  if (pin_here_) entries.emplace_back(0, 0, 1.0);
  return from_triplets(n_pressure_, n_pressure_, entries);
}

template class SaddlePointSystem<2>;
template class SaddlePointSystem<3>;

} // namespace formflow::assembly
