// SPDX-License-Identifier: MIT
// pressure.png/.svg: filled contours of the hydrostatic pressure −σ_H.
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/pictures.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace formflow::io::plot {

namespace {

/// Share of nodes at each end left outside the colour range. The penalty
/// pressure oscillates at the singular die corner; letting those few nodes
/// set the range would wash out the rest of the picture. They still show, in
/// the end colours, and the colour bar's triangles say the data go further.
constexpr double clipped_share = 0.005;

ColourScale pressure_scale(const VectorX& pressure) {
  std::vector<double> sorted(pressure.data(), pressure.data() + pressure.size());
  std::sort(sorted.begin(), sorted.end());
  const auto last = sorted.size() - 1;
  const auto at = [&](double share) {
    return sorted[static_cast<std::size_t>(std::lround(share * static_cast<double>(last)))];
  };
  ColourScale scale =
      ColourScale::linear(at(clipped_share), at(1.0 - clipped_share), 12, Palette::Diverging);
  scale.extends_below = sorted.front() < scale.boundaries().front();
  scale.extends_above = sorted.back() > scale.boundaries().back();
  return scale;
}

} // namespace

void draw_pressure(const Canvas& canvas, const PictureData& data) {
  draw_title(canvas, "Hydrostatic pressure p = −σ_{H} (compression positive)",
             run_description(data.case_, data.results));
  const FieldLayout layout = field_layout(data);
  const VectorX& stress = data.results.fields.hydrostatic_stress;
  if (data.mesh.n_cells() == 0 || stress.size() != data.mesh.n_nodes()) {
    draw_no_data(canvas, layout.axes.area(), "no pressure field");
    return;
  }
  const VectorX pressure = -stress;
  const ColourScale scale = pressure_scale(pressure);
  fill_field_bands(canvas, layout.axes, data.mesh, pressure, scale);
  draw_cell_edges(canvas, layout.axes, data.mesh, {0.5, {0.2, 0.2, 0.2}, 0.15});
  draw_boundary(canvas, layout.axes, data.mesh);
  layout.axes.draw_spines(canvas, 8.0);
  label_contact_parts(canvas, layout.axes, data.mesh);
  draw_colour_bar(canvas, layout.colour_bar, scale,
                  "hydrostatic pressure p = −σ_{H} [units of σ_{p}]");
}

} // namespace formflow::io::plot
