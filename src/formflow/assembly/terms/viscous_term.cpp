// SPDX-License-Identifier: MIT
// (1) The viscous term a(w; u, v) of the flow law (eq. 3.3), its Newton tangent in
// primal–dual form and, for the paper's full-ε̇ a-form, the unsymmetric rest.
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/residual_kernels.hpp"
#include "formflow/assembly/kernels/tangent_kernels.hpp"
#include "formflow/assembly/terms/terms.hpp"
#include "formflow/physics/kinematics.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class ViscousTerm final : public CellTerm<dim> {
public:
  ViscousTerm(const physics::FlowLaw& law, physics::ViscousStrain strain, bool axisymmetric)
      : law_(law), strain_(strain), axisymmetric_(axisymmetric) {}

  std::string_view name() const override { return "viscous"; }

  void add_secant(const CellState<dim>& cell, MatrixX& matrix, VectorX&) const override {
    add_viscous_term<dim>(cell.full, cell.viscosity, strain_, matrix);
    if constexpr (dim == 2)
      if (axisymmetric_) add_hoop_viscous_term(cell.full, cell.viscosity, strain_, matrix);
  }

  void add_force(const CellState<dim>& cell, CellVector& force) const override {
    add_viscous_force<dim>(cell.full, cell.viscosity, cell.rates, strain_, force);
    if constexpr (dim == 2)
      if (axisymmetric_)
        add_hoop_viscous_force(cell.full, cell.viscosity, cell.rates, strain_, force);
  }

  void add_tangent(const CellState<dim>& cell, MatrixX& matrix) const override {
    const ViscousTangentData& t = cell.tangent;
    if constexpr (dim == 2) {
      if (axisymmetric_) {
        add_viscous_tangent_axisymmetric(cell.full, t.deviators, t.duals, t.a, t.b, matrix);
        return;
      }
    }
    add_viscous_tangent<dim>(cell.full, t.deviators, t.duals, t.a, t.b, matrix);
  }

  // The full-ε̇ form's unsymmetric part (primal: exact at the solution, where the duals
  // are ν ė): ⅔ ν′ dε̄̇[δu] · ⅓ ε̇_V(u) ε̇_V(v) = (a + b ν) ⅓ ε̇_V(u) ε̇_V(v) g(δu).
  // It is not negligible: in near-rigid zones ν ≈ σ_p(ε̄̇₁)/ε̄̇₁ ≈ 1.7e3, so (2/9)ν ≈ 385
  // against 1/d = 1000; dropping it made the Newton tail linear (ratio ≈ 0.25, mesh II).
  void add_coupling(const CellState<dim>& cell, UnsymmetricTangent<dim>& coupling) const override {
    if (strain_ != physics::ViscousStrain::Full) return;
    const fem::CellValues<dim>& values = cell.full;
    const int n_nodes = values.n_nodes(), n_local = n_nodes * dim;
    CellVector divergence_row(n_local), deviator_row(n_local);
    for (int q = 0; q < values.n_points(); ++q) {
      const Real c =
          (cell.tangent.a[q] + cell.tangent.b[q] * cell.viscosity[q]) * cell.rates[q].trace() / 3.0;
      if (c == 0.0) continue;
      const auto& grad = values.gradients(q);
      const Tensor3& deviator = cell.tangent.deviators[q];
      const Tensor2<dim> dev = deviator.template topLeftCorner<dim, dim>();
      for (int node = 0; node < n_nodes; ++node) {
        divergence_row.template segment<dim>(node * dim) = grad.col(node);
        deviator_row.template segment<dim>(node * dim) = dev * grad.col(node);
        if (axisymmetric_) { // the hoop slot: ε̇_θθ(φ_a e_r) = φ_a/r
          const Real hoop = values.shape(q)[node] / values.point(q)[1];
          divergence_row[node * dim + 1] += hoop;
          deviator_row[node * dim + 1] += deviator(2, 2) * hoop;
        }
      }
      coupling.cells.push_back(cell.cell);
      coupling.coefficients.push_back(c * values.JxW(q));
      coupling.rows.insert(coupling.rows.end(), divergence_row.data(),
                           divergence_row.data() + n_local);
      coupling.rows.insert(coupling.rows.end(), deviator_row.data(), deviator_row.data() + n_local);
    }
  }

  void add_power(const CellState<dim>& cell, PowerTerms& power) const override {
    const bool deviatoric = strain_ == physics::ViscousStrain::Deviatoric;
    for (int q = 0; q < cell.full.n_points(); ++q) {
      const Tensor3& rate = cell.rates[q];
      const Real equivalent = physics::equivalent_strain_rate(rate);
      const Tensor3 measured = deviatoric ? physics::deviator(rate) : rate;
      const Real dissipation =
          cell.temperatures.empty()
              ? law_.dissipation(equivalent)
              : physics::FlowLawAt(law_, cell.temperatures[q]).dissipation(equivalent);
      power.plastic_dissipation += dissipation * cell.full.JxW(q);
      power.viscous_form +=
          2.0 / 3.0 * cell.viscosity[q] * measured.cwiseProduct(measured).sum() * cell.full.JxW(q);
    }
  }

private:
  physics::FlowLaw law_;
  physics::ViscousStrain strain_;
  bool axisymmetric_;
};

} // namespace

template <int dim>
std::unique_ptr<CellTerm<dim>> make_viscous_term(const physics::FlowLaw& law,
                                                 physics::ViscousStrain strain, bool axisymmetric) {
  return std::make_unique<ViscousTerm<dim>>(law, strain, axisymmetric);
}

template std::unique_ptr<CellTerm<2>> make_viscous_term<2>(const physics::FlowLaw&,
                                                           physics::ViscousStrain, bool);
template std::unique_ptr<CellTerm<3>> make_viscous_term<3>(const physics::FlowLaw&,
                                                           physics::ViscousStrain, bool);

} // namespace formflow::assembly
