// SPDX-License-Identifier: MIT
#include "formflow/solvers/petsc/mumps_workspace.hpp"

#include <petscmat.h>

#include <algorithm>
#include <array>

namespace formflow::solvers::petsc {

bool is_mumps_workspace_shortage(PetscInt infog1) {
  // MUMPS 5 user guide, "Error diagnostics": -8 (integer array IS), -9 (real array S),
  // -11 … -15 (the arrays of the solve phase, the Schur complement and the internal
  // work space of the factorisation) are all "too small, increase ICNTL(14)".
  return infog1 == -8 || infog1 == -9 || (infog1 <= -11 && infog1 >= -15);
}

namespace {

/// The MUMPS factor behind `ksp`'s preconditioner, or nullptr when it has none.
Mat mumps_factor(KSP ksp) {
  PC preconditioner = nullptr;
  if (KSPGetPC(ksp, &preconditioner) != 0) return nullptr;
  PetscBool cholesky = PETSC_FALSE, lu = PETSC_FALSE;
  PetscObjectTypeCompare(reinterpret_cast<PetscObject>(preconditioner), PCCHOLESKY, &cholesky);
  PetscObjectTypeCompare(reinterpret_cast<PetscObject>(preconditioner), PCLU, &lu);
  if (!cholesky && !lu) return nullptr;
  MatSolverType solver_type = nullptr;
  if (PCFactorGetMatSolverType(preconditioner, &solver_type) != 0 || solver_type == nullptr)
    return nullptr;
  PetscBool mumps = PETSC_FALSE;
  PetscStrcmp(solver_type, MATSOLVERMUMPS, &mumps);
  if (!mumps) return nullptr;
  Mat factor = nullptr;
  if (PCFactorGetMatrix(preconditioner, &factor) != 0) return nullptr;
  return factor;
}

} // namespace

std::optional<PetscInt> enlarged_mumps_relaxation(KSP ksp) {
  Mat factor = mumps_factor(ksp);
  if (factor == nullptr) return std::nullopt;
  PetscInt infog1 = 0;
  if (MatMumpsGetInfog(factor, 1, &infog1) != 0 || !is_mumps_workspace_shortage(infog1))
    return std::nullopt;
  PetscInt relaxation = 0;
  MatMumpsGetIcntl(factor, 14, &relaxation);
  return std::max<PetscInt>(2 * relaxation, 40);
}

ScopedPetscOption::ScopedPetscOption(std::string name, const std::string& value)
    : name_(std::move(name)) {
  std::array<char, 256> earlier{};
  PetscBool found = PETSC_FALSE;
  PetscOptionsGetString(nullptr, nullptr, name_.c_str(), earlier.data(), earlier.size(), &found);
  if (found) previous_ = std::string(earlier.data());
  PetscOptionsSetValue(nullptr, name_.c_str(), value.c_str());
}

ScopedPetscOption::~ScopedPetscOption() {
  if (previous_)
    PetscOptionsSetValue(nullptr, name_.c_str(), previous_->c_str());
  else
    PetscOptionsClearValue(nullptr, name_.c_str());
}

} // namespace formflow::solvers::petsc
