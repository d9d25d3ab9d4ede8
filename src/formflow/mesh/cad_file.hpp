// SPDX-License-Identifier: MIT
// A CAD file (mesh.cad_file) checked as data before OpenCASCADE reads it.
#pragma once

#include <optional>
#include <string>

namespace formflow::mesh {

/// What OpenCASCADE's importer is told a checked file is.
enum class CadFormat { Step, Brep };

/// The format name Gmsh's occ::importShapes takes ("step", "brep").
inline const char* cad_format_name(CadFormat format) {
  return format == CadFormat::Step ? "step" : "brep";
}

/// The file's format, or what is wrong: not a readable regular file (a FIFO or device is
/// never opened), larger than 256 MB, an extension other than .step/.stp/.brep/.brp, or
/// a first line that is not the format's own (STEP: "ISO-10303-21;"; BREP: "DBRep_" or
/// "CASCADE Topology"). Only these two readers of OpenCASCADE ever see the file, with
/// the format forced: nothing in it can run Gmsh's script parser. The message never
/// quotes the file's bytes.
struct CadFileCheck {
  std::optional<CadFormat> format;
  std::string problem, hint;
};
CadFileCheck check_cad_file(const std::string& path);

} // namespace formflow::mesh
