// SPDX-License-Identifier: MIT
// How a copy of formflow's matrix into PETSc's went (SequentialSystem, DistributedSystem).
#pragma once

namespace formflow::solvers::petsc {

/// The values handed over on the same pattern; the matrix made anew (the first copy, or
/// a pattern changed: what was built on the old rows must be made again); or PETSc
/// refused (no matrix).
enum class CopyOutcome { values, rebuilt, refused };

} // namespace formflow::solvers::petsc
