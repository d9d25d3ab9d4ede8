// SPDX-License-Identifier: MIT
// Initialising and finalising Gmsh exactly once per scope.
#include "formflow/mesh/gmsh_session.hpp"

#include "formflow/core/error.hpp"

#include <gmsh.h>

#include <atomic>

namespace formflow::mesh {

namespace {

// Gmsh's API works on one global model store; this flag refuses a second
// session instead of letting two users corrupt each other's model.
std::atomic<bool> session_open{false};

} // namespace

GmshSession::GmshSession(bool verbose) {
  if (session_open.exchange(true))
    throw InternalError("a Gmsh session is already open (Gmsh has one global state)");
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
  // Errors throw (as std::string) instead of being only logged.
  gmsh::option::setNumber("General.AbortOnError", 2);
  // Gmsh 4.8 has no option that stops a script it opens from running shell
  // commands (SystemCall) or writing files: a user's file therefore never
  // reaches Gmsh, only a checked private copy (mesh/msh_file.hpp).
}

GmshSession::~GmshSession() {
  gmsh::finalize();
  session_open = false;
}

} // namespace formflow::mesh
