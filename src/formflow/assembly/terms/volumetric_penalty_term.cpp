// SPDX-License-Identifier: MIT
// (2) The volumetric penalty ∫ (1/d) ε̇_V(u) ε̇_V(v) dx of the penalty problem (eq. 3.8),
// integrated with the volumetric rule (selective: 1 point for Q1, 2×2 for Q2); its
// multiplier is σ_H = ε̇_V/d (eq. 3.6). In axisymmetry ε̇_V includes the hoop rate u_r/r.
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/residual_kernels.hpp"
#include "formflow/assembly/terms/terms.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/physics/kinematics.hpp"

namespace formflow::assembly {

namespace {

template <int dim> class VolumetricPenaltyTerm final : public CellTerm<dim> {
public:
  VolumetricPenaltyTerm(Real d, bool axisymmetric, int order, int volumetric_points)
      : d_(d), axisymmetric_(axisymmetric),
        to_nodes_(fem::gauss_to_nodes<dim>(order, volumetric_points)) {}

  std::string_view name() const override { return "volumetric penalty"; }

  void add_secant(const CellState<dim>& cell, MatrixX& matrix, VectorX&) const override {
    if constexpr (dim == 2) {
      if (axisymmetric_) return add_volumetric_penalty_axisymmetric(cell.volumetric, d_, matrix);
    }
    add_volumetric_penalty<dim>(cell.volumetric, d_, matrix);
  }

  void add_force(const CellState<dim>& cell, CellVector& force) const override {
    if constexpr (dim == 2) {
      if (axisymmetric_)
        return add_volumetric_force_axisymmetric(cell.volumetric, d_, cell.velocities, force);
    }
    add_volumetric_force<dim>(cell.volumetric, d_, cell.velocities, force);
  }

  void add_power(const CellState<dim>& cell, PowerTerms& power) const override {
    for (int q = 0; q < cell.volumetric.n_points(); ++q) {
      const Real volumetric = volumetric_rate(cell, q);
      power.volumetric_penalty += volumetric * volumetric / d_ * cell.volumetric.JxW(q);
    }
  }

  bool carries_pressure() const override { return true; }
  CellPressure pressure(const CellState<dim>& cell) const override {
    CellPressure pressure;
    VectorX at_points(cell.volumetric.n_points());
    for (int q = 0; q < cell.volumetric.n_points(); ++q) {
      at_points[q] = volumetric_rate(cell, q) / d_; // σ_H = ε̇_V/d (eq. 3.6)
      pressure.integral += at_points[q] * cell.volumetric.JxW(q);
    }
    pressure.at_nodes = to_nodes_ * at_points;
    return pressure;
  }

private:
  /// ε̇_V = div u (+ u_r/r in axisymmetry) at volumetric point q.
  Real volumetric_rate(const CellState<dim>& cell, int q) const {
    Real rate = cell.velocities.cwiseProduct(cell.volumetric.gradients(q)).sum();
    if (axisymmetric_)
      rate += cell.velocities.row(1).dot(cell.volumetric.shape(q)) / cell.volumetric.point(q)[1];
    return rate;
  }

  Real d_;
  bool axisymmetric_;
  MatrixX to_nodes_; ///< volumetric-rule values → nodal values (fem::gauss_to_nodes)
};

} // namespace

template <int dim>
std::unique_ptr<CellTerm<dim>> make_volumetric_penalty_term(Real d, bool axisymmetric, int order,
                                                            int volumetric_points) {
  return std::make_unique<VolumetricPenaltyTerm<dim>>(d, axisymmetric, order, volumetric_points);
}

template std::unique_ptr<CellTerm<2>> make_volumetric_penalty_term<2>(Real, bool, int, int);
template std::unique_ptr<CellTerm<3>> make_volumetric_penalty_term<3>(Real, bool, int, int);

} // namespace formflow::assembly
