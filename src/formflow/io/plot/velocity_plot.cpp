// SPDX-License-Identifier: MIT
// velocity.png/.svg: velocity arrows at a subsample of the nodes, coloured by speed.
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/pictures.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace formflow::io::plot {

namespace {

/// Target distance between arrows on screen: dense enough to show the flow
/// turning into the die, sparse enough that arrows do not overlap.
constexpr double arrow_spacing_px = 22.0;

/// One node per screen bucket of arrow_spacing_px, the one nearest the bucket centre.
std::vector<Index> arrow_nodes(const Axes& axes, const mesh::Mesh<2>& mesh) {
  std::map<std::pair<long, long>, std::pair<double, Index>> nearest;
  for (Index node = 0; node < mesh.n_nodes(); ++node) {
    const Pixel at = axes.at(mesh.nodes(0, node), mesh.nodes(1, node));
    const double u = (at[0] - axes.area().x) / arrow_spacing_px;
    const double v = (axes.area().bottom() - at[1]) / arrow_spacing_px;
    // Buckets centred on the lattice points, so the boundary nodes are kept.
    const std::pair<long, long> bucket{std::lround(u), std::lround(v)};
    const double distance = std::hypot(u - bucket.first, v - bucket.second);
    auto [it, inserted] = nearest.try_emplace(bucket, distance, node);
    if (!inserted && distance < it->second.first) it->second = {distance, node};
  }
  std::vector<Index> nodes;
  for (const auto& entry : nearest) nodes.push_back(entry.second.second);
  return nodes;
}

void draw_arrow(const Canvas& canvas, Pixel from, Pixel to, const Rgb& colour) {
  const double dx = to[0] - from[0], dy = to[1] - from[1];
  const double length = std::hypot(dx, dy);
  if (length < 2.0) {  // a still node: a dot keeps the sampling grid visible
    canvas.circle(from, 1.3, colour);
    return;
  }
  const double head = std::min(6.5, 0.45 * length);
  const double ux = dx / length, uy = dy / length;
  const Pixel base{to[0] - head * ux, to[1] - head * uy};
  canvas.line(from, base, {1.5, colour});
  const std::array<Pixel, 3> tip = {{to,
                                     {base[0] - 0.45 * head * uy, base[1] + 0.45 * head * ux},
                                     {base[0] + 0.45 * head * uy, base[1] - 0.45 * head * ux}}};
  canvas.fill(tip, colour);
}

}  // namespace

void draw_velocity(const Canvas& canvas, const PictureData& data) {
  draw_title(canvas, "Velocity (arrow length ∝ speed)", run_description(data.case_, data.results));
  const FieldLayout layout = field_layout(data.mesh);
  const Axes& axes = layout.axes;
  const VectorX& velocity = data.results.fields.velocity;
  if (data.mesh.n_cells() == 0 || velocity.size() != 2 * data.mesh.n_nodes()) {
    draw_no_data(canvas, axes.area(), "no velocity field");
    return;
  }
  VectorX speed(data.mesh.n_nodes());
  for (Index n = 0; n < speed.size(); ++n) speed[n] = std::hypot(velocity[2 * n], velocity[2 * n + 1]);
  const double max_speed = speed.maxCoeff();
  const ColourScale scale = ColourScale::linear(0.0, max_speed > 0 ? max_speed : 1.0, 8, Palette::SequentialDark);

  draw_cell_edges(canvas, axes, data.mesh, {0.6, {0.6, 0.6, 0.6}, 0.5});
  draw_boundary(canvas, axes, data.mesh);
  axes.draw(canvas, false);
  // The longest arrow spans most of the spacing: long enough to read, short enough not to touch.
  const double px_per_speed = max_speed > 0 ? 0.95 * arrow_spacing_px / max_speed : 0.0;
  for (const Index node : arrow_nodes(axes, data.mesh)) {
    const Pixel from = axes.at(data.mesh.nodes(0, node), data.mesh.nodes(1, node));
    // Screen y points down: the y component changes sign.
    const Pixel to{from[0] + px_per_speed * velocity[2 * node],
                   from[1] - px_per_speed * velocity[2 * node + 1]};
    draw_arrow(canvas, from, to, scale.band_colour(scale.band_of(speed[node])));
  }
  canvas.text({axes.area().right(), axes.area().bottom() + 30},
              fmt::format("longest arrow: |u| = {:.3g}", max_speed), Font{11.5},
              HAlign::Right, VAlign::Top);
  draw_colour_bar(canvas, layout.colour_bar, scale, "speed |u| [length/time]");
}

}  // namespace formflow::io::plot
