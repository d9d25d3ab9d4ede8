// SPDX-License-Identifier: MIT
// The global saddle-point system of the mixed problem (3.7) with a global pressure
// (Taylor–Hood Q2–Q1, issue 5; or a discontinuous pressure kept as a saddle point,
// issue 20): velocity and pressure solved together.
#pragma once

#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/forming_problem.hpp"

#include <utility>
#include <vector>

namespace formflow::assembly {

/// [A  Bᵀ; B  −d M] [u; δp] = [F; −B_c u_c + d M p] on the free velocity dofs and
/// all pressure dofs, with A the secant velocity matrix of one iteration
/// (viscous, contact and friction terms: FormingProblem::assemble), B_ia =
/// ∫ ψ_i div φ_a dx, M_ij = ∫ ψ_i ψ_j dx, p the current pressure (its load −Bᵀp is
/// already in F) and δp its correction. For d > 0 the matrix is symmetric
/// quasi-definite, for d = 0 a saddle point. The full matrix (both triangles)
/// keeps one pattern: B and M are built once, A's values are copied into fixed
/// slots per iteration; a back-end that takes the blocks apart never has it built.
///
/// Null mode: with d = 0 the constant pressure is in the kernel of Bᵀ when every
/// boundary velocity is prescribed (∫ div φ_a = ∮ φ_a·n vanishes for every free
/// dof). Then the first pressure dof (a vertex value, or cell 0's constant
/// coefficient) is pinned (row and column replaced by the identity) and every
/// solution is shifted to zero mean, ∫ p dx = 0.
/// The benchmark has free surfaces and Γ3 is not prescribed: no pin there.
///
/// In a distributed run (a discontinuous pressure only) the matrix and the right-hand
/// side are this rank's share: A's share, and B, Bᵀ, −dM and the pressure rows' loads of
/// the own cells (assembled_cells); the pin, the null-mode decision and the zero-mean
/// shift are taken from every cell alike on every rank.
template <int dim> class SaddlePointSystem {
public:
  /// `multipliers` must have a global pressure.
  SaddlePointSystem(const FormingProblem<dim>& problem,
                    const ConstraintMultipliers<dim>& multipliers);

  /// Copies the assembled velocity matrix (lower triangle) into the full matrix, made
  /// with the velocity matrix's pattern at the first call. Only a back-end that takes the
  /// whole matrix needs it (LinearSolver::take_saddle_point_blocks).
  void fill_matrix(const LinearSystem& velocity);
  /// B on the free velocity dofs as the whole matrix has it (the pinned row empty), and
  /// the pressure block C (−d M, the pin's 1): the fixed blocks of [A Bᵀ; B C] for a
  /// back-end that takes them apart.
  SparseMatrix coupling() const;
  SparseMatrix pressure_block() const;
  /// The right-hand side for the current pressure `pressure` (vertex values).
  VectorX rhs(const LinearSystem& velocity, const VectorX& pressure) const;
  /// Moves the pressure `increment`'s load −Bᵀ δp into `velocity` (rhs and the
  /// loads of the prescribed rows), so that its reactions are those of p + δp.
  void add_pressure_load(const VectorX& increment, LinearSystem& velocity) const;
  /// Shifts `pressure` to zero mean when the constant is a null mode; else unchanged.
  void fix_pressure_level(VectorX& pressure) const;
  /// The Schur-complement preconditioner of this step, −(M_η + d M) with M_η =
  /// ∫ ψ_i ψ_j/(2η) dx at the last assembly's secant viscosities: spectrally equivalent
  /// to S = −(d M + B A⁻¹ Bᵀ) with constants that depend on the inf-sup constant and
  /// not on the viscosity contrast or h (both parts of S scale with 1/η and d cell
  /// by cell). n_p × n_p; for a discontinuous pressure block diagonal in cell blocks
  /// of pressure_block_size(). A pinned dof has a 1 on its diagonal, as in the matrix.
  SparseMatrix schur_preconditioner() const;
  /// The cell block size of schur_preconditioner() (n_p per cell) for a discontinuous
  /// pressure; 0 for a continuous one (vertex dofs couple neighbouring cells).
  Index pressure_block_size() const;

  /// The whole matrix of the last fill_matrix.
  const SparseMatrix& matrix() const { return matrix_; }
  Index n_velocity() const { return n_velocity_; }
  Index n_pressure() const { return n_pressure_; }
  bool has_pinned_pressure() const { return pinned_; }

private:
  /// The whole matrix's pattern (A's from `lower`, A's lower triangle), the slots of B's
  /// and A's entries in it.
  void build_whole_matrix(const SparseMatrix& lower);
  Index slot(Index row, Index column) const;

  const FormingProblem<dim>& problem_;
  const ConstraintMultipliers<dim>& multipliers_;
  Index n_velocity_ = 0, n_pressure_ = 0;
  Real d_ = 0.0;
  bool pinned_ = false;
  bool distributed_ = false;     ///< this rank's share: own cells' B, M and loads (issue 20)
  bool pin_here_ = false;        ///< the pin's identity entry is in this rank's share
  SparseMatrix divergence_free_; ///< B on the free velocity dofs, n_p × n_free
  SparseMatrix
      divergence_prescribed_; ///< B on the prescribed dofs, n_p × n_dofs (other columns empty)
  SparseMatrix mass_;         ///< M, n_p × n_p
  VectorX constant_;          ///< the coefficients of p ≡ 1
  VectorX pressure_weights_;  ///< ∫ ψ_i dx
  SparseMatrix matrix_;       ///< the full saddle-point matrix
  /// B, Bᵀ, −dM (and the pin): (slot in matrix_, value) of each entry. A list, not a
  /// values array of matrix_'s size: B and M hold few of the saddle point's nonzeros
  /// (3D Q2–P1disc at h = 0.125: 64 MB saved).
  std::vector<std::pair<Index, Real>> fixed_entries_;
  std::vector<Index> lower_slot_, upper_slot_; ///< per value of A's lower triangle (−1: diagonal)
};

} // namespace formflow::assembly
