// SPDX-License-Identifier: MIT
// Which coordinate axis a boundary facet is normal to (symmetry planes).
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <optional>

namespace formflow::mesh {

/// The axis (0 = x, 1 = y, 2 = z) normal to `facet` when the facet lies in a
/// coordinate plane: every node of it has the same coordinate along that axis,
/// to within 1e-9 of the facet's extent (rounding in a generator or a .msh file,
/// never a real tilt); std::nullopt for a tilted or curved facet.
template <int dim>
std::optional<int> facet_normal_axis(const Mesh<dim>& mesh, const BoundaryFacet& facet);

} // namespace formflow::mesh
