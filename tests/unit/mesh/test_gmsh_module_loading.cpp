// SPDX-License-Identifier: MIT
// Gmsh is a module opened on first use (mesh/gmsh_meshers.hpp): a process that makes
// structured meshes never maps Gmsh's libraries, and the first Gmsh mesh loads it.
#include "formflow/mesh/channel_mesh.hpp"

#if FORMFLOW_WITH_GMSH
#include "formflow/mesh/die_face.hpp"
#include "formflow/mesh/gmsh_meshers.hpp"
#endif

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace formflow::mesh {
namespace {

/// The shared objects mapped into this process (/proc/self/maps).
std::string mapped_objects() {
  std::ifstream maps("/proc/self/maps");
  std::ostringstream text;
  text << maps.rdbuf();
  return text.str();
}

#if FORMFLOW_WITH_GMSH
// One test, in order: this executable links the library only, so before any Gmsh mesh
// neither Gmsh nor the module may be mapped (linking Gmsh into the library again would
// cost every process its ~90 libraries' load time, docs/architecture.md "Building").
TEST(GmshModuleLoading, OnlyTheFirstGmshMeshMapsGmsh) {
  const ChannelGeometry geometry;
  const Mesh<2> structured = make_channel_mesh(geometry, 2.5, 2);
  EXPECT_GT(structured.n_cells(), 0);
  const std::string before = mapped_objects();
  EXPECT_EQ(before.find("libgmsh"), std::string::npos) << "Gmsh mapped before any Gmsh mesh";
  EXPECT_EQ(before.find("libformflow_gmsh"), std::string::npos);

  const Mesh<2> unstructured = gmsh_meshers().channel_mesh(
      geometry, die_face_polyline(geometry, 2.5), 2.5, 2, CellShape::Cube);
  EXPECT_GT(unstructured.n_cells(), 0);
  const std::string after = mapped_objects();
  EXPECT_NE(after.find("libformflow_gmsh"), std::string::npos);
  EXPECT_NE(after.find("libgmsh"), std::string::npos);
}
#endif

} // namespace
} // namespace formflow::mesh
