// SPDX-License-Identifier: MIT
// Drawing a 2D Q1/Q2 mesh and nodal fields on it: filled contour bands, cell edges, boundary.
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/io/plot/axes.hpp"
#include "formflow/io/plot/canvas.hpp"
#include "formflow/io/plot/colour_map.hpp"
#include "formflow/mesh/mesh.hpp"

#include <vector>

namespace formflow::io::plot {

/// The data box of a mesh.
struct Box {
  double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
};

/// Smallest box containing every node.
Box bounding_box(const mesh::Mesh<2>& mesh);

/// Typical cell side on screen in pixels: the root of the mean cell area
/// (corner polygon) drawn with the x scale of `axes`.
double cell_pixels(const Axes& axes, const mesh::Mesh<2>& mesh);

/// Samples a nodal field and the geometry of a cell at reference points through the
/// cell's own shape functions, so Q2/P2 fields and curved cells are drawn as the solver
/// sees them: an (s+1)×(s+1) grid of a quadrilateral, or the triangular lattice
/// {(i, j)/s : i + j ≤ s} of a triangle.
class CellSampler {
public:
  CellSampler(const mesh::CellType& type, int subdivisions);
  int subdivisions() const { return subdivisions_; }
  /// Sample points of `cell` in pixels, and the field there (the order of pieces()).
  void sample(const mesh::Mesh<2>& mesh, Index cell, const VectorX& nodal, const Axes& axes,
              std::vector<Pixel>& points, std::vector<double>& values) const;
  /// The small quadrilaterals (or triangles) that tile the cell, as sample-point indices
  /// counter-clockwise in the reference cell.
  const std::vector<std::vector<int>>& pieces() const { return pieces_; }
  /// The sample points along the cell's boundary, counter-clockwise.
  const std::vector<int>& ring() const { return ring_; }

private:
  int subdivisions_;
  MatrixX shape_; ///< (sample points, nodes per cell) shape values at the sample points
  std::vector<std::vector<int>> pieces_;
  std::vector<int> ring_;
};

/// Filled contours of `nodal` (one value per mesh node): each cell is split
/// into small quads and triangles, and each triangle is cut exactly at the
/// band boundaries of `scale` (linear in scale.display()).
void fill_field_bands(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh,
                      const VectorX& nodal, const ColourScale& scale);

/// Thin cell edges (through the mid-side nodes of Q2 cells); skipped when the
/// cells are too small on screen to show anything but grey.
void draw_cell_edges(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh,
                     const Stroke& stroke);

/// The boundary: thin outline, dashed symmetry line, and the die — the
/// `container` and `die` facets — as a thick dark line.
void draw_boundary(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh);

/// Names the contact parts ("container wall", "die") just outside the middle
/// of each, so the thick line reads as tooling, not as part of the field.
void label_contact_parts(const Canvas& canvas, const Axes& axes, const mesh::Mesh<2>& mesh);

} // namespace formflow::io::plot
