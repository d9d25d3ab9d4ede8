// SPDX-License-Identifier: MIT
// A cell-wise pressure drawn without smoothing: checkerboards stay visible.
#include "formflow/io/plot/mesh_drawing.hpp"
#include "formflow/io/plot/pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

namespace formflow::io::plot {

namespace {

/// The mesh with every cell given its own copy of its nodes, so that a "nodal"
/// field on it may jump between cells.
mesh::Mesh<2> broken_mesh(const mesh::Mesh<2>& mesh) {
  mesh::Mesh<2> broken;
  broken.order = mesh.order;
  broken.shape = mesh.shape;
  broken.bubbles = mesh.bubbles;
  const int n = mesh.nodes_per_cell();
  broken.nodes.resize(2, static_cast<Index>(mesh.n_cells()) * n);
  broken.cells.resize(n, mesh.n_cells());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int a = 0; a < n; ++a) {
      broken.cells(a, cell) = cell * n + a;
      broken.nodes.col(cell * n + a) = mesh.nodes.col(mesh.cells(a, cell));
    }
  broken.facets = mesh.facets; // facets name (cell, local face): unchanged
  return broken;
}

/// One value per cell, banded without smoothing, clipped at 0.5 % at each end.
void draw_cell_values(const Canvas& canvas, const PictureData& data, const VectorX& cell_pressure,
                      const std::string& title, std::string_view missing,
                      std::string_view bar_label) {
  draw_title(canvas, title, run_description(data.case_, data.results));
  const FieldLayout layout = field_layout(data);
  if (data.mesh.n_cells() == 0 || cell_pressure.size() != data.mesh.n_cells()) {
    draw_no_data(canvas, layout.axes.area(), missing);
    return;
  }
  const mesh::Mesh<2> broken = broken_mesh(data.mesh);
  VectorX nodal(broken.n_nodes());
  for (Index cell = 0; cell < data.mesh.n_cells(); ++cell)
    nodal.segment(cell * data.mesh.nodes_per_cell(), data.mesh.nodes_per_cell())
        .setConstant(cell_pressure[cell]);
  std::vector<double> sorted(cell_pressure.data(), cell_pressure.data() + cell_pressure.size());
  std::sort(sorted.begin(), sorted.end());
  // The same 0.5 % clipping at each end as pressure.png (singular die corner).
  const auto at = [&](double share) {
    return sorted[static_cast<std::size_t>(share * static_cast<double>(sorted.size() - 1) + 0.5)];
  };
  ColourScale scale = ColourScale::linear(at(0.005), at(0.995), 12, Palette::Diverging);
  scale.extends_below = sorted.front() < scale.boundaries().front();
  scale.extends_above = sorted.back() > scale.boundaries().back();
  fill_field_bands(canvas, layout.axes, broken, nodal, scale);
  draw_cell_edges(canvas, layout.axes, data.mesh, {0.5, {0.2, 0.2, 0.2}, 0.15});
  draw_boundary(canvas, layout.axes, data.mesh);
  layout.axes.draw_spines(canvas, 8.0);
  label_contact_parts(canvas, layout.axes, data.mesh);
  draw_colour_bar(canvas, layout.colour_bar, scale, std::string(bar_label));
}

} // namespace

void draw_cell_pressure(const Canvas& canvas, const PictureData& data, const VectorX& cell_pressure,
                        const std::string& title) {
  draw_cell_values(canvas, data, cell_pressure, title, "no cell pressure",
                   "cell pressure p = −σ_{H} [units of σ_{p}]");
}

void draw_load_error(const Canvas& canvas, const PictureData& data) {
  const post::LoadErrorEstimate& estimate = data.results.load_error;
  // "coarser" indicators share p_h − p_{2h} (the run's mesh over 2h), the refined
  // estimate's p_{h/2} − p_h.
  const bool coarser = estimate.method == "coarser";
  const VectorX& indicators = data.results.fields.cell_load_error;
  const std::string title =
      estimate.error
          ? fmt::format("Load error indicators: Σ η_K = {:.4g}, p = {:.4f} ± {:.4f}",
                        indicators.size() > 0 ? indicators.sum() : estimate.enriched_change,
                        data.results.pressure.ram_reaction, *estimate.error)
          : std::string("Load error indicators");
  draw_cell_values(canvas, data, indicators, title,
                   estimate.error ? "no indicators" : "no error estimate (solver.load_error)",
                   coarser ? "η_{K}: the cell's share of p_{h} − p_{2h}"
                           : "η_{K}: the cell's share of p_{h/2} − p_{h}");
}

} // namespace formflow::io::plot
