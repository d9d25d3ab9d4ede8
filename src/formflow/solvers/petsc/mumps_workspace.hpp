// SPDX-License-Identifier: MIT
// MUMPS sizes its working arrays at the analysis from an estimate plus ICNTL(14) per
// cent; with pivots delayed during the numerical factorisation (a distributed Cholesky
// of a nearly singular velocity block does) the estimate can be short, and MUMPS stops
// with INFOG(1) = -8, -9 or -11 … -15 ("work array too small"). That is a sizing
// problem, not a property of the matrix: the factorisation is repeated with more room.
// PETSc's MUMPS factor never factorises again after a failure (its numerical phase
// returns at once while INFOG(1) < 0), so the retry needs a new factor, analysis and all.
#pragma once

#include <petscksp.h>

#include <optional>
#include <string>

namespace formflow::solvers::petsc {

/// Whether MUMPS' global status INFOG(1) says one of its work arrays was too small.
bool is_mumps_workspace_shortage(PetscInt infog1);

/// When `ksp`'s preconditioner is a MUMPS factorisation that stopped for want of work
/// space: the larger ICNTL(14) to factorise again with (twice the one used, at least
/// 40 %; MUMPS' default is 20). std::nullopt when there is nothing to retry (success,
/// not MUMPS, another failure). INFOG is the same on every rank, so every rank gets the
/// same answer.
std::optional<PetscInt> enlarged_mumps_relaxation(KSP ksp);

/// Sets one option in PETSc's options database while it lives and restores what was
/// there before (the user's own value, or nothing).
class ScopedPetscOption {
public:
  ScopedPetscOption(std::string name, const std::string& value);
  ~ScopedPetscOption();
  ScopedPetscOption(const ScopedPetscOption&) = delete;
  ScopedPetscOption& operator=(const ScopedPetscOption&) = delete;

private:
  std::string name_;
  std::optional<std::string> previous_;
};

} // namespace formflow::solvers::petsc
