// SPDX-License-Identifier: MIT
// Filled contour bands on Q1/Q2 and simplex cells by exact clipping of linear pieces.
#include "formflow/io/plot/mesh_drawing.hpp"

#include "formflow/fem/reference_element.hpp"
#include "formflow/io/plot/polygon_outlines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace formflow::io::plot {

namespace {

/// A polygon vertex carrying the (display-scale) field value.
struct Vertex {
  Pixel at;
  double value;
};

/// Sutherland–Hodgman against one half-space of the value: keeps value ≥ level
/// (`keep_above`) or ≤ level. The field is linear on a triangle, so the cut is exact.
std::vector<Vertex> clip(const std::vector<Vertex>& polygon, double level, bool keep_above) {
  std::vector<Vertex> out;
  auto inside = [&](const Vertex& v) { return keep_above ? v.value >= level : v.value <= level; };
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vertex& a = polygon[i];
    const Vertex& b = polygon[(i + 1) % polygon.size()];
    if (inside(a)) out.push_back(a);
    if (inside(a) != inside(b)) {
      const double w = (level - a.value) / (b.value - a.value);
      out.push_back(
          {{a.at[0] + w * (b.at[0] - a.at[0]), a.at[1] + w * (b.at[1] - a.at[1])}, level});
    }
  }
  return out;
}

/// Band boundaries in display coordinates, and band lookup in them.
struct Bands {
  std::vector<double> levels;
  std::size_t band_of(double display) const {
    const auto above = std::upper_bound(levels.begin() + 1, levels.end() - 1, display);
    return static_cast<std::size_t>(above - levels.begin()) - 1;
  }
};

/// Polygons to fill, per band: each band becomes one path of its pieces' outlines (the
/// edges the pieces share cancel), so the SVG gets one element per band holding only
/// the band's boundary, and same-band pieces show no seams.
using BandPolygons = std::vector<std::vector<std::vector<Pixel>>>;

/// Cuts a small polygon (a sub-quad; the field is taken as linear along its
/// edges) at the band boundaries it straddles.
void split_into_bands(const std::vector<Vertex>& polygon, const Bands& bands, BandPolygons& out) {
  double low = polygon[0].value, high = low;
  for (const Vertex& v : polygon) {
    low = std::min(low, v.value);
    high = std::max(high, v.value);
  }
  const std::size_t first = bands.band_of(low), last = bands.band_of(high);
  for (std::size_t band = first; band <= last; ++band) {
    std::vector<Vertex> piece = polygon;
    // The end bands are open so values beyond the scale take the end colours.
    if (band > 0) piece = clip(piece, bands.levels[band], true);
    if (band + 1 < out.size() && piece.size() >= 3)
      piece = clip(piece, bands.levels[band + 1], false);
    if (piece.size() < 3) continue;
    std::vector<Pixel> pixels;
    for (const Vertex& v : piece) pixels.push_back(v.at);
    out[band].push_back(std::move(pixels));
  }
}

/// The sample points of `ring` (indices into `points`), in order.
std::vector<Pixel> ring_points(const std::vector<Pixel>& points, const std::vector<int>& ring) {
  std::vector<Pixel> out;
  out.reserve(ring.size());
  for (const int k : ring) out.push_back(points[static_cast<std::size_t>(k)]);
  return out;
}

/// Sub-divisions per cell side: about 6 px per piece, at least 2 for Q2
/// (its fields are quadratic), at most 8 so fine meshes do not bloat the SVG.
int subdivisions_for(const Axes& axes, const mesh::Mesh<2>& mesh) {
  return std::clamp(static_cast<int>(std::lround(cell_pixels(axes, mesh) / 6.0)), mesh.order, 8);
}

} // namespace

double cell_pixels(const Axes& axes, const mesh::Mesh<2>& mesh) {
  Real area = 0.0;
  // Corners counter-clockwise: triangles 0, 1, 2; quadrilaterals (lexicographic nodes)
  // 0, n−1, n²−1, n(n−1). The shoelace over them.
  std::vector<int> corners = {0, 1, 2};
  if (!mesh.is_simplex()) {
    const int n = mesh.nodes_per_side();
    corners = {0, n - 1, n * n - 1, n * (n - 1)};
  }
  const std::size_t n_corners = corners.size();
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (std::size_t k = 0; k < n_corners; ++k) {
      const Index a = mesh.cells(corners[k], cell);
      const Index b = mesh.cells(corners[(k + 1) % n_corners], cell);
      area += 0.5 * (mesh.nodes(0, a) * mesh.nodes(1, b) - mesh.nodes(0, b) * mesh.nodes(1, a));
    }
  const double px_per_unit = std::abs(axes.px(1.0) - axes.px(0.0));
  return std::sqrt(std::abs(area) / std::max<Index>(mesh.n_cells(), 1)) * px_per_unit;
}

Box bounding_box(const mesh::Mesh<2>& mesh) {
  if (mesh.n_nodes() == 0) return {};
  return {mesh.nodes.row(0).minCoeff(), mesh.nodes.row(0).maxCoeff(), mesh.nodes.row(1).minCoeff(),
          mesh.nodes.row(1).maxCoeff()};
}

CellSampler::CellSampler(const mesh::CellType& type, int subdivisions)
    : subdivisions_(subdivisions) {
  const int n = subdivisions, side = n + 1;
  std::vector<Point<2>> reference;
  if (type.is_simplex()) {
    // Lattice point (i, j), i + j ≤ n, row by row: index of row j starts after the
    // rows below it, which hold side, side − 1, ... points.
    std::vector<int> row_start(static_cast<std::size_t>(side) + 1, 0);
    for (int j = 0; j < side; ++j) row_start[j + 1] = row_start[j] + side - j;
    const auto at = [&](int i, int j) { return row_start[j] + i; };
    for (int j = 0; j < side; ++j)
      for (int i = 0; i + j <= n; ++i) reference.emplace_back(Real(i) / n, Real(j) / n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        pieces_.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < n) pieces_.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    for (int i = 0; i < n; ++i) ring_.push_back(at(i, 0));     // vertex 0 → 1
    for (int j = 0; j < n; ++j) ring_.push_back(at(n - j, j)); // vertex 1 → 2
    for (int j = n; j > 0; --j) ring_.push_back(at(0, j));     // vertex 2 → 0
  } else {
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) reference.emplace_back(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * side + i;
        pieces_.push_back({a, a + 1, a + side + 1, a + side});
      }
    for (int i = 0; i < n; ++i) ring_.push_back(i);
    for (int j = 0; j < n; ++j) ring_.push_back(j * side + n);
    for (int i = n; i > 0; --i) ring_.push_back(n * side + i);
    for (int j = n; j > 0; --j) ring_.push_back(j * side);
  }
  shape_.resize(static_cast<Index>(reference.size()), mesh::nodes_per_cell<2>(type));
  VectorX values;
  Eigen::Matrix<Real, 2, Eigen::Dynamic> gradients;
  for (std::size_t p = 0; p < reference.size(); ++p) {
    fem::tabulate_shape<2>(type, reference[p], values, gradients);
    shape_.row(static_cast<Index>(p)) = values.transpose();
  }
}

void CellSampler::sample(const mesh::Mesh<2>& mesh, Index cell, const VectorX& nodal,
                         const Axes& axes, std::vector<Pixel>& points,
                         std::vector<double>& values) const {
  const auto n_points = static_cast<std::size_t>(shape_.rows());
  points.resize(n_points);
  values.resize(n_points);
  for (std::size_t p = 0; p < n_points; ++p) {
    double x = 0.0, y = 0.0, value = 0.0;
    for (Index local = 0; local < shape_.cols(); ++local) {
      const Index node = mesh.cells(local, cell);
      const double weight = shape_(static_cast<Index>(p), local);
      x += weight * mesh.nodes(0, node);
      y += weight * mesh.nodes(1, node);
      value += weight * nodal[node];
    }
    points[p] = axes.at(x, y);
    values[p] = value;
  }
}

void fill_field_bands(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh,
                      const VectorX& nodal, const ColourScale& scale) {
  Bands bands;
  for (const double boundary : scale.boundaries()) bands.levels.push_back(scale.display(boundary));
  const CellSampler sampler(mesh.cell_type(), subdivisions_for(axes, mesh));
  BandPolygons polygons(scale.n_bands());
  std::vector<Pixel> points;
  std::vector<double> values;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    sampler.sample(mesh, cell, nodal, axes, points, values);
    for (double& value : values) value = scale.display(value);
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    // Most cells lie inside one band: one polygon instead of s² keeps the SVG small.
    if (bands.band_of(*low) == bands.band_of(*high)) {
      polygons[bands.band_of(*low)].push_back(ring_points(points, sampler.ring()));
      continue;
    }
    std::vector<Vertex> piece;
    for (const std::vector<int>& corners : sampler.pieces()) {
      piece.clear();
      for (const int k : corners)
        piece.push_back({points[static_cast<std::size_t>(k)], values[static_cast<std::size_t>(k)]});
      split_into_bands(piece, bands, polygons);
    }
  }
  // The 86 514-dof adaptive ram's strain rate: 3.45 MB of SVG with every piece drawn,
  // 0.57 MB outlined; its results are written 0.3 s sooner (docs/benchmarks.md).
  for (std::size_t band = 0; band < polygons.size(); ++band)
    canvas.fill_polygons(merged_outlines(polygons[band]), scale.band_colour(band), true);
}

void draw_cell_edges(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh,
                     const Stroke& stroke) {
  if (cell_pixels(axes, mesh) < 6.0) return;
  const CellSampler sampler(mesh.cell_type(), mesh.order == 2 ? 4 : 1);
  const VectorX zeros = VectorX::Zero(mesh.n_nodes());
  std::vector<Pixel> points;
  std::vector<double> values;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    sampler.sample(mesh, cell, zeros, axes, points, values);
    canvas.polyline(ring_points(points, sampler.ring()), stroke, true);
  }
}

void draw_boundary(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh) {
  const Stroke outline{1.2, {0.25, 0.25, 0.25}};
  const Stroke symmetry{1.0, {0.25, 0.25, 0.25}, 1.0, 8.0};
  const Stroke die{4.5, {0.08, 0.08, 0.08}};
  // Die last, so its thick line covers the thin outline where they meet.
  for (const bool die_pass : {false, true})
    for (const mesh::BoundaryFacet& facet : mesh.facets) {
      if (mesh::is_contact(facet.label) != die_pass) continue;
      std::vector<Pixel> points;
      for (const int local : mesh.face_nodes(facet.local_face)) {
        const Index node = mesh.cells(local, facet.cell);
        points.push_back(axes.at(mesh.nodes(0, node), mesh.nodes(1, node)));
      }
      const bool is_symmetry = facet.label == mesh::BoundaryLabel::Symmetry;
      canvas.polyline(points, die_pass ? die : is_symmetry ? symmetry : outline);
    }
}

void label_contact_parts(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh) {
  for (const auto& [label, name] : {std::pair{mesh::BoundaryLabel::Container, "container wall"},
                                    std::pair{mesh::BoundaryLabel::Die, "die"}}) {
    Point<2> middle = Point<2>::Zero(), normal = Point<2>::Zero();
    Real length = 0.0;
    for (const mesh::BoundaryFacet& facet : mesh.facets) {
      if (facet.label != label) continue;
      const std::vector<int> nodes = mesh.face_nodes(facet.local_face);
      const Point<2> first = mesh.nodes.col(mesh.cells(nodes.front(), facet.cell));
      const Point<2> last = mesh.nodes.col(mesh.cells(nodes.back(), facet.cell));
      Point<2> centre = Point<2>::Zero();
      for (int local = 0; local < mesh.nodes_per_cell(); ++local)
        centre += mesh.nodes.col(mesh.cells(local, facet.cell)) / mesh.nodes_per_cell();
      const Point<2> tangent = last - first;
      Point<2> outward(tangent.y(), -tangent.x());
      if (outward.dot(0.5 * (first + last) - centre) < 0) outward = -outward;
      middle += 0.5 * (first + last) * tangent.norm();
      normal += outward; // |outward| = facet length: a length-weighted mean direction
      length += tangent.norm();
    }
    if (!(length > 0)) continue;
    middle /= length;
    normal.normalize();
    // Screen y points down.
    const Pixel at{axes.px(middle.x()) + 10.0 * normal.x(),
                   axes.py(middle.y()) - 10.0 * normal.y()};
    const bool sideways = std::abs(normal.x()) > std::abs(normal.y());
    const HAlign h = !sideways ? HAlign::Centre : normal.x() > 0 ? HAlign::Left : HAlign::Right;
    const VAlign v = sideways ? VAlign::Middle : normal.y() > 0 ? VAlign::Bottom : VAlign::Top;
    canvas.text(at, name, Font{12.0, true, {0.08, 0.08, 0.08}}, h, v);
  }
}

} // namespace formflow::io::plot
