// SPDX-License-Identifier: MIT
// Pressure (hydrostatic stress σ_H) spaces of the mixed problem (SPEC §2, eq. 3.7).
#pragma once

#include "formflow/core/types.hpp"

#include <string_view>

namespace formflow::fem {

/// Pressure space paired with the velocity element (Remark 4.3):
/// - P0: one constant per cell (discontinuous);
/// - P1disc: 1, ξ, η (, ζ) per cell (discontinuous, linear);
/// - Q1disc: the bilinear/trilinear monomials per cell (discontinuous) — not a
///   case-file choice; it is the space for which reduced 2×2 integration of the
///   Q2 penalty term is exactly a mixed method (Remark 5.1), used in tests;
/// - Q1: continuous bilinear on the cell vertices (Taylor–Hood with Q2);
/// - P1: continuous linear on the vertices of triangles and tetrahedra (Taylor–Hood
///   with P2, the MINI element with P1b).
/// On simplices P1disc's monomials are those of the reference simplex (the whole P1).
/// The discontinuous bases are monomials in the reference coordinates ξ (a
/// "mapped" basis); on the affine cells of the channel mesh this is the same
/// space as the physical polynomials.
enum class PressureSpace { P0, P1disc, Q1disc, Q1, P1 };

inline std::string_view pressure_space_name(PressureSpace space) {
  switch (space) {
  case PressureSpace::P0: return "P0";
  case PressureSpace::P1disc: return "P1disc";
  case PressureSpace::Q1disc: return "Q1disc";
  case PressureSpace::Q1: return "Q1";
  case PressureSpace::P1: return "P1";
  }
  return "?";
}

inline bool is_discontinuous(PressureSpace space) {
  return space != PressureSpace::Q1 && space != PressureSpace::P1;
}

/// Number of pressure basis functions on one cell.
template <int dim> int pressure_functions_per_cell(PressureSpace space);

/// Values of the cell's pressure basis functions at reference point `xi`
/// (length pressure_functions_per_cell). For Q1 these are the vertex (Q1)
/// shape functions in the lexicographic vertex order of fem/lagrange.hpp; for P1 the
/// barycentric coordinates of the simplex's vertices 0..dim (1 − Σ ξ_i, ξ_1, …).
template <int dim> VectorX tabulate_pressure(PressureSpace space, const Point<dim>& xi);

} // namespace formflow::fem
