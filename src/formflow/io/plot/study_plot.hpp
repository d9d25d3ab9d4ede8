// SPDX-License-Identifier: MIT
// The picture of a parameter study: error norms (or pressures) against the varied key.
#pragma once

#include "formflow/io/plot/pictures.hpp"
#include "formflow/post/study_table.hpp"

namespace formflow::io::plot {

/// Log-log plot of the error norms against the parameter (or, without an exact
/// solution, of the differences to the last rung; without either, the
/// pressures on a log parameter axis with the Richardson limit). Dashed
/// reference slopes: the theory order when the table knows it, else the most
/// frequent observed pair order (rounded to ½). rcond when present.
/// Non-converged rungs are drawn as larger red dots.
void draw_study(const Canvas& canvas, const post::StudyTable& table);

/// draw_study rendered as study.png / study.svg (name "study").
Picture render_study_plot(const post::StudyTable& table);

/// Log-log plot of the annulus-mean ε̄̇ against the distance ρ from the die
/// corner, one line per rung, with the reference 1/ρ (slope −1) of the
/// singularity through the coarsest rung's outermost point.
void draw_corner(const Canvas& canvas, const post::StudyTable& table);

/// draw_corner rendered as corner.png / corner.svg (name "corner").
Picture render_corner_plot(const post::StudyTable& table);

} // namespace formflow::io::plot
