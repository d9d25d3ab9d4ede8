// SPDX-License-Identifier: MIT
// Writes every result file of a run into an output directory, atomically.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"

#include <string>

namespace formflow::io {

/// Writes summary.json, history.csv, contact.csv, fields.vtu and the pictures
/// into `directory` (created if missing). Each file goes to a temporary name
/// first and is renamed into place, so no file is ever half-written.
/// Non-finite numbers are never written (they would become JSON null).
void write_results(const std::string& directory, const Case& case_, const mesh::Mesh<2>& mesh,
                   const post::Results& results);

/// The summary.json document as text (also what `formflow run --json` prints).
std::string summary_json(const Case& case_, const post::Results& results);

} // namespace formflow::io
