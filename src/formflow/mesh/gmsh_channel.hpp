// SPDX-License-Identifier: MIT
// The extrusion channel built and meshed with the Gmsh API (unstructured quadrilaterals).
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/die_face.hpp"
#include "formflow/mesh/gmsh_session.hpp"

#include <functional>
#include <utility>
#include <vector>

namespace formflow::mesh {

/// The half channel's geometry in Gmsh's built-in kernel (not yet synchronised):
/// its plane surface and, in the order of the surface's curve loop (symmetry,
/// front, free exit, die, container, rear), each part's curves.
struct ChannelModel {
  int surface = 0;
  std::vector<std::pair<BoundaryLabel, std::vector<int>>> parts;
};

/// Adds the geometry of build_channel_model to the current model, for it and for
/// the solid channels that extrude it (mesh/gmsh_solid_channel.hpp).
ChannelModel add_channel_geometry(const ChannelGeometry& geometry,
                                  const std::vector<Point<2>>& die_face, Real size);

/// Gmsh's options for recombined quadrilaterals of target size `size` (and, with
/// setOrder(2), complete quad-9/hexa-27 elements).
void set_recombined_quadrilateral_options(Real size);

/// Gmsh's options for Frontal-Delaunay triangles (and, extruded, tetrahedra) of target size
/// `size`, complete second order with setOrder(2).
void set_triangle_options(Real size);

/// Adds the half channel to the current model of `session` and meshes it with
/// recombined quadrilaterals (Gmsh's Frontal-Delaunay, then blossom full-quad
/// recombination) of target size `size`, of `order` 1 (quad-4) or 2 (quad-9).
/// `die_face` is a polyline from (L_c, H_in) down to (x_d, H_out), the start of
/// the exit; the exit runs to x_d + L_e. Any die profile enters only here,
/// so a wedge or curved die is another `die_face`. Physical curve groups carry
/// the part names (label_name); the surface is the physical group "domain",
/// so that a written .msh keeps its elements. `size_field`, if given, runs in
/// the session just before meshing, to replace the uniform size by a field
/// (mesh/gmsh_sized_channel.hpp). `shape`: recombined quadrilaterals, or Gmsh's
/// Frontal-Delaunay triangles as they are.
void build_channel_model(const GmshSession& session, const ChannelGeometry& geometry,
                         const std::vector<Point<2>>& die_face, Real size, int order,
                         const std::function<void()>& size_field = {},
                         CellShape shape = CellShape::Cube);

/// The channel with `die_face`, meshed by Gmsh, as a formflow mesh.
Mesh<2> make_gmsh_channel_mesh(const ChannelGeometry& geometry,
                               const std::vector<Point<2>>& die_face, Real size, int order,
                               CellShape shape = CellShape::Cube);

/// The channel of `geometry` (any die shape, with its land), meshed by Gmsh.
inline Mesh<2> make_gmsh_channel_mesh(const ChannelGeometry& geometry, Real size, int order) {
  return make_gmsh_channel_mesh(geometry, die_face_polyline(geometry, size), size, order);
}

} // namespace formflow::mesh
