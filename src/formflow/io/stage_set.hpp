// SPDX-License-Identifier: MIT
// The case seen by the outer loops' composition table (solvers/stage_table.hpp).
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/solvers/stage_table.hpp"

namespace formflow::io {

/// Which outer loops `case_` asks for and what of its solve they depend on, for one
/// process (`ranks` = 1: the run plan sets the launcher's count).
solvers::StageSet stage_set(const Case& case_);

} // namespace formflow::io
