// SPDX-License-Identifier: MIT
// Rendering all pictures of a run, and the layout and subtitle they share.
#include "formflow/io/plot/pictures.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/picture_rendering.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iterator>
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
      case_.mesh.distortion.kind == mesh::Distortion::None
          ? std::string("uniform cells")
          : fmt::format("{} distortion {:g}", choice_of(case_, "verification.distortion"),
                        case_.mesh.distortion.amplitude);
  return fmt::format("manufactured solution \"{}\" · {}, h = {:g} · {} · {}",
                     choice_of(case_, "verification.solution"), fem::element_name(case_.element),
                     case_.mesh.size, distortion, outcome);
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
      case_.mesh.source == mesh::MeshSource::File
          ? fmt::format("{} cells from {}", results.n_cells,
                        std::filesystem::path(case_.mesh.file).filename().string())
          : fmt::format("h = {:g}", case_.mesh.size);
  return fmt::format("{} · {}, {} · μ_{{f}} = {:g} · {} · {} {:.4g}",
                     drawing ? "drawing" : "extrusion", fem::element_name(case_.element), cells,
                     case_.friction.mu, outcome, drawing ? "drawing stress" : "ram pressure",
                     results.pressure.ram_reaction);
}

FieldLayout field_layout(const PictureData& data) {
  // Left margin for y tick labels, right margin for the colour bar and its labels.
  const Rect area{62, 70, 690, picture_height - 70 - 72};
  const Box box = bounding_box(data.mesh);
  Axes axes = equal_aspect_axes(area, box.x0, box.x1, box.y0, box.y1);
  if (data.vertical_axis != axes.y_axis().label) {
    Axis vertical = axes.y_axis();
    vertical.label = data.vertical_axis;
    axes = Axes(axes.area(), axes.x_axis(), vertical);
  }
  const Rect& plot = axes.area();
  return {std::move(axes), Rect{plot.right() + 26, plot.y, 20, plot.height}};
}

Rect graph_area() {
  return {92, 72, picture_width - 92 - 100, picture_height - 72 - 84};
}

std::span<const std::string> picture_names() {
  static const std::vector<std::string> names = {"strain_rate",  "velocity",    "pressure",
                                                 "contact",      "convergence", "load_error",
                                                 "exit_velocity"};
  return names;
}

void draw_not_converged_mark(const Canvas& canvas, solvers::StopReason stop_reason) {
  const Rgb red{0.8, 0.05, 0.05};
  constexpr double frame = 4.0; // pixels: unmissable, yet clear of the axes and labels
  canvas.stroke_rect({0.5 * frame, 0.5 * frame, canvas.width() - frame, canvas.height() - frame},
                     {frame, red});
  canvas.text({12, 10}, "NOT CONVERGED", Font{14.0, true, red}, HAlign::Left, VAlign::Top);
  canvas.text({12, 28}, std::string(solvers::stop_reason_name(stop_reason)), Font{11.0, false, red},
              HAlign::Left, VAlign::Top);
}

std::vector<Picture> render_pictures(const Case& case_, const mesh::Mesh<2>& mesh,
                                     const post::Results& results) {
  const PictureData data{case_, mesh, results};
  using DrawPicture = void (*)(const Canvas&, const PictureData&);
  const DrawPicture drawings[] = {draw_strain_rate,  draw_velocity,    draw_pressure,
                                  draw_contact,      draw_convergence, draw_load_error,
                                  draw_exit_velocity};
  const std::span<const std::string> names = picture_names();
  FF_ASSERT(names.size() == std::size(drawings), "one name per picture");
  std::vector<PictureJob> jobs;
  // Hot forming adds temperature.png (io/results_writer.cpp lists it for every run).
  const bool thermal = results.thermal.enabled;
  for (std::size_t k = 0; k < names.size() + (thermal ? 1 : 0); ++k) {
    const DrawPicture picture = k < names.size() ? drawings[k] : draw_temperature;
    const std::string name = k < names.size() ? names[k] : std::string("temperature");
    jobs.push_back({name, [&data, picture](Canvas& canvas) {
                      picture(canvas, data);
                      if (!data.results.converged())
                        draw_not_converged_mark(canvas, data.results.stop_reason);
                    }});
  }
  return render_jobs(jobs);
}

} // namespace formflow::io::plot
