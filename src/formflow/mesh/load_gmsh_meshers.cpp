// SPDX-License-Identifier: MIT
// Loading formflow's Gmsh module on first use (mesh/gmsh_meshers.hpp).
#include "formflow/mesh/gmsh_meshers.hpp"

#include "formflow/core/error.hpp"

#include <dlfcn.h>

#include <future>

namespace formflow::mesh {

namespace {

GmshMeshers load() {
  // The build's own module, by the absolute path CMake wrote (FORMFLOW_GMSH_MODULE):
  // no search path, no environment variable, so nothing else can be loaded in its place.
  void* module = dlopen(FORMFLOW_GMSH_MODULE, RTLD_NOW | RTLD_LOCAL);
  if (!module) {
    const char* reason = dlerror();
    throw InternalError(std::string("cannot load formflow's Gmsh module ") + FORMFLOW_GMSH_MODULE +
                        ": " + (reason ? reason : "unknown reason") +
                        " (rebuild formflow; it builds the module beside the library)");
  }
  using Entry = const GmshMeshers* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(module, gmsh_meshers_symbol));
  const GmshMeshers* meshers = entry ? entry() : nullptr;
  if (!meshers || meshers->size != sizeof(GmshMeshers))
    throw InternalError(std::string("formflow's Gmsh module ") + FORMFLOW_GMSH_MODULE +
                        " is not this build's (rebuild formflow)");
  return *meshers; // the module stays loaded for the process's lifetime
}

} // namespace

const GmshMeshers& gmsh_meshers() {
  static const GmshMeshers meshers = load();
  return meshers;
}

void preload_gmsh_meshers() {
  // The static's initialisation is thread-safe: a gmsh_meshers() call on another thread
  // meanwhile waits for this load instead of starting its own. The future's destructor
  // (at exit) joins the thread, so the process never unloads under a running dlopen.
  static const std::future<void> loading = std::async(std::launch::async, [] {
    try {
      gmsh_meshers();
    } catch (...) { // reported again, with its message, by the caller's own gmsh_meshers()
    }
  });
}

} // namespace formflow::mesh
