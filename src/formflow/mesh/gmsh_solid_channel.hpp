// SPDX-License-Identifier: MIT
// Solid die channels (geometry.dimension = 3) built and meshed with the Gmsh API.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/mesh/solid_channel.hpp"

namespace formflow::mesh {

/// Whether Gmsh builds the solid channel of `solid` with `die` (mesh.source =
/// "gmsh"): the slab with every die, the rectangle with the square die, the profile
/// (mesh/gmsh_profile_die.hpp, its own builder). The
/// rectangle's other dies and the round section are not built by Gmsh
/// (io/case_validation_3d.cpp refuses them by key).
/// (Inline: the case validation asks it in builds without Gmsh too.)
inline bool gmsh_builds_solid_channel(const SolidChannel& solid, DieShape die) {
  return solid.section == ChannelSection::Slab || solid.section == ChannelSection::Profile ||
         (solid.section == ChannelSection::Rectangle && die == DieShape::Square);
}

/// The solid channel meshed by Gmsh in hexahedra of `order` (hexa-8 or hexa-27,
/// complete), target size `size`, labelled as make_solid_channel_mesh labels its
/// structured mesh:
/// * slab: the plane channel's recombined quadrilaterals (build_channel_model's
///   mesh) extruded over the thickness in extrusion_layers(thickness, size)
///   layers: each boundary curve's extruded surface keeps the curve's part, both
///   z faces are symmetry;
/// * rectangle, square die: the cross-section x = 0 in four rectangles (the
///   exit's [0, H_out] × [0, W_out], the rest of the container around it),
///   meshed with recombined quadrilaterals and extruded along x over L_c (the
///   container), the exit's rectangle then over the land and L_e: every
///   boundary surface is classified by where it lies (rear x = 0, die x = L_c
///   and the land, container y = H_in and z = W_in, free exit, front, symmetry
///   y = 0 and z = 0).
/// `drawing`: the container wall is free (Γ2). Gmsh chooses the cross-section's
/// cells, so the mesh is not the structured one; the x layers are round(L/size).
/// `shape` Simplex: those hexahedra cut into tetrahedra (split_into_tetrahedra, no bubbles).
Mesh<3> make_gmsh_solid_channel_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                     Real size, int order, bool drawing,
                                     CellShape shape = CellShape::Cube);

} // namespace formflow::mesh
