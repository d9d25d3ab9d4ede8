// SPDX-License-Identifier: MIT
// The exact incompressibility constraint (d = 0) of the mixed problem with a
// discontinuous pressure: the cell adds r_e Bᵀ M⁻¹ B and the load −Bᵀ λ_e, r_e = ρ ν̄_e
// with ν̄_e the cell's mean secant viscosity (so every cell's constraint converges at
// the rate ≈ 1/(1 + ρ β_h²) whatever its viscosity); the Uzawa step
// λ_e ← λ_e + r_e M⁻¹ B u_e (ConstraintMultipliers::update) drives M⁻¹ B u to 0.
#include "formflow/assembly/terms/pressure_space_term.hpp"
#include "formflow/core/error.hpp"

#include <numeric>

namespace formflow::assembly {

namespace {

template <int dim> class AugmentedPressureTerm final : public PressureSpaceTerm<dim> {
public:
  using PressureSpaceTerm<dim>::PressureSpaceTerm;
  std::string_view name() const override { return "augmented pressure"; }

  void add_secant(const CellState<dim>& cell, MatrixX& matrix, VectorX& load) const override {
    const MatrixX& divergence = this->multipliers_.cell_divergence(cell.cell);
    const Real mean_viscosity = std::accumulate(cell.viscosity.begin(), cell.viscosity.end(), 0.0) /
                                static_cast<Real>(cell.viscosity.size());
    const Real r = this->multipliers_.record_augmentation(cell.cell, mean_viscosity);
    load.noalias() -= divergence.transpose() * this->multipliers_.cell_multiplier(cell.cell);
    matrix.noalias() +=
        r * divergence.transpose() * this->multipliers_.cell_inverse_mass(cell.cell) * divergence;
  }

  void add_force(const CellState<dim>&, CellVector&) const override {
    FF_ASSERT(false, "Newton does not linearise the Uzawa multipliers (solvers/capabilities)");
  }
  bool has_loads() const override { return true; }
  bool newton_ready() const override { return false; }
};

} // namespace

template <int dim>
std::unique_ptr<CellTerm<dim>> make_augmented_pressure_term(ConstraintMultipliers<dim>& pressure,
                                                            const mesh::CellType& type) {
  return std::make_unique<AugmentedPressureTerm<dim>>(pressure, type);
}

template std::unique_ptr<CellTerm<2>> make_augmented_pressure_term<2>(ConstraintMultipliers<2>&,
                                                                      const mesh::CellType&);
template std::unique_ptr<CellTerm<3>> make_augmented_pressure_term<3>(ConstraintMultipliers<3>&,
                                                                      const mesh::CellType&);

} // namespace formflow::assembly
