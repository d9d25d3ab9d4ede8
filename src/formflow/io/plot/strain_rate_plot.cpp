// SPDX-License-Identifier: MIT
// strain_rate.png/.svg: log-scale filled contours of the equivalent strain rate.
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/pictures.hpp"
#include "formflow/io/plot/ticks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace formflow::io::plot {

namespace {

/// Decades shown below the maximum. The die corner is singular, so the
/// maximum grows with refinement; four decades still separate the plastic
/// zone (~0.1–10) from the dead-metal and rigid zones (≲ 10⁻²) on any mesh.
constexpr double decades_shown = 4.0;

ColourScale strain_rate_scale(const VectorX& rate) {
  const double high = rate.maxCoeff();
  double low_positive = high;
  for (Index i = 0; i < rate.size(); ++i)
    if (rate[i] > 0) low_positive = std::min(low_positive, rate[i]);
  if (!(high > 0)) return ColourScale::logarithmic(1e-4, 1.0); // a rigid body: all "low"
  const double low = std::max(low_positive, high * std::pow(10.0, -decades_shown));
  ColourScale scale = ColourScale::logarithmic(low < high ? low : high / 10.0, high);
  scale.extends_below = rate.minCoeff() < scale.boundaries().front();
  return scale;
}

/// Marks the node of the largest rate (normally the die corner) with its value.
void mark_maximum(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh,
                  const VectorX& rate) {
  Index node = 0;
  rate.maxCoeff(&node);
  const Pixel at = axes.at(mesh.nodes(0, node), mesh.nodes(1, node));
  canvas.circle(at, 4.0, {0.85, 0.1, 0.1});
  const bool right_half = at[0] > axes.area().x + 0.6 * axes.area().width;
  const Pixel label{at[0] + (right_half ? -8.0 : 8.0), at[1] - 8.0};
  const std::string text = fmt::format("max {:.3g}", rate[node]);
  const Font font{12.0, true, {0.75, 0.05, 0.05}};
  const double width = canvas.text_width(text, font);
  canvas.fill_rect({right_half ? label[0] - width - 3 : label[0] - 3, label[1] - 13, width + 6, 17},
                   {1, 1, 1}, 0.8);
  canvas.text(label, text, font, right_half ? HAlign::Right : HAlign::Left, VAlign::Baseline);
}

} // namespace

void draw_strain_rate(const Canvas& canvas, const PictureData& data) {
  draw_title(canvas, "Equivalent strain rate ε\u0304\u0307 (log scale)",
             run_description(data.case_, data.results));
  const FieldLayout layout = field_layout(data);
  const VectorX& rate = data.results.fields.equivalent_strain_rate;
  if (data.mesh.n_cells() == 0 || rate.size() != data.mesh.n_nodes()) {
    draw_no_data(canvas, layout.axes.area(), "no strain-rate field");
    return;
  }
  const ColourScale scale = strain_rate_scale(rate);
  fill_field_bands(canvas, layout.axes, data.mesh, rate, scale);
  draw_cell_edges(canvas, layout.axes, data.mesh, {0.5, {1, 1, 1}, 0.3});
  draw_boundary(canvas, layout.axes, data.mesh);
  layout.axes.draw_spines(canvas, 8.0);
  label_contact_parts(canvas, layout.axes, data.mesh);
  mark_maximum(canvas, layout.axes, data.mesh, rate);
  draw_colour_bar(canvas, layout.colour_bar, scale,
                  "equivalent strain rate ε\u0304\u0307 [1/time]");
}

} // namespace formflow::io::plot
