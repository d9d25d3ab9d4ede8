// SPDX-License-Identifier: MIT
// Pictures of a solid run: symmetry-plane sections drawn by the plane pictures, and
// the contact stresses over the unrolled die surface.
#include "formflow/io/plot/solid_pictures.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/plot/solid_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace formflow::io::plot {

namespace {

/// Where a Γ3 point is drawn on the unrolled die surface (draw_contact_surface).
Pixel unrolled(const Case& case_, const post::ContactSample& sample) {
  const mesh::SolidChannel& solid = case_.mesh.solid;
  const Real h_in = case_.mesh.geometry.entry_half_height;
  if (solid.section == mesh::ChannelSection::Slab) return {sample.x + (h_in - sample.y), sample.z};
  const Real theta = std::atan2(sample.z, sample.y);
  const Real distance = std::hypot(sample.y, sample.z);
  Real wall = h_in; // the round billet's radius
  if (solid.section == mesh::ChannelSection::Rectangle) {
    // Along the ray at θ the container's outline is at min(H/cos θ, W/sin θ).
    const Real c = std::cos(theta), s = std::sin(theta);
    wall = std::min(c > 0 ? h_in / c : INFINITY, s > 0 ? solid.entry_half_width / s : INFINITY);
  }
  return {sample.x + (wall - distance), theta * 180 / std::numbers::pi};
}

/// One panel: the points coloured by `value` on a linear scale from 0, its colour bar.
void contact_panel(const Canvas& canvas, const Rect& area, const PictureData& data,
                   const std::vector<Pixel>& where, Real (*value)(const post::ContactSample&),
                   const std::string& title) {
  const auto& contact = data.results.contact;
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY, high = 0.0;
  for (std::size_t k = 0; k < contact.size(); ++k) {
    x0 = std::min(x0, where[k][0]);
    x1 = std::max(x1, where[k][0]);
    y0 = std::min(y0, where[k][1]);
    y1 = std::max(y1, where[k][1]);
    high = std::max(high, value(contact[k]));
  }
  const bool slab = data.case_.mesh.solid.section == mesh::ChannelSection::Slab;
  const Axes axes(area, Axis{x0, x1, false, {}, "x + (wall distance − distance): unrolled"},
                  Axis{y0, y1, false, {}, slab ? "z" : "angle about the axis [°]"});
  ColourScale scale = ColourScale::linear(0.0, high > 0 ? high : 1.0, 8, Palette::Sequential);
  // A mark about the spacing of the points on screen (they come from a surface rule).
  const double spacing = std::sqrt(area.width * area.height /
                                   std::max<double>(1.0, static_cast<double>(contact.size())));
  const double side = std::clamp(0.9 * spacing, 2.0, 10.0);
  canvas.clip(area);
  for (std::size_t k = 0; k < contact.size(); ++k) {
    const Pixel at = axes.at(where[k][0], where[k][1]);
    canvas.fill_rect({at[0] - side / 2, at[1] - side / 2, side, side},
                     scale.band_colour(scale.band_of(value(contact[k]))));
  }
  canvas.unclip();
  axes.draw(canvas, false);
  draw_colour_bar(canvas, {area.right() + 26, area.y, 18, area.height}, scale, title);
}

} // namespace

std::span<const std::string> solid_picture_names() {
  static const std::vector<std::string> names = {"strain_rate_z0",  "pressure_z0",
                                                 "strain_rate_y0",  "pressure_y0",
                                                 "contact_surface", "convergence"};
  return names;
}

void draw_contact_surface(const Canvas& canvas, const PictureData& data) {
  draw_title(canvas, "Contact pressure and friction stress over the die surface (unrolled)",
             run_description(data.case_, data.results));
  const auto& contact = data.results.contact;
  const Rect top{92, 72, 660, 200}, bottom{92, 330, 660, 200};
  if (contact.empty()) {
    draw_no_data(canvas, {top.x, top.y, top.width, bottom.bottom() - top.y}, "no contact points");
    return;
  }
  std::vector<Pixel> where;
  for (const post::ContactSample& sample : contact) where.push_back(unrolled(data.case_, sample));
  contact_panel(
      canvas, top, data, where, [](const post::ContactSample& s) { return s.contact_pressure; },
      "contact pressure −σ_{N}");
  contact_panel(
      canvas, bottom, data, where, [](const post::ContactSample& s) { return s.friction_stress; },
      "friction stress |σ_{T}|");
}

std::vector<Picture> render_solid_pictures(const Case& case_, const mesh::Mesh<3>& mesh,
                                           const post::Results& results) {
  const PlaneSection z0 = symmetry_section(mesh, 2), y0 = symmetry_section(mesh, 1);
  const post::Results on_z0 = section_results(results, z0), on_y0 = section_results(results, y0);
  const PictureData z0_data{case_, z0.mesh, on_z0, "y"}, y0_data{case_, y0.mesh, on_y0, "z"};
  using DrawPicture = void (*)(const Canvas&, const PictureData&);
  struct Drawing {
    DrawPicture draw;
    const PictureData* data;
    const char* note; // which plane a section shows, in the corner
  };
  const Drawing drawings[] = {
      {draw_strain_rate, &z0_data, "section z = 0"}, {draw_pressure, &z0_data, "section z = 0"},
      {draw_strain_rate, &y0_data, "section y = 0"}, {draw_pressure, &y0_data, "section y = 0"},
      {draw_contact_surface, &z0_data, ""},          {draw_convergence, &z0_data, ""}};
  const std::span<const std::string> names = solid_picture_names();
  FF_ASSERT(names.size() == std::size(drawings), "one name per picture");
  std::vector<Picture> out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Drawing drawing = drawings[k];
    // A solid mesh without that symmetry plane (a box with walls there) has no section.
    if (*drawing.note && drawing.data->mesh.n_cells() == 0) continue;
    const DrawFunction function = [&results, drawing](Canvas& canvas) {
      drawing.draw(canvas, *drawing.data);
      if (*drawing.note)
        canvas.text({canvas.width() - 12, 20}, drawing.note, Font{13.0, true, {0.2, 0.2, 0.2}},
                    HAlign::Right, VAlign::Top);
      if (!results.converged()) draw_not_converged_mark(canvas, results.stop_reason);
    };
    out.push_back({names[k], render_png(picture_width, picture_height, function),
                   render_svg(picture_width, picture_height, function)});
  }
  return out;
}

} // namespace formflow::io::plot
