// SPDX-License-Identifier: MIT
// contact.png/.svg: contact pressure and friction stress along the contact boundary Γ3.
#include "formflow/io/plot/pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace formflow::io::plot {

namespace {

const Rgb contact_pressure_colour{0.12, 0.31, 0.61};
const Rgb friction_colour{0.85, 0.37, 0.01};
const Rgb stick_colour{0.55, 0.75, 0.55};

/// Arc length where the container wall meets the die face: the shared end
/// point of a container and a die facet, reached from the last container
/// sample. Empty when the contact has only one part.
std::optional<double> junction_arc_length(const PictureData& data) {
  const auto& contact = data.results.contact;
  const auto die = std::find_if(contact.begin(), contact.end(),
                                [](const post::ContactSample& s) { return s.part == 1; });
  if (die == contact.begin() || die == contact.end()) return std::nullopt;
  const post::ContactSample& last_container = *(die - 1);
  const mesh::Mesh<2>& mesh = data.mesh;
  std::vector<Index> container_nodes, die_nodes;
  for (const auto& facet : mesh.facets)
    for (const int local : mesh.face_nodes(facet.local_face)) {
      if (facet.label == mesh::BoundaryLabel::Container)
        container_nodes.push_back(mesh.cells(local, facet.cell));
      if (facet.label == mesh::BoundaryLabel::Die)
        die_nodes.push_back(mesh.cells(local, facet.cell));
    }
  for (const Index node : container_nodes)
    if (std::find(die_nodes.begin(), die_nodes.end(), node) != die_nodes.end())
      return last_container.arc_length + std::hypot(mesh.nodes(0, node) - last_container.x,
                                                    mesh.nodes(1, node) - last_container.y);
  return 0.5 * (last_container.arc_length + die->arc_length);
}

/// Light bands behind the curves where the samples stick (half-way to the neighbours).
void shade_sticking(const Canvas& canvas, const Axes& axes,
                    const std::vector<post::ContactSample>& contact) {
  for (std::size_t i = 0; i < contact.size(); ++i) {
    if (!contact[i].sticking) continue;
    const double left =
        i == 0 ? contact[i].arc_length : 0.5 * (contact[i - 1].arc_length + contact[i].arc_length);
    const double right = i + 1 == contact.size()
                             ? contact[i].arc_length
                             : 0.5 * (contact[i].arc_length + contact[i + 1].arc_length);
    const Rect& area = axes.area();
    canvas.fill_rect({axes.px(left), area.y, axes.px(right) - axes.px(left), area.height},
                     stick_colour, 0.35);
  }
}

std::vector<Pixel> curve(const Axes& axes, const std::vector<post::ContactSample>& contact,
                         bool friction) {
  std::vector<Pixel> points;
  for (const auto& sample : contact)
    points.push_back(
        axes.at(sample.arc_length, friction ? sample.friction_stress : sample.contact_pressure));
  return points;
}

/// Upper end of the stress axis. The contact pressure is singular at the die
/// corner: a handful of samples there can be several times the rest. Values
/// above twice the 90th percentile are left off the scale (drawn running out
/// of the top, with their value written there) so the profile stays readable.
double robust_high(const std::vector<post::ContactSample>& contact) {
  std::vector<double> values;
  for (const auto& sample : contact) {
    values.push_back(sample.contact_pressure);
    values.push_back(sample.friction_stress);
  }
  std::sort(values.begin(), values.end());
  const double p90 = values[static_cast<std::size_t>(0.9 * static_cast<double>(values.size() - 1))];
  double high = 0.0;
  for (const double value : values)
    if (p90 <= 0 || value <= 2.0 * p90) high = std::max(high, value);
  return high;
}

/// Writes the value of each sample that runs off the top of the axes above it
/// (the larger of the two stresses), skipping labels that would overlap.
void label_off_scale(const Canvas& canvas, const Axes& axes,
                     const std::vector<post::ContactSample>& contact) {
  double last_x = -1e9;
  for (const auto& sample : contact) {
    const double value = std::max(sample.contact_pressure, sample.friction_stress);
    const double x = axes.px(sample.arc_length);
    if (value <= axes.y_axis().hi || x - last_x < 40.0) continue;
    canvas.text({x, axes.area().y - 3}, fmt::format("▲ {:.3g}", value),
                Font{11.5, true, contact_pressure_colour}, HAlign::Centre, VAlign::Bottom);
    last_x = x;
  }
}

Axes contact_axes(const std::vector<post::ContactSample>& contact) {
  double low = 0.0;
  for (const auto& sample : contact)
    low = std::min({low, sample.contact_pressure, sample.friction_stress});
  const double high = robust_high(contact);
  const double pad = 0.06 * std::max(high - low, 1e-12);
  // Room above the curves for the legend and the part names.
  return Axes(
      graph_area(),
      Axis{std::min(0.0, contact.front().arc_length),
           contact.back().arc_length,
           false,
           {},
           "arc length s along Γ_{3}, from its end nearest the rear (ram side)"},
      Axis{low < 0 ? low - pad : 0.0, high + 5 * pad, false, {}, "stress [units of σ_{p}]"});
}

} // namespace

void draw_contact(const Canvas& canvas, const PictureData& data) {
  // In drawing the container wall is free (Γ2): Γ3 is the die alone.
  const bool drawing = data.case_.process.type == physics::ProcessType::Drawing;
  draw_title(canvas,
             drawing ? "Contact stresses along the die (Γ_{3})"
                     : "Contact stresses along the container and die (Γ_{3})",
             run_description(data.case_, data.results));
  const auto& contact = data.results.contact;
  if (contact.empty()) {
    Axes(graph_area(), Axis{}, Axis{}).draw(canvas, false);
    draw_no_data(canvas, graph_area(), "no contact samples");
    return;
  }
  const Axes axes = contact_axes(contact);
  const Rect& area = axes.area();
  shade_sticking(canvas, axes, contact);
  axes.draw(canvas, true);
  canvas.clip(area);
  if (axes.y_axis().lo < 0)
    canvas.line(axes.at(axes.x_axis().lo, 0), axes.at(axes.x_axis().hi, 0), {1.0, {0.3, 0.3, 0.3}});
  if (const auto junction = junction_arc_length(data)) {
    const double x = axes.px(*junction);
    canvas.line({x, area.y}, {x, area.bottom()}, {1.2, {0.3, 0.3, 0.3}, 1.0, 7.0});
    const Font font{12.0, true, {0.3, 0.3, 0.3}};
    canvas.text({x - 8, area.y + 8}, "◀ container wall", font, HAlign::Right, VAlign::Top);
    canvas.text({x + 8, area.y + 8}, "die face ▶", font, HAlign::Left, VAlign::Top);
  }
  canvas.polyline(curve(axes, contact, false), {2.2, contact_pressure_colour});
  canvas.polyline(curve(axes, contact, true), {2.2, friction_colour});
  canvas.unclip();
  label_off_scale(canvas, axes, contact);
  std::vector<LegendEntry> legend = {{"contact pressure −σ_{N}", {2.2, contact_pressure_colour}},
                                     {"friction stress |σ_{T}|", {2.2, friction_colour}}};
  if (std::any_of(contact.begin(), contact.end(), [](const auto& s) { return s.sticking; }))
    legend.push_back({"sticking (u_{T} ≈ 0)", {12.0, stick_colour, 0.35}});
  // Top left: the container wall away from the die corner is where the curves are lowest.
  draw_legend(canvas, {area.x + 10, area.y + 10}, legend, HAlign::Left);
}

} // namespace formflow::io::plot
