// SPDX-License-Identifier: MIT
// Scoped use of the Gmsh library, whose state is global to the process.
#pragma once

#include <stdexcept>
#include <string>

namespace formflow::mesh {

/// A failure reported by Gmsh itself (it throws its last error message as a
/// std::string); `what()` is that message.
struct GmshFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Initialises Gmsh on construction and finalises it on destruction, so no
/// model, option or log outlives the scope. Gmsh keeps one global state per
/// process: at most one session may be open at a time (a second one throws
/// InternalError). Configuration files (gmshrc) are not read, so a run does
/// not depend on the user's Gmsh settings; nothing is printed unless
/// `verbose` (General.Terminal).
class GmshSession {
public:
  explicit GmshSession(bool verbose = false);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// Runs `action` (Gmsh API calls) and turns Gmsh's own exceptions (thrown as
  /// std::string) into GmshFailure carrying Gmsh's message.
  template <class Action> decltype(auto) call(Action&& action) const {
    try {
      return action();
    } catch (const std::string& message) {
      throw GmshFailure(message);
    }
  }
};

} // namespace formflow::mesh
