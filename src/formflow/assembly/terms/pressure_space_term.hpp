// SPDX-License-Identifier: MIT
// What the three terms of the mixed formulation's pressure space share: σ_H from its
// coefficients (its cell integral and nodal values) and the power ∫ σ_H ε̇_V dx.
#pragma once

#include "formflow/assembly/terms/terms.hpp"
#include "formflow/fem/pressure_space.hpp"
#include "formflow/fem/reference_element.hpp"

namespace formflow::assembly {

/// Base of the condensed, augmented and global pressure terms: they differ in how the
/// coefficients c of σ_H = Σ c_i ψ_i enter the system, not in what σ_H is.
template <int dim> class PressureSpaceTerm : public CellTerm<dim> {
public:
  PressureSpaceTerm(ConstraintMultipliers<dim>& multipliers, const mesh::CellType& type)
      : multipliers_(multipliers) {
    const int nodes_per_cell = mesh::nodes_per_cell<dim>(type);
    at_nodes_.resize(nodes_per_cell,
                     fem::pressure_functions_per_cell<dim>(multipliers.pressure_space()));
    for (int a = 0; a < nodes_per_cell; ++a)
      at_nodes_.row(a) = fem::tabulate_pressure<dim>(multipliers.pressure_space(),
                                                     fem::reference_node<dim>(type, a))
                             .transpose();
  }

  /// ∫ σ_H div u dx = cᵀ B u_e: (1/d)‖P div u‖² for d > 0, → 0 for the exact constraint.
  void add_power(const CellState<dim>& cell, PowerTerms& power) const override {
    power.volumetric_penalty +=
        coefficients(cell).dot(multipliers_.cell_divergence(cell.cell) * cell.local_velocity());
  }

  bool carries_pressure() const override { return true; }
  CellPressure pressure(const CellState<dim>& cell) const override {
    const VectorX c = coefficients(cell);
    return {multipliers_.cell_basis_integral(cell.cell).dot(c), at_nodes_ * c};
  }

protected:
  VectorX coefficients(const CellState<dim>& cell) const {
    return multipliers_.cell_pressure_coefficients(cell.cell, cell.local_velocity());
  }
  ConstraintMultipliers<dim>& multipliers_;

private:
  MatrixX at_nodes_; ///< ψ_i at the cell's reference nodes (n_nodes × n_pressure)
};

} // namespace formflow::assembly
