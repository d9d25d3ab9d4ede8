// SPDX-License-Identifier: MIT
// The case seen by the capability table (solvers/capabilities.hpp).
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/solvers/capabilities.hpp"

#include <optional>
#include <string>

namespace formflow::io {

/// What of `case_` decides the nonlinear loop: formulation, exact constraints,
/// friction enforcement (as stick_choice resolves it), symmetry, method and linear solver.
solvers::ProblemShape problem_shape(const Case& case_);

/// friction.stick and contact.normals as the run uses them. friction.stick = "auto" (the
/// default) is "exact" where the semismooth Newton serves the case (the exact law under a
/// Newton loop) unless contact.normals = "faces" was given, which is honoured with the
/// augmented loop; "augmented" elsewhere. contact.normals not given follows the stick:
/// nodes for exact stick (one multiplier per Γ3 node), else the key's value. What the
/// user gave is never overridden: a conflicting explicit pair is refused by
/// solvers::choose_loop.
struct StickChoice {
  StickEnforcement stick = StickEnforcement::Augmented; ///< never Auto
  assembly::ContactNormals normals = assembly::ContactNormals::Faces;
  bool stick_given = false;   ///< friction.stick was set (not "auto")
  bool normals_given = false; ///< contact.normals was set (key_locations)
};
StickChoice stick_choice(const Case& case_);

/// friction.stick = "auto" with contact.normals = "faces" given where the semismooth
/// Newton would serve: the faces are honoured and the augmented loop runs; the warning
/// ("file:line: ...") that says so, or none.
std::optional<std::string> face_points_note(const Case& case_);

/// The case's contact settings with the normals stick_choice resolved.
assembly::ContactSettings contact_settings(const Case& case_);

} // namespace formflow::io
