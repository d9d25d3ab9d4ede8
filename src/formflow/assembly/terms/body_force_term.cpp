// SPDX-License-Identifier: MIT
// A volume load ∫ f·v dx (manufactured solutions).
#include "formflow/assembly/terms/terms.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class BodyForceTerm final : public CellTerm<dim> {
public:
  explicit BodyForceTerm(BodyForce<dim> force) : force_(std::move(force)) {}
  std::string_view name() const override { return "body force"; }

  void add_secant(const CellState<dim>& cell, MatrixX&, VectorX& load) const override {
    add_load(cell, load, 1.0);
  }
  /// The force K u − F: the load with its sign turned.
  void add_force(const CellState<dim>& cell, CellVector& force) const override {
    VectorX load = VectorX::Zero(force.size());
    add_load(cell, load, -1.0);
    force += load;
  }
  void add_power(const CellState<dim>&, PowerTerms&) const override {} // not a dissipation
  bool has_loads() const override { return true; }

private:
  void add_load(const CellState<dim>& cell, VectorX& load, Real sign) const {
    const fem::CellValues<dim>& values = cell.full;
    for (int q = 0; q < values.n_points(); ++q) {
      const Point<dim> force = force_(values.point(q));
      for (int a = 0; a < values.n_nodes(); ++a) // ∫ f·φ_a e_i dx
        load.template segment<dim>(a * dim) += (sign * values.shape(q)[a] * values.JxW(q)) * force;
    }
  }
  BodyForce<dim> force_;
};

} // namespace

template <int dim> std::unique_ptr<CellTerm<dim>> make_body_force_term(BodyForce<dim> force) {
  return std::make_unique<BodyForceTerm<dim>>(std::move(force));
}

template std::unique_ptr<CellTerm<2>> make_body_force_term<2>(BodyForce<2>);
template std::unique_ptr<CellTerm<3>> make_body_force_term<3>(BodyForce<3>);

} // namespace formflow::assembly
