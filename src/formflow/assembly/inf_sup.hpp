// SPDX-License-Identifier: MIT
// The discrete inf-sup (LBB) constant β_h of a velocity/pressure pair (Remark 4.3).
#pragma once

#include "formflow/fem/pressure_space.hpp"
#include "formflow/mesh/mesh.hpp"

namespace formflow::assembly {

/// β_h = min_q max_v (q, div v) / (|v|_1 ‖q‖_0) over the mesh's velocity space
/// (all boundary nodes fixed: H¹₀) and the pressure space, q ⊥ the null modes.
struct InfSupEstimate {
  Real beta = 0.0;      ///< √ of the smallest eigenvalue of S q = λ M q above the null modes
  int n_null_modes = 0; ///< pressures with (q, div v) = 0 ∀v: the constant and spurious modes
  Index n_velocity_dofs = 0; ///< free velocity dofs
  Index n_pressure_dofs = 0; ///< pressure dofs (after the filter)
};

/// Dense generalised eigenproblem S q = λ M q with S = B A⁻¹ Bᵀ (A: vector
/// Laplacian, B_ia = (ψ_i, div φ_a), M: pressure mass): meant for small
/// meshes (a few thousand dofs). With `macro_filter` (P0 only), the local
/// checkerboard (+1 −1 / −1 +1) of every complete 2×2 macro-element of a
/// uniform mesh is removed from the pressure space (the macro-element filter of
/// Remark 4.3). Eigenvalues below 1e-10 × the largest count as null modes.
InfSupEstimate inf_sup_constant(const mesh::Mesh<2>& mesh, fem::PressureSpace space,
                                bool macro_filter = false);

/// Projects the local checkerboard mode out of every complete 2×2 macro-element
/// of a uniform square mesh of side `size` (cells grouped by their centres);
/// cells of incomplete macro-elements keep their values. `cell_values` is a P0 field.
VectorX filter_checkerboard(const mesh::Mesh<2>& mesh, Real size, const VectorX& cell_values);

} // namespace formflow::assembly
