// SPDX-License-Identifier: MIT
// The pictures of a three-dimensional run: the fields on the symmetry planes, the
// contact stresses over the unrolled die surface, the convergence.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/io/plot/pictures.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"

#include <span>
#include <string>
#include <vector>

namespace formflow::io::plot {

/// The stems of render_solid_pictures' pictures, in its order: strain_rate_z0,
/// pressure_z0 (the section z = 0, x–y), strain_rate_y0, pressure_y0 (the section
/// y = 0, x–z), contact_surface, convergence.
std::span<const std::string> solid_picture_names();

/// Contact pressure (top) and friction stress (bottom) at the Γ3 quadrature points,
/// each point a coloured mark over the die surface unrolled into the plane: the
/// horizontal coordinate is x + (d_wall − d), d the point's distance from the axis
/// along its ray from it (y for the slab) and d_wall the container wall's along the
/// same ray, so the wall, the die face (also a face x = L_c of a square die) and the
/// land follow one another as in a plane picture; the vertical coordinate is the
/// angle atan(z/y) about the axis (z for the slab).
void draw_contact_surface(const Canvas& canvas, const PictureData& data);

/// Every picture above for a solid run on `mesh` (a section only where `mesh` has
/// that symmetry plane); a run that did not converge carries
/// draw_not_converged_mark on each. Throws std::runtime_error if cairo fails.
std::vector<Picture> render_solid_pictures(const Case& case_, const mesh::Mesh<3>& mesh,
                                           const post::Results& results);

} // namespace formflow::io::plot
