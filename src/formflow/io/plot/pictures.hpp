// SPDX-License-Identifier: MIT
// The pictures of a run: one drawing function per picture, and rendering them all.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/io/plot/axes.hpp"
#include "formflow/io/plot/canvas.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"

#include <span>
#include <string>
#include <vector>

namespace formflow::io::plot {

/// Size of every picture in pixels: legible at 100 % on a laptop screen.
inline constexpr int picture_width = 900;
inline constexpr int picture_height = 600;

/// What a picture is drawn from.
struct PictureData {
  const Case& case_;
  const mesh::Mesh<2>& mesh;
  const post::Results& results;
  /// The label of the vertical axis of a field picture: "y" in the plane, "z" on a
  /// solid's y = 0 section (io/plot/solid_pictures.hpp).
  std::string vertical_axis = "y";
  /// A solid's exit section (draw_exit_section): u_x at the section's nodes.
  const VectorX* axial_velocity = nullptr;
};

/// A rendered picture: file stem ("strain_rate") and the PNG and SVG file contents.
struct Picture {
  std::string name;
  std::string png;
  std::string svg;
};

/// Filled log-scale contours of the nodal equivalent strain rate, die drawn thick.
void draw_strain_rate(const Canvas& canvas, const PictureData& data);
/// Velocity arrows at (subsampled) nodes, coloured by speed, over the mesh.
void draw_velocity(const Canvas& canvas, const PictureData& data);
/// Hot forming only (render_pictures adds it when results.thermal.enabled).
void draw_temperature(const Canvas& canvas, const PictureData& data);
/// Filled contours of the hydrostatic pressure −σ_H, diverging colours centred on 0.
void draw_pressure(const Canvas& canvas, const PictureData& data);
/// A cell-wise pressure (one value per cell, compression positive) with no
/// smoothing between cells, so that checkerboard modes stay visible (docs/mixed.md).
void draw_cell_pressure(const Canvas& canvas, const PictureData& data, const VectorX& cell_pressure,
                        const std::string& title);
/// Each cell's share η_K of the load's error estimate (post/load_error_estimate.hpp),
/// signed, without smoothing; "no error estimate" when it was not computed.
void draw_load_error(const Canvas& canvas, const PictureData& data);
/// Contact pressure and friction stress against arc length along Γ3.
void draw_contact(const Canvas& canvas, const PictureData& data);
/// Relative change per iteration (log) with the tolerance, and the pressure history.
void draw_convergence(const Canvas& canvas, const PictureData& data);
/// The axial velocity across the exit section against its mean (io/plot/exit_velocity_plot.cpp).
void draw_exit_velocity(const Canvas& canvas, const PictureData& data);
/// A solid's exit section (data.mesh in (y, z)) filled by the axial velocity
/// data.axial_velocity, with the profile's outline and its edges' mean speeds.
void draw_exit_section(const Canvas& canvas, const PictureData& data);

/// The stems of the pictures render_pictures draws, in its order:
/// strain_rate, velocity, pressure, contact, convergence, load_error.
std::span<const std::string> picture_names();

/// The mark of a run that did not converge, drawn over a finished picture: a
/// red frame round the whole canvas and "NOT CONVERGED" with the stop reason
/// in red in its top-left corner, clear of the centred title. A picture of
/// the last iterate must not pass for a picture of a solution.
void draw_not_converged_mark(const Canvas& canvas, solvers::StopReason stop_reason);

/// Every picture above, in the order of picture_names(); a run that did not
/// converge carries draw_not_converged_mark on each. Throws std::runtime_error
/// if cairo fails.
std::vector<Picture> render_pictures(const Case& case_, const mesh::Mesh<2>& mesh,
                                     const post::Results& results);

// Shared by the picture files.

/// One line saying which run this is: process, element, mesh size, friction,
/// outcome and the ram pressure (the subtitle of every picture); for a
/// manufactured-solution run: the solution, element, h, distortion and outcome.
std::string run_description(const Case& case_, const post::Results& results);

/// Where a field picture puts its mesh (equal aspect) and its colour bar.
struct FieldLayout {
  Axes axes;
  Rect colour_bar;
};
/// The field-picture layout for `data.mesh` on a picture_width × picture_height
/// canvas, the vertical axis labelled data.vertical_axis.
FieldLayout field_layout(const PictureData& data);

/// The plot area of a graph picture (contact, convergence), leaving room for
/// axis labels on both sides.
Rect graph_area();

} // namespace formflow::io::plot
