// SPDX-License-Identifier: MIT
// Building the channel geometry with Gmsh's built-in CAD kernel and meshing it.
#include "formflow/mesh/gmsh_channel.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/gmsh_mesh.hpp"

#include <gmsh.h>

#include <map>

namespace formflow::mesh {

namespace {

namespace geo = gmsh::model::geo;

/// Adds the segments of the polyline `points` as one part; returns their curve tags.
std::vector<int> add_polyline(const std::vector<int>& points) {
  std::vector<int> curves;
  for (std::size_t k = 0; k + 1 < points.size(); ++k)
    curves.push_back(geo::addLine(points[k], points[k + 1]));
  return curves;
}

void add_part(BoundaryLabel label, const std::vector<int>& curves) {
  const int group = gmsh::model::addPhysicalGroup(1, curves);
  // Gmsh 4.8's addPhysicalGroup takes no name.
  gmsh::model::setPhysicalName(1, group, std::string(label_name(label)));
}

} // namespace

ChannelModel add_channel_geometry(const ChannelGeometry& geometry,
                                  const std::vector<Point<2>>& die_face, Real size) {
  FF_ASSERT(die_face.size() >= 2, "the die face needs two points");
  const Real front = die_face.back().x() + geometry.exit_length;
  auto point = [size](Real x, Real y) { return geo::addPoint(x, y, 0.0, size); };
  // The boundary counter-clockwise: symmetry, front, free exit, die face
  // (from the exit up), container wall, rear.
  const int origin = point(0.0, 0.0);
  const int front_bottom = point(front, 0.0);
  const int front_top = point(front, geometry.exit_half_height);
  std::vector<int> die;
  for (auto p = die_face.rbegin(); p != die_face.rend(); ++p) die.push_back(point(p->x(), p->y()));
  const int rear_top = point(0.0, geometry.entry_half_height);

  ChannelModel model;
  model.parts = {{BoundaryLabel::Symmetry, add_polyline({origin, front_bottom})},
                 {BoundaryLabel::Front, add_polyline({front_bottom, front_top})},
                 {BoundaryLabel::FreeExit, add_polyline({front_top, die.front()})},
                 {BoundaryLabel::Die, add_polyline(die)},
                 {BoundaryLabel::Container, add_polyline({die.back(), rear_top})},
                 {BoundaryLabel::Rear, add_polyline({rear_top, origin})}};
  std::vector<int> loop;
  for (const auto& [label, curves] : model.parts)
    loop.insert(loop.end(), curves.begin(), curves.end());
  model.surface = geo::addPlaneSurface({geo::addCurveLoop(loop)});
  return model;
}

void set_triangle_options(Real size) {
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 0);
}

void set_recombined_quadrilateral_options(Real size) {
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  // Frontal-Delaunay triangles recombined by the blossom algorithm into an
  // all-quadrilateral mesh. (The quad-oriented algorithm 8 crashes in Gmsh 4.8.4.)
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 0); // quad-9/hexa-27, not serendipity
}

void build_channel_model(const GmshSession& session, const ChannelGeometry& geometry,
                         const std::vector<Point<2>>& die_face, Real size, int order,
                         const std::function<void()>& size_field, CellShape shape) {
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  session.call([&] {
    gmsh::model::add("channel");
    const ChannelModel model = add_channel_geometry(geometry, die_face, size);
    geo::synchronize();
    for (const auto& [label, curves] : model.parts) add_part(label, curves);
    // Only elements in a physical group are written to a .msh: the surface too.
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {model.surface}), "domain");
    if (shape == CellShape::Simplex)
      set_triangle_options(size);
    else
      set_recombined_quadrilateral_options(size);
    if (size_field) size_field();
    gmsh::model::mesh::generate(2);
    if (order == 2) gmsh::model::mesh::setOrder(2);
  });
}

Mesh<2> make_gmsh_channel_mesh(const ChannelGeometry& geometry,
                               const std::vector<Point<2>>& die_face, Real size, int order,
                               CellShape shape) {
  GmshSession session;
  build_channel_model(session, geometry, die_face, size, order, {}, shape);
  try {
    return mesh_from_gmsh_model(session, {}, order, shape); // the groups carry the part names
  } catch (const MeshFileError& error) {
    // Our own geometry: a failure here is a bug, not the user's input.
    throw InternalError("Gmsh channel mesh: " + error.message);
  }
}

} // namespace formflow::mesh
