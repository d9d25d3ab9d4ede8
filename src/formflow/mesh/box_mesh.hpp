// SPDX-License-Identifier: MIT
// Structured quadrilateral mesh of a rectangle, optionally distorted (verification meshes).
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// How the interior nodes of a box mesh are moved off the uniform lattice.
enum class Distortion {
  None,   ///< uniform rectangles (affine cells)
  Smooth, ///< the image of the uniform mesh under one fixed smooth map (non-affine cells)
  Random, ///< each interior vertex moved by an independent random offset (non-affine cells)
};

/// The distortion and its size. Smooth: the vertices move by the fixed map
/// x̂ → x̂ + a·sin(πx̂)sin(πŷ)·(sin 2πŷ, sin 2πx̂) in box coordinates x̂, ŷ ∈ [0, 1]
/// (a = `amplitude`; one-to-one for a < 1/(3π) ≈ 0.1), the same map on every
/// mesh of a ladder. Random: each interior vertex moves by up to `amplitude` ×
/// (cell side) per direction, drawn from `seed`; cells stay convex for amplitude < 0.25.
struct BoxDistortion {
  Distortion kind = Distortion::None;
  Real amplitude = 0.1;
  int seed = 1; ///< ≥ 0
};

/// `n_x` × `n_y` cells of polynomial `order` (1 or 2) on [lower, upper]. The
/// higher-order nodes of a Q2 cell sit where the bilinear map of its four
/// vertices puts them (straight edges), so every cell is a bilinear image of
/// the reference square. Labels: rear x = x₀, front x = x₁, symmetry y = y₀,
/// free_exit y = y₁ (no contact boundary).
Mesh<2> make_box_mesh(const Point<2>& lower, const Point<2>& upper, int n_x, int n_y, int order,
                      const BoxDistortion& distortion = {});

} // namespace formflow::mesh
