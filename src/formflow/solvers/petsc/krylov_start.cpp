// SPDX-License-Identifier: MIT
// The guess and the inexact tolerance of an iterative PETSc solve.
#include "formflow/solvers/petsc/krylov_start.hpp"

#include <algorithm>

namespace formflow::solvers::petsc {

bool is_iterative(KSP ksp) {
  KSPType type = nullptr;
  KSPGetType(ksp, &type);
  PetscBool preonly = PETSC_FALSE;
  PetscStrcmp(type, KSPPREONLY, &preonly);
  return !preonly;
}

std::optional<VectorX> KrylovStart::take_guess(Index size) {
  std::optional<VectorX> guess;
  if (guess_.size() == size) guess = std::move(guess_);
  guess_.resize(0);
  return guess;
}

bool KrylovStart::inexact_allowed(KSP ksp) {
  if (inexact_allowed_) return *inexact_allowed_;
  if (!ksp) return true; // decided at the first factorisation
  PetscBool wanted = PETSC_TRUE, given = PETSC_FALSE;
  PetscOptionsGetBool(nullptr, nullptr, "-formflow_inexact_steps", &wanted, &given);
  inexact_allowed_ = is_iterative(ksp) && wanted;
  return *inexact_allowed_;
}

void KrylovStart::apply_tolerance(KSP ksp, Mat matrix, Vec rhs, Vec solution, bool guessed) {
  PetscReal rtol = 0, abstol = 0, dtol = 0;
  PetscInt max_iterations = 0;
  KSPGetTolerances(ksp, &rtol, &abstol, &dtol, &max_iterations);
  if (own_tolerance_ <= 0) own_tolerance_ = rtol;
  Real wanted = own_tolerance_;
  if (asked_reduction_ > 0 && inexact_allowed(ksp)) {
    PetscReal rhs_norm = 0, start_norm = 0;
    VecNorm(rhs, NORM_2, &rhs_norm);
    start_norm = rhs_norm;
    if (guessed) {
      Vec residual = nullptr;
      VecDuplicate(rhs, &residual);
      MatMult(matrix, solution, residual);
      VecAYPX(residual, -1.0, rhs); // b − A x₀
      VecNorm(residual, NORM_2, &start_norm);
      VecDestroy(&residual);
    }
    if (rhs_norm > 0) wanted = std::max(wanted, asked_reduction_ * start_norm / rhs_norm);
  }
  if (wanted != rtol) KSPSetTolerances(ksp, wanted, abstol, dtol, max_iterations);
}

} // namespace formflow::solvers::petsc
