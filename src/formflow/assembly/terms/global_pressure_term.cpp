// SPDX-License-Identifier: MIT
// A global pressure (Taylor–Hood Q2–Q1, or a discontinuous one kept as a saddle point):
// its coefficients p are unknowns of the saddle-point system
// (assembly/saddle_point_system.hpp), which holds B and −dM; the velocity system gets
// only the load −Bᵀ p of the current pressure. The term also records the cell's
// viscosity-scaled pressure mass for the Schur-complement preconditioner.
#include "formflow/assembly/terms/pressure_space_term.hpp"
#include "formflow/core/error.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class GlobalPressureTerm final : public PressureSpaceTerm<dim> {
public:
  using PressureSpaceTerm<dim>::PressureSpaceTerm;
  std::string_view name() const override { return "global pressure"; }

  void add_secant(const CellState<dim>& cell, MatrixX&, VectorX& load) const override {
    this->multipliers_.record_viscous_mass(cell.cell, cell.full, cell.viscosity);
    load.noalias() -= this->multipliers_.cell_divergence(cell.cell).transpose() *
                      this->multipliers_.cell_pressure(cell.cell); // −Bᵀ p
  }
  void add_force(const CellState<dim>&, CellVector&) const override {
    FF_ASSERT(false, "Newton does not solve the saddle-point system (solvers/capabilities)");
  }
  bool has_loads() const override { return true; }
  bool newton_ready() const override { return false; }
};

} // namespace

template <int dim>
std::unique_ptr<CellTerm<dim>> make_global_pressure_term(ConstraintMultipliers<dim>& pressure,
                                                         const mesh::CellType& type) {
  return std::make_unique<GlobalPressureTerm<dim>>(pressure, type);
}

template std::unique_ptr<CellTerm<2>> make_global_pressure_term<2>(ConstraintMultipliers<2>&,
                                                                   const mesh::CellType&);
template std::unique_ptr<CellTerm<3>> make_global_pressure_term<3>(ConstraintMultipliers<3>&,
                                                                   const mesh::CellType&);

} // namespace formflow::assembly
