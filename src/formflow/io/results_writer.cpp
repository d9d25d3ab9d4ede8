// SPDX-License-Identifier: MIT
// write_results: every output file of a run, published as one set.
#include "formflow/io/results_writer.hpp"

#include "formflow/io/csv.hpp"
#include "formflow/io/plot/pictures.hpp"
#include "formflow/io/plot/solid_pictures.hpp"
#include "formflow/io/pvtu.hpp"
#include "formflow/io/report_html.hpp"
#include "formflow/io/result_set.hpp"
#include "formflow/io/vtu.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace formflow::io {

std::span<const std::string> result_file_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = {"summary.json", "history.csv", "contact.csv", "fields.vtu",
                                    "report.html"};
    // The plane pictures and the solid ones: either set replaces the other's files.
    for (const auto& names : {plot::picture_names(), plot::solid_picture_names()})
      for (const std::string& picture : names) {
        if (std::find(all.begin(), all.end(), picture + ".png") != all.end()) continue;
        all.push_back(picture + ".png");
        all.push_back(picture + ".svg");
      }
    // Hot forming's picture (written only when thermal.enabled; listed so that a stale
    // one is removed from a directory an isothermal run reuses).
    all.push_back("temperature.png");
    all.push_back("temperature.svg");
    // A distributed run's fields.pvtu and its pieces, one per rank (listed for up to 256
    // ranks, so that a later run removes the stale ones).
    all.push_back("fields.pvtu");
    for (int part = 0; part < 256; ++part) all.push_back(piece_name(part));
    return all;
  }();
  return names;
}

template <int dim>
void write_results(const std::string& directory, const Case& case_, const mesh::Mesh<dim>& mesh,
                   const post::Results& results, const StopRequested& stop_requested) {
  // Everything is built (and checked for non-finite numbers) in memory first:
  // if any check fails, no file of this run is written at all.
  std::vector<ResultFile> files;
  files.push_back({"summary.json", summary_json(case_, results)});
  files.push_back({"history.csv", history_csv(results.history, results.stop_reason)});
  files.push_back({"contact.csv", contact_csv(results.contact, results.stop_reason, dim)});
  files.push_back({"fields.vtu", fields_vtu(mesh, results.fields, results.stop_reason)});
  // A distributed run: also the parallel VTU, one piece per rank's cells (every rank
  // holds the whole velocity in this first slice, so rank 0 writes them all).
  if (const int ranks = results.linear_algebra.ranks; ranks > 1)
    for (auto& [name, text] :
         fields_pvtu(mesh, results.fields, results.stop_reason, ranks, results.cell_ranks))
      files.push_back({std::move(name), std::move(text)});
  if (is_stop_requested(stop_requested)) throw Stopped("stopped before drawing the pictures");
  // The plane pictures, or a solid run's sections and unrolled die surface.
  std::vector<ReportPicture> report_pictures;
  std::vector<plot::Picture> pictures;
  if constexpr (dim == 2)
    pictures = plot::render_pictures(case_, mesh, results);
  else
    pictures = plot::render_solid_pictures(case_, mesh, results);
  for (plot::Picture& picture : pictures) {
    report_pictures.push_back({picture.name, picture.svg});
    files.push_back({picture.name + ".png", std::move(picture.png)});
    files.push_back({picture.name + ".svg", std::move(picture.svg)});
  }
  files.push_back({"report.html", report_html(case_, results, report_pictures)});
  publish_result_set(directory, files, "summary.json", result_file_names(), stop_requested);
}

void write_results(const std::string& directory, const Case& case_, const mesh::AnyMesh& mesh,
                   const post::Results& results, const StopRequested& stop_requested) {
  std::visit(
      [&](const auto& typed) { write_results(directory, case_, typed, results, stop_requested); },
      mesh);
}

template void write_results<2>(const std::string&, const Case&, const mesh::Mesh<2>&,
                               const post::Results&, const StopRequested&);
template void write_results<3>(const std::string&, const Case&, const mesh::Mesh<3>&,
                               const post::Results&, const StopRequested&);

} // namespace formflow::io
