// SPDX-License-Identifier: MIT
// The mixed problem (3.7) with a discontinuous pressure condensed cell by cell at
// d > 0: c = (1/d) M⁻¹ B u, and the cell adds (1/d) Bᵀ M⁻¹ B to the SPD velocity
// matrix. Linear in u, so Newton takes it as it is.
#include "formflow/assembly/terms/pressure_space_term.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class CondensedPressureTerm final : public PressureSpaceTerm<dim> {
public:
  using PressureSpaceTerm<dim>::PressureSpaceTerm;
  std::string_view name() const override { return "condensed pressure"; }

  void add_secant(const CellState<dim>& cell, MatrixX& matrix, VectorX&) const override {
    const MatrixX& divergence = this->multipliers_.cell_divergence(cell.cell);
    const Real d = this->multipliers_.penalty().d;
    matrix.noalias() += (1.0 / d) * divergence.transpose() *
                        this->multipliers_.cell_inverse_mass(cell.cell) * divergence;
  }

  void add_force(const CellState<dim>& cell, CellVector& force) const override {
    // At most 8 pressure functions per cell (Q1disc in 3D): no heap in the cell loop.
    using CellPressureVector = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 8, 1>;
    const MatrixX& divergence = this->multipliers_.cell_divergence(cell.cell);
    const CellPressureVector projected = divergence * cell.local_velocity();
    const CellPressureVector c = this->multipliers_.cell_inverse_mass(cell.cell) * projected /
                                 this->multipliers_.penalty().d;
    force.noalias() += divergence.transpose() * c; // Bᵀ c
  }
};

} // namespace

template <int dim>
std::unique_ptr<CellTerm<dim>> make_condensed_pressure_term(ConstraintMultipliers<dim>& pressure,
                                                            const mesh::CellType& type) {
  return std::make_unique<CondensedPressureTerm<dim>>(pressure, type);
}

template std::unique_ptr<CellTerm<2>> make_condensed_pressure_term<2>(ConstraintMultipliers<2>&,
                                                                      const mesh::CellType&);
template std::unique_ptr<CellTerm<3>> make_condensed_pressure_term<3>(ConstraintMultipliers<3>&,
                                                                      const mesh::CellType&);

} // namespace formflow::assembly
