// SPDX-License-Identifier: MIT
// The vector-potential velocity field on the unit cube and its body force.
#include "formflow/physics/manufactured_3d.hpp"

#include <cmath>
#include <numbers>

namespace formflow::physics {

VectorPotentialField::VectorPotentialField(Real extension, Real amplitude, Real wave)
    : extension_(extension), amplitude_(amplitude), wave_(wave) {}

VectorPotentialField VectorPotentialField::of(ManufacturedSolution solution) {
  if (solution == ManufacturedSolution::Extension) return {1.0, 0.0, std::numbers::pi};
  return {1.0, 0.05, std::numbers::pi};
}

Real VectorPotentialField::phi(const std::array<int, 3>& order, const Point<3>& x) const {
  // d^m/dx^m sin(k x) = k^m sin(k x + m π/2).
  Real value = 1.0;
  for (int d = 0; d < 3; ++d)
    value *= std::pow(wave_, order[d]) * std::sin(wave_ * x[d] + order[d] * std::numbers::pi / 2);
  return value;
}

Real VectorPotentialField::velocity_derivative(int i, std::array<int, 3> order,
                                               const Point<3>& x) const {
  // curl (0, φ, φ) = (φ_y − φ_z, −φ_x, φ_x), times a/k.
  const auto with = [&](int axis) {
    std::array<int, 3> more = order;
    ++more[axis];
    return phi(more, x);
  };
  Real vortex = 0.0;
  if (i == 0) vortex = with(1) - with(2);
  if (i == 1) vortex = -with(0);
  if (i == 2) vortex = with(0);
  // c·(x, −y/2, −z/2): linear, so only its value and first derivative along x_i.
  const Real stretch = i == 0 ? 1.0 : -0.5;
  const int total = order[0] + order[1] + order[2];
  Real extension = 0.0;
  if (total == 0) extension = stretch * x[i];
  if (total == 1 && order[i] == 1) extension = stretch;
  return extension_ * extension + amplitude_ / wave_ * vortex;
}

Point<3> VectorPotentialField::velocity(const Point<3>& x) const {
  Point<3> u;
  for (int i = 0; i < 3; ++i) u[i] = velocity_derivative(i, {0, 0, 0}, x);
  return u;
}

Tensor2<3> VectorPotentialField::gradient(const Point<3>& x) const {
  Tensor2<3> g;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      std::array<int, 3> order{0, 0, 0};
      ++order[j];
      g(i, j) = velocity_derivative(i, order, x);
    }
  return g;
}

std::array<Tensor2<3>, 3> VectorPotentialField::hessians(const Point<3>& x) const {
  std::array<Tensor2<3>, 3> h;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        std::array<int, 3> order{0, 0, 0};
        ++order[j];
        ++order[k];
        h[i](j, k) = velocity_derivative(i, order, x);
      }
  return h;
}

Point<3> manufactured_body_force(const FlowLaw& law, const VectorPotentialField& field,
                                 const Point<3>& x) {
  return viscous_body_force<3>(law, field.gradient(x), field.hessians(x));
}

} // namespace formflow::physics
