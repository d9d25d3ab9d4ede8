// SPDX-License-Identifier: MIT
// The convergence picture of the load: its error against dofs, uniform vs adaptive.
#pragma once

#include "formflow/io/plot/pictures.hpp"
#include "formflow/post/study_table.hpp"

namespace formflow::io::plot {

/// Log-log plot of the load's error against the number of dofs, for the rungs of a
/// mesh study (uniform refinement) and the cycles of its adaptive run (issue 17).
/// With table.exact_load: |p_h − p| as dots, each with its estimate as a bar from the
/// dot to a cap at the estimate (the interval p_h ± estimate holds p when the cap is
/// at or above the dot). Without it: the estimates alone. Dashed reference slopes
/// dofs^(−1/2) (first order in h: uniform refinement around the die corner) and
/// dofs^(−1) (what adaptivity recovers), through the finest uniform and adaptive point.
void draw_load_error_against_dofs(const Canvas& canvas, const post::StudyTable& table);

/// draw_load_error_against_dofs rendered as load_error_dofs.png / .svg.
Picture render_load_error_dofs_plot(const post::StudyTable& table);

} // namespace formflow::io::plot
