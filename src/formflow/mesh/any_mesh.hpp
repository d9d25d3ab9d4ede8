// SPDX-License-Identifier: MIT
// A mesh of either dimension: what a mesh source produces before the run is typed on dim.
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <variant>

namespace formflow::mesh {

/// The mesh a case produced, plane (quadrilaterals) or solid (hexahedra). The
/// dimension is a property of the mesh, not of the code that made it: the
/// loader returns one of these and the run dispatches once on it (std::visit)
/// into code templated on dim.
using AnyMesh = std::variant<Mesh<2>, Mesh<3>>;

/// 2 or 3.
inline int dimension_of(const AnyMesh& mesh) {
  return mesh.index() == 0 ? 2 : 3;
}

} // namespace formflow::mesh
