// SPDX-License-Identifier: MIT
// How a nonlinear loop hands exact friction's multipliers to the assembly and
// lets an outer loop update them between its iterations.
#pragma once

#include "formflow/assembly/friction_multipliers.hpp"
#include "formflow/core/types.hpp"

#include <functional>

namespace formflow::solvers {

/// Exact Coulomb friction inside the Newton loop (solvers/augmented_newton.hpp):
/// `multipliers` λ̂ are frozen during each iteration (its assembly and line
/// search); after the iteration, `after_iteration(velocity)` may update them and
/// says whether they have settled. The loop stops as converged only
/// when its own change is below δ and they have settled.
template <int dim> struct FrictionMultiplierHook {
  const assembly::FrictionMultipliers<dim>* multipliers = nullptr;
  std::function<bool(const VectorX& velocity)> after_iteration;
};

} // namespace formflow::solvers
