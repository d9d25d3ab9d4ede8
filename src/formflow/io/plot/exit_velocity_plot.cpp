// SPDX-License-Identifier: MIT
// exit_velocity.png/.svg: the axial velocity across the exit section, against its mean.
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

namespace formflow::io::plot {

namespace {

const Rgb velocity_colour{0.12, 0.31, 0.61};
const Rgb mean_colour{0.85, 0.37, 0.01};

/// The velocity axis: the profile's range with a margin, never a zero span (a uniform
/// exit is a flat line in the middle).
Axis velocity_axis(const post::ExitFlow& exit) {
  const double span = std::max(exit.velocity_max - exit.velocity_min,
                               1e-3 * std::max(std::abs(exit.velocity_mean), 1e-12));
  return Axis{exit.velocity_min - 0.5 * span,
              exit.velocity_max + 0.5 * span,
              false,
              {},
              "axial velocity u_{x} [length/time]"};
}

/// The nonuniformity to 3 digits, or "undefined" where no metal leaves.
std::string nonuniformity_text(const post::ExitFlow& exit) {
  return exit.nonuniformity ? fmt::format("{:.3g}", *exit.nonuniformity) : "undefined";
}

} // namespace

void draw_exit_velocity(const Canvas& canvas, const PictureData& data) {
  draw_title(canvas, "Axial velocity across the exit section",
             run_description(data.case_, data.results));
  const post::ExitFlow& exit = data.results.exit;
  const bool axisymmetric = data.case_.symmetry == physics::Symmetry::Axisymmetric;
  if (!exit.present || exit.profile.size() < 2) {
    Axes(graph_area(), Axis{}, Axis{}).draw(canvas, false);
    draw_no_data(canvas, graph_area(), "no exit section (no \"front\" facets)");
    return;
  }
  const Axes axes(graph_area(),
                  Axis{exit.profile.front()[0],
                       exit.profile.back()[0],
                       false,
                       {},
                       axisymmetric ? "radius r across the exit" : "y across the exit"},
                  velocity_axis(exit));
  axes.draw(canvas, true);
  const Rect& area = axes.area();
  canvas.clip(area);
  const double y_mean = axes.py(exit.velocity_mean);
  canvas.line({area.x, y_mean}, {area.right(), y_mean}, {1.6, mean_colour, 1.0, 9.0});
  std::vector<Pixel> points;
  for (const auto& [position, velocity] : exit.profile)
    points.push_back(axes.at(position, velocity));
  canvas.polyline(points, {2.0, velocity_colour});
  canvas.unclip();
  const std::vector<LegendEntry> legend = {
      {"u_{x} at the exit's nodes", {2.0, velocity_colour}},
      {fmt::format("{} {:.5g}", axisymmetric ? "flux-weighted mean" : "mean", exit.velocity_mean),
       {1.6, mean_colour, 1.0, 9.0}}};
  draw_legend(canvas, {area.right() - 10, area.y + 10}, legend);
  canvas.text({area.x + 8, area.bottom() - 8},
              fmt::format("nonuniformity (max − min)/mean = {}    flux balance = {:+.3g}",
                          nonuniformity_text(exit), exit.flux_balance),
              Font{12.0, false, {0.15, 0.15, 0.15}}, HAlign::Left, VAlign::Bottom);
}

void draw_exit_section(const Canvas& canvas, const PictureData& data) {
  const post::ExitFlow& exit = data.results.exit;
  draw_title(canvas, "Axial velocity over the exit section",
             exit.present ? fmt::format("{}; mean {:.5g}, nonuniformity {}",
                                        run_description(data.case_, data.results),
                                        exit.velocity_mean, nonuniformity_text(exit))
                          : run_description(data.case_, data.results));
  FieldLayout layout = field_layout(data);
  Axis horizontal = layout.axes.x_axis();
  horizontal.label = "y";
  layout.axes = Axes(layout.axes.area(), horizontal, layout.axes.y_axis());
  const VectorX* axial = data.axial_velocity;
  if (!exit.present || data.mesh.n_cells() == 0 || !axial || axial->size() != data.mesh.n_nodes()) {
    draw_no_data(canvas, layout.axes.area(), "no exit section (no \"front\" facets)");
    return;
  }
  const double low = axial->minCoeff(), high = axial->maxCoeff();
  // A uniform exit (a rigid translation: equal to round-off) still gets a readable bar,
  // one band around its speed; bands narrower than a millionth of it would be round-off
  // drawn in colour (and ColourScale's steps would fall below the numbers' resolution).
  const double scale_of = std::max({std::abs(low), std::abs(high), 1e-300});
  const double spread = high - low > 1e-6 * scale_of ? 0.0 : 1e-3 * scale_of;
  const ColourScale scale =
      ColourScale::linear(low - spread, high + spread, 10, Palette::Sequential);
  fill_field_bands(canvas, layout.axes, data.mesh, *axial, scale);
  draw_cell_edges(canvas, layout.axes, data.mesh, {0.5, {1, 1, 1}, 0.3});
  draw_boundary(canvas, layout.axes, data.mesh);
  // A profile: each outline edge's mean speed at its midpoint (the model's part of it).
  const Rect& area = layout.axes.area();
  const Font label{10.0, false, {0.1, 0.1, 0.1}};
  for (const post::ExitEdge& edge : exit.edges) {
    if (!std::isfinite(edge.velocity_mean)) continue;
    const double y = 0.5 * (edge.from[0] + edge.to[0]), z = 0.5 * (edge.from[1] + edge.to[1]);
    const Pixel at = layout.axes.at(y, z);
    if (at[0] < area.x || at[0] > area.right() || at[1] < area.y || at[1] > area.bottom())
      continue; // an edge of the mirrored part of the section
    canvas.text(at, fmt::format("{:.4g}", edge.velocity_mean), label, HAlign::Centre,
                VAlign::Middle);
  }
  layout.axes.draw_spines(canvas, 8.0);
  draw_colour_bar(canvas, layout.colour_bar, scale, "axial velocity u_{x}");
}

} // namespace formflow::io::plot
