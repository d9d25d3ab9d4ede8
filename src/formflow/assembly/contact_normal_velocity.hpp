// SPDX-License-Identifier: MIT
// The Γ3 nodes' normal velocity carried from one mesh to another with it, so that a
// velocity interpolated onto a finer mesh does not read as a contact pressure it never
// had (issue 20: the 3D coarse start's first fine step).
#pragma once

#include "formflow/assembly/discretisation.hpp"

namespace formflow::assembly {

/// u·n at every Γ3 node (n the node's unit normal, contact_node_normals), 0 at every
/// other node: a nodal scalar field of `discretisation`'s mesh, for
/// fem::interpolate_nodal_field.
template <int dim>
VectorX contact_normal_velocity(const Discretisation<dim>& discretisation, const VectorX& velocity);

/// Sets u·n at every Γ3 node of `discretisation` to `normal_velocity` (a nodal field of
/// its mesh, as contact_normal_velocity gives it) by moving the node's free velocity
/// components along the normal's free part; the prescribed components keep their values.
///
/// Why: the penalty reads the contact pressure from the normal velocity, σ_N = −u_N/d_N
/// with d_N = 1e-6 by default, so u_N carries σ_N at a scale of 1e-6. A velocity
/// interpolated from a coarser mesh onto a curved die (the 3D round die: the coarse
/// faces are other surfaces than the fine ones) gets a normal part of the tangential
/// velocity times the normals' difference, 1e-3–1e-2, which the penalty reads as a
/// contact pressure 10³–10⁴ times too large, and the nonlocal Coulomb threshold with it:
/// the first fine step then sticks on the whole die (3D round quarter at h = 0.25, μ =
/// 0.05: ram reaction 10.9 against 2.05). Carrying u_N over as a scalar keeps the coarse
/// solution's contact pressure instead.
template <int dim>
void set_contact_normal_velocity(const Discretisation<dim>& discretisation,
                                 const VectorX& normal_velocity, VectorX& velocity);

} // namespace formflow::assembly
