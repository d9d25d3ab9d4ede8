// SPDX-License-Identifier: MIT
// Gmsh's meshers, loaded on first use from formflow's Gmsh module.
#pragma once

#include "formflow/mesh/cad_file.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/gmsh_mesh.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/mesh/profile_die.hpp"
#include "formflow/mesh/solid_channel.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace formflow::mesh {

/// What the library asks of Gmsh: the entry points of the module libformflow_gmsh.so
/// (mesh/gmsh_meshers_entry.cpp), each the function of the same name in the
/// mesh/gmsh_*.hpp headers. Gmsh with OpenCASCADE and its ~90 shared libraries is
/// linked into that module, not into the library: loading them costs every process
/// 0.13 s of CPU (the dynamic loader's symbol lookups) before main, which most runs
/// (structured meshes) and most test processes never need.
struct GmshMeshers {
  std::size_t size = sizeof(GmshMeshers); ///< the module's view of this struct (checked)
  Mesh<2> (*channel_mesh)(const ChannelGeometry& geometry, const std::vector<Point<2>>& die_face,
                          Real size, int order, CellShape shape) = nullptr;
  Mesh<2> (*sized_channel_mesh)(const ChannelGeometry& geometry,
                                const std::vector<Point<2>>& die_face, const Mesh<2>& background,
                                const VectorX& node_sizes, int order) = nullptr;
  Mesh<3> (*solid_channel_mesh)(const ChannelGeometry& geometry, const SolidChannel& solid,
                                Real size, int order, bool drawing, CellShape shape) = nullptr;
  Mesh<3> (*profile_die_mesh)(const ChannelGeometry& geometry, const ProfileDie& die, Real size,
                              Real bearing_size, int order) = nullptr;
  Mesh<3> (*cad_mesh)(const std::string& path, CadFormat format,
                      const std::vector<PhysicalBoundary>& boundaries, Real size,
                      int order) = nullptr;
  Mesh<2> (*read_mesh)(const std::string& path, const std::vector<PhysicalBoundary>& boundaries,
                       int order, CellShape shape) = nullptr;
  Mesh<3> (*read_solid_mesh)(const std::string& path,
                             const std::vector<PhysicalBoundary>& boundaries, int order,
                             CellShape shape) = nullptr;
};

/// The module's entry points, loaded on the first call (thread-safe) from the path
/// the build wrote into the library (never from a path the user or the environment
/// supplies). Throws InternalError naming the module and the loader's message when
/// it cannot be loaded: the build is incomplete, not the user's input.
const GmshMeshers& gmsh_meshers();

/// Starts loading the module on a thread of its own, once per process, and returns at
/// once: a run that will need Gmsh later (an adaptive run's first remesh) finds it
/// loaded, the dynamic loader's 0.4 s spent beside the first solve instead of in front
/// of the remesh. A failure there is left for gmsh_meshers() to report when called.
/// The process waits for the load at exit.
void preload_gmsh_meshers();

/// The name of the module's one exported function, which returns its GmshMeshers.
inline constexpr const char* gmsh_meshers_symbol = "formflow_gmsh_meshers";

} // namespace formflow::mesh
