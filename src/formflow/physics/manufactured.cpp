// SPDX-License-Identifier: MIT
// Stream-function velocity fields and their body forces.
#include "formflow/physics/manufactured.hpp"

#include "formflow/core/error.hpp"
#include "formflow/physics/kinematics.hpp"

#include <cmath>
#include <numbers>

namespace formflow::physics {

StreamFunctionField::StreamFunctionField(Real extension, Real amplitude, Real wave_x, Real wave_y)
    : extension_(extension), amplitude_(amplitude), wave_x_(wave_x), wave_y_(wave_y) {
  FF_ASSERT(wave_y != 0.0, "wave_y scales the stream function and must not be zero");
}

StreamFunctionField StreamFunctionField::of(ManufacturedSolution solution) {
  constexpr Real pi = std::numbers::pi;
  if (solution == ManufacturedSolution::Extension) return {1.0, 0.0, pi, 2 * pi};
  return {1.0, 0.25, pi, 2 * pi};
}

Real StreamFunctionField::psi(int m, int n, const Point<2>& x) const {
  FF_ASSERT(m >= 0 && n >= 0 && m + n <= 3, "stream-function derivative order");
  // c·x·y: its derivatives up to order 3.
  Real value = 0.0;
  if (m == 0 && n == 0) value = x.x() * x.y();
  if (m == 1 && n == 0) value = x.y();
  if (m == 0 && n == 1) value = x.x();
  if (m == 1 && n == 1) value = 1.0;
  value *= extension_;
  // d^m/dx^m sin(k x) = k^m sin(k x + m π/2).
  const Real half_pi = std::numbers::pi / 2;
  const Real sx = std::pow(wave_x_, m) * std::sin(wave_x_ * x.x() + m * half_pi);
  const Real sy = std::pow(wave_y_, n) * std::sin(wave_y_ * x.y() + n * half_pi);
  return value + amplitude_ / wave_y_ * sx * sy;
}

Point<2> StreamFunctionField::velocity(const Point<2>& x) const {
  return Point<2>(psi(0, 1, x), -psi(1, 0, x));
}

Tensor2<2> StreamFunctionField::gradient(const Point<2>& x) const {
  Tensor2<2> g;
  g << psi(1, 1, x), psi(0, 2, x), //  ∂(ψ_y)/∂x, ∂(ψ_y)/∂y
      -psi(2, 0, x), -psi(1, 1, x);
  return g;
}

std::array<Tensor2<2>, 2> StreamFunctionField::hessians(const Point<2>& x) const {
  Tensor2<2> h0, h1;
  h0 << psi(2, 1, x), psi(1, 2, x), psi(1, 2, x), psi(0, 3, x);
  h1 << -psi(3, 0, x), -psi(2, 1, x), -psi(2, 1, x), -psi(1, 2, x);
  return {h0, h1};
}

template <int dim>
Point<dim> viscous_body_force(const FlowLaw& law, const Tensor2<dim>& gradient,
                              const std::array<Tensor2<dim>, dim>& hessian) {
  const Tensor3 rate = strain_rate<dim>(gradient);
  const Tensor3 dev = deviator(rate);
  const Real rate_bar = equivalent_strain_rate(rate);
  FF_ASSERT(rate_bar > 0, "the manufactured field must have a positive equivalent strain rate");

  // ν = σ_p/ε̄̇ and dν/dε̄̇ = (σ_p′ ε̄̇ − σ_p)/ε̄̇².
  const Real viscosity = law.secant_viscosity(rate_bar);
  const Real viscosity_slope =
      (law.yield_stress_derivative(rate_bar) * rate_bar - law.yield_stress(rate_bar)) /
      (rate_bar * rate_bar);
  Point<dim> force = Point<dim>::Zero();
  for (int k = 0; k < dim; ++k) {
    // ∂_k ε̇_ij = ½(∂_j∂_k u_i + ∂_i∂_k u_j); ∂_k ε̄̇ = ⅔ ė:∂_k ė / ε̄̇.
    Tensor3 rate_k = Tensor3::Zero();
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) rate_k(i, j) = 0.5 * (hessian[i](j, k) + hessian[j](i, k));
    const Real rate_bar_k = 2.0 / 3.0 * dev.cwiseProduct(deviator(rate_k)).sum() / rate_bar;
    // f_i = −∂_k τ_ik, τ = ⅔ ν ε̇.
    for (int i = 0; i < dim; ++i)
      force[i] -=
          2.0 / 3.0 * (viscosity_slope * rate_bar_k * rate(i, k) + viscosity * rate_k(i, k));
  }
  return force;
}

Point<2> manufactured_body_force(const FlowLaw& law, const StreamFunctionField& field,
                                 const Point<2>& x) {
  return viscous_body_force<2>(law, field.gradient(x), field.hessians(x));
}

template Point<2> viscous_body_force<2>(const FlowLaw&, const Tensor2<2>&,
                                        const std::array<Tensor2<2>, 2>&);
template Point<3> viscous_body_force<3>(const FlowLaw&, const Tensor2<3>&,
                                        const std::array<Tensor2<3>, 3>&);

} // namespace formflow::physics
