// SPDX-License-Identifier: MIT
// The solve plan of a case, from the capability table.
#include "formflow/app/solve_plan.hpp"

namespace formflow::app {

std::string SolvePlan::name(bool coarse_start_ran) const {
  std::string text = solvers::loop_name(loop, shape);
  if (coarse_start_ran) text += " from coarse meshes";
  return text;
}

} // namespace formflow::app
