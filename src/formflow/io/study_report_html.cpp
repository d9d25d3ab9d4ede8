// SPDX-License-Identifier: MIT
// report.html of a study: the table of study.csv and the study's pictures.
#include "formflow/io/html_text.hpp"
#include "formflow/io/report_html.hpp"

#include <fmt/format.h>

#include <iterator>
#include <sstream>

namespace formflow::io {

namespace {

/// study.csv as an HTML table: the header row as <th>, an empty cell where the
/// quantity does not apply (the CSV's convention). study.csv has no quoted
/// fields (its values are numbers and words), so a comma always separates.
void csv_table(std::back_insert_iterator<std::string> out, const std::string& csv) {
  std::istringstream lines(csv);
  std::string line;
  bool header = true;
  out = fmt::format_to(out, "<table>\n");
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    out = fmt::format_to(out, "<tr>");
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      const std::string cell = line.substr(start, comma - start);
      if (header)
        out = fmt::format_to(out, "<th>{}</th>", html_escaped(cell));
      else
        out = fmt::format_to(out, "<td class=\"number\">{}</td>", html_escaped(cell));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    out = fmt::format_to(out, "</tr>\n");
    header = false;
  }
  fmt::format_to(out, "</table>\n");
}

} // namespace

std::string study_report_html(const post::StudyTable& table, const std::string& csv,
                              std::span<const ReportPicture> pictures) {
  std::string body;
  std::back_insert_iterator<std::string> out(body);
  out = fmt::format_to(out, "<h1>formflow {} study of <code>{}</code></h1>\n<p>{}</p>\n",
                       FORMFLOW_VERSION, html_escaped(table.key), html_escaped(table.description));
  int failed = 0;
  for (const post::StudyRung& rung : table.rungs) failed += rung.converged() ? 0 : 1;
  if (failed == 0)
    out = fmt::format_to(out, "<p class=\"status converged\">all {} rungs converged</p>\n",
                         table.rungs.size());
  else
    out = fmt::format_to(out,
                         "<p class=\"status failed\">{} of {} rungs did NOT converge (their "
                         "stop_reason column says why)</p>\n",
                         failed, table.rungs.size());
  out = fmt::format_to(out, "<h2>Study table (study.csv)</h2>\n");
  csv_table(out, csv);
  out = fmt::format_to(out, "<h2>Pictures</h2>\n");
  for (const ReportPicture& picture : pictures)
    out = fmt::format_to(out,
                         "<figure id=\"{0}\"><img src=\"{1}\" alt=\"{0}\" width=\"900\" "
                         "height=\"600\"><figcaption>{0} (also {0}.svg and {0}.png)"
                         "</figcaption></figure>\n",
                         html_escaped(picture.name), data_uri("image/svg+xml", picture.svg));
  return html_page("formflow study: " + table.key, body);
}

} // namespace formflow::io
