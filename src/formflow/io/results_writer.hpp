// SPDX-License-Identifier: MIT
// Writes every result file of a run into an output directory, as one atomic set.
#pragma once

#include "formflow/core/stop_request.hpp"
#include "formflow/io/case.hpp"
#include "formflow/mesh/any_mesh.hpp"
#include "formflow/post/results.hpp"

#include <span>
#include <string>

namespace formflow::io {

/// Every file a run of any kind may write: summary.json, history.csv, contact.csv,
/// fields.vtu, report.html (io/report_html.hpp), each plane and solid picture's .png and
/// .svg, and hot forming's temperature.png/.svg. A run writes a subset (temperature.*
/// only when thermal.enabled); the whole list is what it *replaces*: a file of this
/// list that the new set lacks is removed (a stale temperature.png of an earlier hot run
/// would otherwise sit beside an isothermal result), and check_output_directory takes
/// it before the solve so that nothing in the way is found only after it.
std::span<const std::string> result_file_names();

/// Writes the files of result_file_names() into `directory` (created if
/// missing) as one set (io/result_set.hpp): all built in memory first (and
/// checked for non-finite numbers: InternalError, nothing written), then
/// staged and moved in with summary.json last, so a reader sees the previous
/// set or the complete new one. `stop_requested` is asked between files
/// (throws Stopped, directory unchanged). A run that did not converge says so
/// in every file: summary.json `converged: false`, a `# not converged: <reason>`
/// first line in the CSVs, FieldData `converged` = 0 in fields.vtu and a red
/// mark on the pictures. Throws OutputError if the disk refuses the files.
/// A solid (dim = 3) run writes no pictures: they are drawings of the plane
/// channel (io/plot/), and a 3D run has no plane to draw. Its set is the three
/// data files, fields.vtu with hexahedra and contact.csv with x, y, z; pictures
/// of an earlier plane run in `directory` are moved aside with the old set.
template <int dim>
void write_results(const std::string& directory, const Case& case_, const mesh::Mesh<dim>& mesh,
                   const post::Results& results, const StopRequested& stop_requested = {});

/// write_results for the mesh of either dimension a run produced.
void write_results(const std::string& directory, const Case& case_, const mesh::AnyMesh& mesh,
                   const post::Results& results, const StopRequested& stop_requested = {});

/// The summary.json document as text (also what `formflow run --json` prints).
std::string summary_json(const Case& case_, const post::Results& results);

} // namespace formflow::io
