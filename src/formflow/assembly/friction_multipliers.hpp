// SPDX-License-Identifier: MIT
// The per-point friction multipliers λ_T of exact (non-regularised) Coulomb friction.
#pragma once

#include "formflow/core/types.hpp"

#include <vector>

namespace formflow::assembly {

/// Tangential friction tractions λ_T at the Γ3 quadrature points, in the order of
/// FormingProblem::contact_state (λ_T resists the slip: the traction on the
/// workpiece is σ_T = −λ_T). Handed to FormingProblem::assemble, they make the
/// friction of `friction.regularization = "none"` the Alart–Curnier law
/// λ = proj_{|λ| ≤ τ_f}(λ_T + r u_T), linearised as a load plus a penalty of at
/// most r; the augmented-Lagrangian loop (solvers/augmented_lagrangian.hpp)
/// updates them between inner solves, solvers/augmented_newton.hpp between Newton
/// iterations (FormingProblem::assemble_newton takes them too). An empty
/// `traction` means λ_T = 0.
template <int dim> struct FrictionMultipliers { std::vector<Point<dim>> traction; };

} // namespace formflow::assembly
