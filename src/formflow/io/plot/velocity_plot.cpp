// SPDX-License-Identifier: MIT
// velocity.png/.svg: velocity arrows at a subsample of the nodes, coloured by speed.
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace formflow::io::plot {

namespace {

/// Smallest distance between arrows on screen: dense enough to show the flow
/// turning into the die, sparse enough that arrows do not overlap.
constexpr double min_arrow_spacing_px = 24.0;

/// A whole multiple of the node spacing, so that on a structured mesh every
/// k-th node gets an arrow and the arrows form a regular grid.
double arrow_spacing(const Axes& axes, const mesh::Mesh<2>& mesh) {
  const double node_px = std::max(cell_pixels(axes, mesh) / mesh.order, 1e-3);
  return node_px * std::max(1.0, std::ceil(min_arrow_spacing_px / node_px - 1e-6));
}

/// One node per screen bucket of `spacing` pixels, the one nearest the bucket centre.
std::vector<Index> arrow_nodes(const Axes& axes, const mesh::Mesh<2>& mesh, double spacing) {
  std::map<std::pair<long, long>, std::pair<double, Index>> nearest;
  for (Index node = 0; node < mesh.n_nodes(); ++node) {
    const Pixel at = axes.at(mesh.nodes(0, node), mesh.nodes(1, node));
    const double u = (at[0] - axes.area().x) / spacing;
    const double v = (axes.area().bottom() - at[1]) / spacing;
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
  if (length < 2.0) { // a still node: a dot keeps the sampling grid visible
    canvas.circle({0.5 * (from[0] + to[0]), 0.5 * (from[1] + to[1])}, 1.3, colour);
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

} // namespace

void draw_velocity(const Canvas& canvas, const PictureData& data) {
  draw_title(canvas, "Velocity (arrow length ∝ speed)", run_description(data.case_, data.results));
  const FieldLayout layout = field_layout(data);
  const Axes& axes = layout.axes;
  const VectorX& velocity = data.results.fields.velocity;
  if (data.mesh.n_cells() == 0 || velocity.size() != 2 * data.mesh.n_nodes()) {
    draw_no_data(canvas, axes.area(), "no velocity field");
    return;
  }
  VectorX speed(data.mesh.n_nodes());
  for (Index n = 0; n < speed.size(); ++n)
    speed[n] = std::hypot(velocity[2 * n], velocity[2 * n + 1]);
  const double max_speed = speed.maxCoeff();
  const ColourScale scale =
      ColourScale::linear(0.0, max_speed > 0 ? max_speed : 1.0, 8, Palette::SequentialDark);

  draw_cell_edges(canvas, axes, data.mesh, {0.6, {0.6, 0.6, 0.6}, 0.5});
  draw_boundary(canvas, axes, data.mesh);
  axes.draw_spines(canvas, 8.0);
  label_contact_parts(canvas, axes, data.mesh);
  // The longest arrow spans most of the spacing: long enough to read, short enough not to touch.
  const double spacing = arrow_spacing(axes, data.mesh);
  const double px_per_speed = max_speed > 0 ? 0.9 * spacing / max_speed : 0.0;
  for (const Index node : arrow_nodes(axes, data.mesh, spacing)) {
    // Centred on the node, so arrows at the front end do not run into the colour bar.
    // Screen y points down: the y component changes sign.
    const Pixel at = axes.at(data.mesh.nodes(0, node), data.mesh.nodes(1, node));
    const double half_x = 0.5 * px_per_speed * velocity[2 * node];
    const double half_y = -0.5 * px_per_speed * velocity[2 * node + 1];
    draw_arrow(canvas, {at[0] - half_x, at[1] - half_y}, {at[0] + half_x, at[1] + half_y},
               scale.band_colour(scale.band_of(speed[node])));
  }
  canvas.text({axes.area().right(), axes.area().bottom() + 30},
              fmt::format("longest arrow: |u| = {:.3g}", max_speed), Font{11.5}, HAlign::Right,
              VAlign::Top);
  draw_colour_bar(canvas, layout.colour_bar, scale, "speed |u| [length/time]");
}

} // namespace formflow::io::plot
