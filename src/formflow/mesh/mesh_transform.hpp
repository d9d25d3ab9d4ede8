// SPDX-License-Identifier: MIT
// Rigid transformations of a mesh (for the invariance tests of the verification suite).
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// The mesh moved by `shift`; connectivity and labels unchanged.
template <int dim> Mesh<dim> translated(const Mesh<dim>& mesh, const Point<dim>& shift);

/// The mirror image x_axis → −x_axis. The local node order of every cell is
/// reversed along `axis` (and the two faces normal to it swapped) so that the
/// cells keep a positive Jacobian; labels stay with their facets.
template <int dim> Mesh<dim> mirrored(const Mesh<dim>& mesh, int axis);

} // namespace formflow::mesh
