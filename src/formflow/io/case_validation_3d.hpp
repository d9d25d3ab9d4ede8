// SPDX-License-Identifier: MIT
// What a three-dimensional case can run, and the solid-channel keys a case must not set in vain.
#pragma once

#include "formflow/io/case.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace formflow::io {

/// A combination of keys that is refused: the keys involved (the case validation
/// blames the one set last), what is wrong and what would run.
struct KeyRefusal {
  std::vector<std::string> keys;
  std::string message, hint;
};

/// Why `case_` cannot run as its geometry.dimension asks: a solid-channel key
/// (geometry.section, .thickness, .entry_half_width, .exit_half_width) set to a
/// value other than its default where it has no effect, or a three-dimensional case with what 3D
/// does not run yet (Gmsh meshes of some sections, the axisymmetric model), a rectangle
/// whose half widths do not fit, or a round billet's square-die exit that does not fit
/// inside its circle. `is_set(name)` tells whether the user gave
/// the key (a key left at its default is never the one to blame).
/// std::nullopt when the case is fine.
std::optional<KeyRefusal> solid_case_problem(const Case& case_,
                                             const std::function<bool(const std::string&)>& is_set);

} // namespace formflow::io
