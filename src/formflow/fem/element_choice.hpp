// SPDX-License-Identifier: MIT
// The cell layout a velocity element and its pressure need.
#pragma once

#include "formflow/fem/lagrange.hpp"
#include "formflow/fem/pressure_space.hpp"
#include "formflow/mesh/cell_type.hpp"

namespace formflow::fem {

/// The cells of `element` paired with `pressure` (`mixed`: a pressure space is used).
/// Q1/Q2 are cube cells of their order. P1b is P1 with its cell bubble. P2 carries
/// bubbles (P2+: the cell centroid, in 3D also the face centroids) exactly when its
/// pressure is discontinuous: P1disc per cell has dim + 1 constraints against P2's
/// freedom, which is not inf-sup stable without them (Boffi, Brezzi & Fortin, Mixed
/// Finite Element Methods, §8.6.2); the continuous P1 pressure (Taylor–Hood) is
/// stable with plain P2, which then needs none (docs/mixed.md).
inline mesh::CellType velocity_cell_type(ElementKind element, PressureSpace pressure, bool mixed) {
  switch (element) {
  case ElementKind::Q1: return {mesh::CellShape::Cube, 1, false};
  case ElementKind::Q2: return {mesh::CellShape::Cube, 2, false};
  case ElementKind::P1b: return {mesh::CellShape::Simplex, 1, true};
  case ElementKind::P2: return {mesh::CellShape::Simplex, 2, mixed && is_discontinuous(pressure)};
  }
  return {};
}

} // namespace formflow::fem
