// SPDX-License-Identifier: MIT
// write_results: every output file of a run, each written atomically.
#include "formflow/io/results_writer.hpp"

#include "formflow/io/atomic_file.hpp"
#include "formflow/io/csv.hpp"
#include "formflow/io/plot/pictures.hpp"
#include "formflow/io/vtu.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace formflow::io {

void write_results(const std::string& directory, const Case& case_, const mesh::Mesh<2>& mesh,
                   const post::Results& results) {
  // Everything is built (and checked for non-finite numbers) in memory first:
  // if any check fails, no file of this run is written at all, rather than a
  // mix of new and stale files.
  std::vector<std::pair<std::string, std::string>> files;
  files.emplace_back("summary.json", summary_json(case_, results));
  files.emplace_back("history.csv", history_csv(results.history));
  files.emplace_back("contact.csv", contact_csv(results.contact));
  files.emplace_back("fields.vtu", fields_vtu(mesh, results.fields));
  for (plot::Picture& picture : plot::render_pictures(case_, mesh, results)) {
    files.emplace_back(picture.name + ".png", std::move(picture.png));
    files.emplace_back(picture.name + ".svg", std::move(picture.svg));
  }

  const std::filesystem::path root(directory);
  std::filesystem::create_directories(root);
  for (const auto& [name, contents] : files) write_file_atomically(root / name, contents);
}

} // namespace formflow::io
