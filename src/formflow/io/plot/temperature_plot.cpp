// SPDX-License-Identifier: MIT
// temperature.png/.svg (hot forming): filled contours of the temperature field.
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/pictures.hpp"

#include <fmt/format.h>

namespace formflow::io::plot {

void draw_temperature(const Canvas& canvas, const PictureData& data) {
  const post::ThermalResults& thermal = data.results.thermal;
  draw_title(canvas, "Temperature T",
             fmt::format("{}; exit mean {:.4g}, max {:.4g}",
                         run_description(data.case_, data.results), thermal.exit_mean,
                         thermal.max_temperature));
  const FieldLayout layout = field_layout(data);
  const VectorX& T = data.results.fields.temperature;
  if (data.mesh.n_cells() == 0 || T.size() != data.mesh.n_nodes()) {
    draw_no_data(canvas, layout.axes.area(), "no temperature field");
    return;
  }
  const double low = T.minCoeff(), high = T.maxCoeff();
  // A uniform field still gets a readable bar: one band around its value.
  const double spread = high > low ? 0.0 : std::max(1.0, std::abs(high) * 1e-3);
  const ColourScale scale =
      ColourScale::linear(low - spread, high + spread, 10, Palette::Sequential);
  fill_field_bands(canvas, layout.axes, data.mesh, T, scale);
  draw_cell_edges(canvas, layout.axes, data.mesh, {0.5, {1, 1, 1}, 0.3});
  draw_boundary(canvas, layout.axes, data.mesh);
  layout.axes.draw_spines(canvas, 8.0);
  label_contact_parts(canvas, layout.axes, data.mesh);
  draw_colour_bar(canvas, layout.colour_bar, scale, "temperature T");
}

} // namespace formflow::io::plot
