// SPDX-License-Identifier: MIT
// How the plane die channel becomes a solid one (geometry.dimension = 3).
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/mesh/profile_die.hpp"

namespace formflow::mesh {

/// The cross-section of a three-dimensional channel (quarter models: symmetry
/// planes y = 0 and z = 0).
enum class ChannelSection {
  /// The plane channel extruded over z ∈ [0, thickness], u_z = 0 on both z faces:
  /// plane strain posed in 3D (SPEC §6).
  Slab,
  /// A rectangular container and exit (half widths in z), square or wedge die.
  Rectangle,
  /// A round billet (radius = the half heights) through a square or conical die.
  Round,
  /// A round billet through a flat die with the opening of a product's outline and its
  /// bearing, then the free extrudate (mesh/profile_die.hpp); built by Gmsh in tetrahedra.
  Profile,
};

/// The geometry.* keys of a solid channel beyond the plane profile (ChannelGeometry,
/// whose x lengths and y half heights keep their meaning in 3D).
struct SolidChannel {
  ChannelSection section = ChannelSection::Slab;
  Real thickness = 1.0;         ///< slab: extent in z
  Real entry_half_width = 10.0; ///< rectangle: half width (z) of the container
  Real exit_half_width = 5.0;   ///< rectangle, round + square die: half width (z) of the product
  ProfileDie profile;           ///< profile: outline, symmetry, billet, bearing
};

} // namespace formflow::mesh
