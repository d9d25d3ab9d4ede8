// SPDX-License-Identifier: MIT
// Rendering all pictures of a run, and the layout and subtitle they share.
#include "formflow/io/plot/pictures.hpp"

#include "formflow/io/case_keys.hpp"
#include "formflow/io/plot/mesh_drawing.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <string_view>
#include <utility>
#include <variant>

namespace formflow::io::plot {

namespace {

/// The value of an enumerated case key as written in the case file ("smooth").
std::string choice_of(const Case& case_, std::string_view key) {
  return std::get<std::string>(find_case_key(key)->get(case_));
}

/// A verification run has no process, die or ram: name the exact solution, the
/// element, h and the distortion of the unit-square mesh instead.
std::string manufactured_description(const Case& case_, const std::string& outcome) {
  const std::string distortion =
      case_.distortion.kind == mesh::Distortion::None
          ? std::string("uniform cells")
          : fmt::format("{} distortion {:g}", choice_of(case_, "verification.distortion"),
                        case_.distortion.amplitude);
  return fmt::format("manufactured solution \"{}\" · {}, h = {:g} · {} · {}",
                     choice_of(case_, "verification.solution"), fem::element_name(case_.element),
                     case_.mesh_size, distortion, outcome);
}

} // namespace

std::string run_description(const Case& case_, const post::Results& results) {
  const bool drawing = case_.process.type == physics::ProcessType::Drawing;
  const std::string outcome =
      results.converged()
          ? fmt::format("converged in {} iterations", results.iterations)
          : fmt::format("NOT converged ({}, {} iterations)",
                        solvers::stop_reason_name(results.stop_reason), results.iterations);
  if (case_.manufactured != physics::ManufacturedSolution::None)
    return manufactured_description(case_, outcome);
  // A mesh read from a file has no single cell size: name the file instead.
  const std::string cells =
      case_.mesh_source == mesh::MeshSource::File
          ? fmt::format("{} cells from {}", results.n_cells,
                        std::filesystem::path(case_.mesh_file).filename().string())
          : fmt::format("h = {:g}", case_.mesh_size);
  return fmt::format("{} · {}, {} · μ_{{f}} = {:g} · {} · {} {:.4g}",
                     drawing ? "drawing" : "extrusion", fem::element_name(case_.element), cells,
                     case_.friction.mu, outcome, drawing ? "drawing stress" : "ram pressure",
                     results.pressure.ram_reaction);
}

FieldLayout field_layout(const mesh::Mesh<2>& mesh) {
  // Left margin for y tick labels, right margin for the colour bar and its labels.
  const Rect area{62, 70, 690, picture_height - 70 - 72};
  const Box box = bounding_box(mesh);
  Axes axes = equal_aspect_axes(area, box.x0, box.x1, box.y0, box.y1);
  const Rect& plot = axes.area();
  return {std::move(axes), Rect{plot.right() + 26, plot.y, 20, plot.height}};
}

Rect graph_area() {
  return {92, 72, picture_width - 92 - 100, picture_height - 72 - 84};
}

std::vector<Picture> render_pictures(const Case& case_, const mesh::Mesh<2>& mesh,
                                     const post::Results& results) {
  const PictureData data{case_, mesh, results};
  using DrawPicture = void (*)(const Canvas&, const PictureData&);
  const std::pair<const char*, DrawPicture> pictures[] = {{"strain_rate", draw_strain_rate},
                                                          {"velocity", draw_velocity},
                                                          {"pressure", draw_pressure},
                                                          {"contact", draw_contact},
                                                          {"convergence", draw_convergence}};
  std::vector<Picture> out;
  for (const auto& [name, draw] : pictures) {
    const DrawPicture picture = draw;
    const DrawFunction function = [&data, picture](Canvas& canvas) { picture(canvas, data); };
    out.push_back({name, render_png(picture_width, picture_height, function),
                   render_svg(picture_width, picture_height, function)});
  }
  return out;
}

} // namespace formflow::io::plot
