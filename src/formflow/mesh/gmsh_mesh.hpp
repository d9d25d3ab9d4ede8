// SPDX-License-Identifier: MIT
// Gmsh meshes (generated or read from a .msh file) as formflow meshes.
#pragma once

#include "formflow/mesh/gmsh_session.hpp"
#include "formflow/mesh/mesh.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace formflow::mesh {

/// A physical group name of the Gmsh model and the boundary part its curves are.
struct PhysicalBoundary {
  std::string name;
  BoundaryLabel label = BoundaryLabel::Rear;
};

/// Our lexicographic local node (fem/lagrange.hpp) of node `gmsh_node` of a
/// Gmsh quad-4 (`order` 1) or quad-9 (`order` 2).
int lexicographic_of_gmsh_node(int order, int gmsh_node);

/// What is wrong with a Gmsh mesh, and which input is at fault, so that the
/// caller can name the case key: the file itself, one physical group of the
/// boundary map, the element kind, or the boundary map as a whole.
struct MeshFileError : std::runtime_error {
  /// Cell: the file's cells are of the other shape than mesh.cell asks for.
  enum class Subject { File, Group, Element, Cell, Boundaries };
  Subject subject;
  std::string group; ///< the physical name concerned (Subject::Group), else empty
  std::string message;
  std::string hint;

  MeshFileError(Subject subject_, std::string group_, std::string message_, std::string hint_)
      : std::runtime_error(message_), subject(subject_), group(std::move(group_)),
        message(std::move(message_)), hint(std::move(hint_)) {}
};

/// Converts the current model of `session`: its 2D elements become the cells
/// (Gmsh quad-4 → Q1, quad-9 → Q2, reordered lexicographically; with `shape` =
/// Simplex tri-3 → P1, tri-6 → P2, already in our order; clockwise
/// cells are mirrored to counter-clockwise), the cell faces used by one cell
/// only are the boundary facets, labelled by the physical curve groups named
/// in `boundaries`. Several names may map to one part; an empty `boundaries`
/// maps the physical curves named like a part ("rear", "die", ...) to that
/// part. Throws MeshFileError
/// for: no 2D elements, elements other than quadrilaterals of `order`
/// (triangles, 8-node serendipity quadrilaterals, mixed orders), a mapped name
/// that is not a physical curve group, a named physical curve on the boundary
/// that is not mapped, a mapped curve element not on the boundary or in two
/// parts, and boundary facets without a label.
/// The Jacobian of the cells is not checked here (see fem::CellValues).
Mesh<2> mesh_from_gmsh_model(const GmshSession& session,
                             const std::vector<PhysicalBoundary>& boundaries, int order,
                             CellShape shape = CellShape::Cube);

/// Reads a mesh file through Gmsh (.msh 4.1 or 2.2, ASCII or binary) and
/// converts it as mesh_from_gmsh_model does. The file is data, never a
/// script: its header is checked first (mesh/msh_header.hpp) and Gmsh reads a
/// private copy (mesh/msh_file.hpp). A missing or unreadable file, or one that
/// is not MSH, is a MeshFileError with Subject::File.
Mesh<2> read_gmsh_mesh(const std::string& path, const std::vector<PhysicalBoundary>& boundaries,
                       int order, CellShape shape = CellShape::Cube);

/// Writes the mesh of the current model of `session` as .msh format 4.1.
void write_gmsh_mesh(const GmshSession& session, const std::string& path, bool binary);

} // namespace formflow::mesh
