// SPDX-License-Identifier: MIT
// The Gmsh module's one exported function (mesh/gmsh_meshers.hpp): its entry points.
#include "formflow/mesh/gmsh_cad_die.hpp"
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/mesh/gmsh_meshers.hpp"
#include "formflow/mesh/gmsh_profile_die.hpp"
#include "formflow/mesh/gmsh_sized_channel.hpp"
#include "formflow/mesh/gmsh_solid_channel.hpp"
#include "formflow/mesh/gmsh_solid_mesh.hpp"

namespace {

formflow::mesh::Mesh<2> channel_mesh(const formflow::mesh::ChannelGeometry& geometry,
                                     const std::vector<formflow::Point<2>>& die_face,
                                     formflow::Real size, int order,
                                     formflow::mesh::CellShape shape) {
  return formflow::mesh::make_gmsh_channel_mesh(geometry, die_face, size, order, shape);
}

} // namespace

extern "C" __attribute__((visibility("default"))) const formflow::mesh::GmshMeshers*
formflow_gmsh_meshers() {
  namespace mesh = formflow::mesh;
  static const mesh::GmshMeshers meshers = [] {
    mesh::GmshMeshers entries;
    entries.channel_mesh = &channel_mesh;
    entries.sized_channel_mesh = &mesh::make_sized_gmsh_channel_mesh;
    entries.solid_channel_mesh = &mesh::make_gmsh_solid_channel_mesh;
    entries.profile_die_mesh = &mesh::make_gmsh_profile_die_mesh;
    entries.cad_mesh = &mesh::make_gmsh_cad_mesh;
    entries.read_mesh = &mesh::read_gmsh_mesh;
    entries.read_solid_mesh = &mesh::read_gmsh_solid_mesh;
    return entries;
  }();
  return &meshers;
}
