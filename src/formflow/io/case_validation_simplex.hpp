// SPDX-License-Identifier: MIT
// What a case of triangles or tetrahedra can run, and the defaults the cell shape sets.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/io/case_validation_3d.hpp"

#include <functional>
#include <optional>
#include <string>

namespace formflow::io {

/// Defaults that follow mesh.cell when the user left them unset (`is_set` tells): the
/// cell is the hexahedron of geometry.dimension = 3; on triangles and tetrahedra the
/// element is P2, the formulation mixed (the penalty method on simplices is the mixed
/// formulation with d > 0, its pressure condensed per cell), and P1b's pressure P1.
void resolve_cell_defaults(Case& case_, const std::function<bool(const std::string&)>& is_set);

/// Why `case_`'s cells, element and pressure do not go together, or what simplices do
/// not run yet; std::nullopt when they are fine. Checked after resolve_cell_defaults.
std::optional<KeyRefusal> cell_case_problem(const Case& case_,
                                            const std::function<bool(const std::string&)>& is_set);

/// The cells the velocity element and pressure of `case_` need (fem/element_choice.hpp).
mesh::CellType case_cell_type(const Case& case_);

} // namespace formflow::io
