// SPDX-License-Identifier: MIT
// Pictures of a solid run: symmetry-plane sections drawn by the plane pictures, and
// the contact stresses over the unrolled die surface.
#include "formflow/io/plot/solid_pictures.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/plot/picture_rendering.hpp"
#include "formflow/io/plot/solid_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace formflow::io::plot {

namespace {

/// Where a Γ3 point is drawn on the unrolled die surface (draw_contact_surface).
Pixel unrolled(const Case& case_, const post::ContactSample& sample) {
  const mesh::SolidChannel& solid = case_.mesh.solid;
  const Real h_in = case_.mesh.geometry.entry_half_height;
  if (solid.section == mesh::ChannelSection::Slab) return {sample.x + (h_in - sample.y), sample.z};
  const Real theta = std::atan2(sample.z, sample.y);
  const Real distance = std::hypot(sample.y, sample.z);
  // The round billet's radius (a profile's billet has its own key).
  Real wall = solid.section == mesh::ChannelSection::Profile ? solid.profile.billet_radius : h_in;
  if (solid.section == mesh::ChannelSection::Rectangle) {
    // Along the ray at θ the container's outline is at min(H/cos θ, W/sin θ).
    const Real c = std::cos(theta), s = std::sin(theta);
    wall = std::min(c > 0 ? h_in / c : INFINITY, s > 0 ? solid.entry_half_width / s : INFINITY);
  }
  return {sample.x + (wall - distance), theta * 180 / std::numbers::pi};
}

/// The nearest of a set of screen points, each with its own reach: the distance to
/// its eighth-nearest neighbour, which on a grid of spacings a, b is the diagonal
/// √(a² + b²) (the four neighbours along the axes, then the four diagonal ones), so
/// a point's Voronoi cell is covered where the rule is uneven (a rectangle's corner
/// seen as an angle is), while the plane a diagonal beyond the outermost points stays
/// empty, whatever the axes' scales (a length and an angle).
class NearestPoints {
public:
  explicit NearestPoints(const std::vector<Pixel>& points) : points_(points) {
    if (points_.empty()) return;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const Pixel& p : points_) {
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
    const double area = std::max(1.0, (x1 - x0 + 1.0) * (y1 - y0 + 1.0));
    bucket_ = std::max(2.0, 2.0 * std::sqrt(area / static_cast<double>(points_.size())));
    for (std::size_t k = 0; k < points_.size(); ++k) buckets_[bucket_of(points_[k])].push_back(k);
    reach_.assign(points_.size(), 4.0); // a lone point: a few pixels around it
    for (std::size_t k = 0; k < points_.size(); ++k) {
      std::vector<double> distances;
      visit(points_[k], 3, [&](std::size_t j) {
        if (j != k) distances.push_back(distance(points_[j], points_[k]));
      });
      if (distances.size() >= 8) {
        std::nth_element(distances.begin(), distances.begin() + 7, distances.end());
        reach_[k] = std::max(2.0, distances[7]);
      }
      largest_reach_ = std::max(largest_reach_, reach_[k]);
    }
  }

  /// The index of the point nearest to `p` if `p` is within that point's reach, else −1.
  long within(const Pixel& p) const {
    long best = -1;
    double best_distance = INFINITY;
    visit(p, 1 + static_cast<int>(largest_reach_ / bucket_), [&](std::size_t j) {
      if (const double d = distance(points_[j], p); d < best_distance) {
        best_distance = d;
        best = static_cast<long>(j);
      }
    });
    return best >= 0 && best_distance <= reach_[static_cast<std::size_t>(best)] ? best : -1;
  }

private:
  static double distance(const Pixel& a, const Pixel& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1]);
  }
  std::pair<long, long> bucket_of(const Pixel& p) const {
    return {static_cast<long>(std::floor(p[0] / bucket_)),
            static_cast<long>(std::floor(p[1] / bucket_))};
  }
  template <class Visit> void visit(const Pixel& p, int radius, Visit&& on_point) const {
    const auto [bx, by] = bucket_of(p);
    for (long i = bx - radius; i <= bx + radius; ++i)
      for (long j = by - radius; j <= by + radius; ++j)
        if (const auto found = buckets_.find({i, j}); found != buckets_.end())
          for (const std::size_t k : found->second) on_point(k);
  }

  const std::vector<Pixel>& points_;
  double bucket_ = 2.0, largest_reach_ = 0.0;
  std::vector<double> reach_;
  std::map<std::pair<long, long>, std::vector<std::size_t>> buckets_;
};

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
  const Axes axes(area,
                  Axis{x0,
                       x1,
                       false,
                       {},
                       slab ? "unrolled: x along the container, then x + (H − y) over the die"
                            : "unrolled: x along the container, then x + (wall − distance from the "
                              "axis) over the die"},
                  Axis{y0, y1, false, {}, slab ? "z" : "angle about the axis [°]"});
  ColourScale scale = ColourScale::linear(0.0, high > 0 ? high : 1.0, 8, Palette::Sequential);
  // The points come from a surface quadrature rule: uneven (Gauss points cluster
  // towards face edges) and, on a square die's face, not on a grid of the unrolled
  // coordinates. Each 2-pixel block takes the colour of its nearest point when one is
  // within its reach, a Voronoi map: the surface is tiled without gaps and its outline
  // (where no points are) stays white.
  std::vector<Pixel> at(contact.size());
  for (std::size_t k = 0; k < contact.size(); ++k) at[k] = axes.at(where[k][0], where[k][1]);
  const NearestPoints nearest(at);
  const std::vector<int> band = [&] {
    std::vector<int> bands(contact.size());
    for (std::size_t k = 0; k < contact.size(); ++k) bands[k] = scale.band_of(value(contact[k]));
    return bands;
  }();
  constexpr double block = 2.0;
  canvas.clip(area);
  for (double y = area.y; y < area.bottom(); y += block) {
    // Runs of one colour along the row are one rectangle (a small SVG).
    int run_band = -1;
    double run_start = area.x;
    auto close_run = [&](double end) {
      if (run_band >= 0)
        canvas.fill_rect({run_start, y, end - run_start, block}, scale.band_colour(run_band));
    };
    for (double x = area.x; x < area.right(); x += block) {
      const long k = nearest.within({x + block / 2, y + block / 2});
      const int this_band = k < 0 ? -1 : band[static_cast<std::size_t>(k)];
      if (this_band != run_band) {
        close_run(x);
        run_band = this_band;
        run_start = x;
      }
    }
    close_run(area.right());
  }
  canvas.unclip();
  axes.draw(canvas, false);
  draw_colour_bar(canvas, {area.right() + 26, area.y, 18, area.height}, scale, title);
}

} // namespace

std::span<const std::string> solid_picture_names() {
  static const std::vector<std::string> names = {
      "strain_rate_z0",  "pressure_z0", "strain_rate_y0", "pressure_y0",
      "contact_surface", "convergence", "exit_velocity"};
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
  // The exit: the "front" facets on the plane x = x_end, in (y, z).
  Real x_end = -INFINITY;
  for (const mesh::BoundaryFacet& facet : mesh.facets)
    if (facet.label == mesh::BoundaryLabel::Front)
      for (const int local : mesh.face_nodes(facet.local_face))
        x_end = std::max(x_end, mesh.nodes(0, mesh.cells(local, facet.cell)));
  const PlaneSection exit = std::isfinite(x_end)
                                ? boundary_section(mesh, mesh::BoundaryLabel::Front, 0, x_end)
                                : PlaneSection{};
  const post::Results on_exit = section_results(results, exit);
  VectorX axial(static_cast<Index>(exit.solid_node.size()));
  if (results.fields.velocity.size() == 3 * results.n_nodes)
    for (std::size_t k = 0; k < exit.solid_node.size(); ++k)
      axial[static_cast<Index>(k)] = results.fields.velocity[3 * exit.solid_node[k]];
  else
    axial.resize(0);
  PictureData exit_data{case_, exit.mesh, on_exit, "z"};
  exit_data.axial_velocity = &axial;
  using DrawPicture = void (*)(const Canvas&, const PictureData&);
  struct Drawing {
    DrawPicture draw;
    const PictureData* data;
    const char* note; // which plane a section shows, in the corner
  };
  const Drawing drawings[] = {{draw_strain_rate, &z0_data, "section z = 0"},
                              {draw_pressure, &z0_data, "section z = 0"},
                              {draw_strain_rate, &y0_data, "section y = 0"},
                              {draw_pressure, &y0_data, "section y = 0"},
                              {draw_contact_surface, &z0_data, ""},
                              {draw_convergence, &z0_data, ""},
                              {draw_exit_section, &exit_data, ""}};
  const std::span<const std::string> names = solid_picture_names();
  FF_ASSERT(names.size() == std::size(drawings), "one name per picture");
  std::vector<PictureJob> jobs;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Drawing drawing = drawings[k];
    // A solid mesh without that symmetry plane (a box with walls there) has no section.
    if (*drawing.note && drawing.data->mesh.n_cells() == 0) continue;
    jobs.push_back({names[k], [&results, drawing](Canvas& canvas) {
                      drawing.draw(canvas, *drawing.data);
                      if (*drawing.note)
                        canvas.text({canvas.width() - 12, 20}, drawing.note,
                                    Font{13.0, true, {0.2, 0.2, 0.2}}, HAlign::Right, VAlign::Top);
                      if (!results.converged())
                        draw_not_converged_mark(canvas, results.stop_reason);
                    }});
  }
  return render_jobs(jobs);
}

} // namespace formflow::io::plot
