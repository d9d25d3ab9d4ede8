// SPDX-License-Identifier: MIT
// What a mesh of a case is made from: the mesh layer's own parameter struct.
#pragma once

#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/cell_type.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/mesh_source.hpp"
#include "formflow/mesh/solid_channel.hpp"

#include <map>
#include <string>

namespace formflow::mesh {

/// Everything io::load_mesh (and the verification box mesh) reads to make the
/// cells, so that mesh sequencing (app/coarse_start.cpp) varies one small
/// struct instead of copying the whole case. The velocity element
/// (`mesh.element`) is fem's choice and stays in the case: the mesh layer sees
/// only the cells' polynomial order, which the caller passes beside the spec.
struct MeshSpec {
  MeshSource source = MeshSource::Structured; ///< mesh.source
  /// mesh.cell: quadrilaterals or triangles in 2D, hexahedra or tetrahedra in 3D (the
  /// case's resolution makes an unset key the cube of geometry.dimension).
  CellKind cell = CellKind::Quadrilateral;
  /// mesh.size: side of the structured cells, Gmsh's target size, the box mesh's
  /// cell side (1/size cells per direction); unused for a file.
  Real size = 1.0;
  /// mesh.bearing_size: a profile's cells along the bearing (0: size / 2); bearing_cell()
  Real bearing_size = 0.0;
  Real bearing_cell() const { return bearing_size > 0 ? bearing_size : 0.5 * size; }
  ChannelGeometry geometry; ///< geometry.*: the die channel (structured and gmsh)
  /// geometry.dimension: 2 (quadrilaterals of the plane channel) or 3 (hexahedra of
  /// the solid channel `solid`).
  int dimension = 2;
  SolidChannel solid;   ///< geometry.section, .thickness, .*_half_width: used when dimension = 3
  std::string cad_file; ///< mesh.cad_file: STEP/BREP path as written (relative: to the case's)
  std::string file; ///< mesh.file: .msh path as written (relative: to the case file's directory)
  /// mesh.boundaries: physical group name in `file` → boundary part name
  /// (mesh::label_name); empty: the physical names are the part names themselves.
  std::map<std::string, std::string> boundaries;
  BoxDistortion distortion; ///< verification.distortion/amplitude/seed: the box mesh's
};

} // namespace formflow::mesh
