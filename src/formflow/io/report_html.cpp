// SPDX-License-Identifier: MIT
// report.html of a run: the outcome, the loads, the pictures, the history and the case.
#include "formflow/io/report_html.hpp"

#include "formflow/io/case_keys.hpp"
#include "formflow/io/html_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace formflow::io {

namespace {

using Out = std::back_insert_iterator<std::string>;

std::string number(Real value) {
  return fmt::format("{:.6g}", value);
}

/// |value − reference| / |reference| as a percentage, or a dash where it has no meaning.
std::string relative_difference(Real value, Real reference) {
  if (reference == 0 || !std::isfinite(value) || !std::isfinite(reference)) return "—";
  return fmt::format("{:.3g} %", 100 * std::abs(value - reference) / std::abs(reference));
}

void outcome_section(Out out, const Case& case_, const post::Results& results) {
  const std::string reason(solvers::stop_reason_name(results.stop_reason));
  if (results.converged())
    fmt::format_to(out, "<p class=\"status converged\">converged in {} iterations ({})</p>\n",
                   results.iterations, html_escaped(results.method));
  else
    fmt::format_to(out,
                   "<p class=\"status failed\">NOT CONVERGED ({}) after {} iterations: every "
                   "number and picture below is the last iterate, not a solution</p>\n",
                   html_escaped(reason), results.iterations);
  fmt::format_to(out, "<p>{} · {} elements, {} nodes, {} dofs · cell diameters {} to {}</p>\n",
                 html_escaped(std::string(fem::element_name(case_.element))), results.n_cells,
                 results.n_nodes, results.n_dofs, number(results.min_cell_diameter),
                 number(results.max_cell_diameter));
}

void loads_section(Out out, const Case& case_, const post::Results& results) {
  const post::Pressures& pressure = results.pressure;
  const bool drawing = case_.process.type == physics::ProcessType::Drawing;
  fmt::format_to(out,
                 "<h2>Load</h2>\n<p>{}, per unit height of the driven end, measured three "
                 "ways (SPEC §4); the last column is each measure's difference from the "
                 "reaction.</p>\n<table>\n<tr><th>measure</th><th>value</th><th>difference "
                 "from the reaction</th></tr>\n",
                 drawing ? "Drawing stress" : "Extrusion pressure");
  const auto row = [&](const char* name, const char* explanation, Real value) {
    fmt::format_to(out,
                   "<tr><td>{}<br><span class=\"note\">{}</span></td><td "
                   "class=\"number\">{}</td><td class=\"number\">{}</td></tr>\n",
                   name, explanation, number(value),
                   relative_difference(value, pressure.ram_reaction));
  };
  row("ram reaction", "reaction force on the driven end / its height", pressure.ram_reaction);
  row("power balance", "(plastic dissipation + friction power) / (u⁰ · height)",
      pressure.power_balance);
  row("total discrete power",
      "all terms of b and j_dT / (u⁰ · height); equals the reaction at "
      "convergence",
      pressure.total_power);
  row("mean −σ_H near the ram", "over the column of cells touching the ram",
      pressure.mean_hydrostatic_near_ram);
  out = fmt::format_to(out, "</table>\n");
  // The load's error bar (docs/error-estimation.md), or why there is none.
  const post::LoadErrorEstimate& estimate = results.load_error;
  const char* how = estimate.method == "coarser" ? "loads on the meshes coarsened once and twice"
                                                 : "adjoint on the mesh refined once";
  out = estimate.error ? fmt::format_to(out,
                                        "<p>Estimated discretisation error of the load: ± {} "
                                        "({}).</p>\n",
                                        number(*estimate.error), how)
                       : fmt::format_to(out, "<p>No estimate of the load's error: {}.</p>\n",
                                        html_escaped(estimate.unavailable));
  const post::PowerTerms& power = results.power;
  fmt::format_to(out,
                 "<table>\n<tr><th>power term</th><th>value</th></tr>\n"
                 "<tr><td>plastic dissipation</td><td class=\"number\">{}</td></tr>\n"
                 "<tr><td>viscous form a(u; u, u)</td><td class=\"number\">{}</td></tr>\n"
                 "<tr><td>volumetric penalty</td><td class=\"number\">{}</td></tr>\n"
                 "<tr><td>contact penalty</td><td class=\"number\">{}</td></tr>\n"
                 "<tr><td>friction</td><td class=\"number\">{}</td></tr>\n"
                 "<tr><td>total</td><td class=\"number\">{}</td></tr>\n</table>\n",
                 number(power.plastic_dissipation), number(power.viscous_form),
                 number(power.volumetric_penalty), number(power.contact_penalty),
                 number(power.friction), number(power.total()));
}

void warnings_section(Out out, const Case& case_, const post::Results& results) {
  out = fmt::format_to(out, "<h2>Warnings</h2>\n");
  if (case_.warnings.empty() && results.converged()) {
    fmt::format_to(out, "<p>None.</p>\n");
    return;
  }
  if (!results.converged())
    fmt::format_to(out, "<p class=\"warning\">The nonlinear iteration stopped: {}.</p>\n",
                   html_escaped(std::string(solvers::stop_reason_name(results.stop_reason))));
  for (const std::string& warning : case_.warnings)
    fmt::format_to(out, "<p class=\"warning\">{}</p>\n", html_escaped(warning));
}

void pictures_section(Out out, std::span<const ReportPicture> pictures) {
  if (pictures.empty()) return;
  out = fmt::format_to(out, "<h2>Pictures</h2>\n");
  for (const ReportPicture& picture : pictures)
    fmt::format_to(out,
                   "<figure id=\"{0}\"><img src=\"{1}\" alt=\"{0}\" width=\"900\" "
                   "height=\"600\"><figcaption>{0} (also {0}.svg and {0}.png)</figcaption>"
                   "</figure>\n",
                   html_escaped(picture.name), data_uri("image/svg+xml", picture.svg));
}

void history_section(Out out, const post::Results& results) {
  out = fmt::format_to(out, "<h2>Iteration history</h2>\n<table>\n<tr><th>iteration</th>"
                            "<th>relative change</th><th>pressure</th><th>seconds</th></tr>\n");
  for (const solvers::IterationRecord& record : results.history)
    fmt::format_to(out,
                   "<tr><td class=\"number\">{}</td><td class=\"number\">{:.3e}</td><td "
                   "class=\"number\">{}</td><td class=\"number\">{:.3g}</td></tr>\n",
                   record.iteration, record.relative_change, number(record.pressure),
                   record.seconds);
  out = fmt::format_to(out, "</table>\n");
  if (!results.coarse_iterations.empty())
    for (std::size_t k = 0; k < results.coarse_iterations.size(); ++k)
      fmt::format_to(out, "<p class=\"note\">coarse start: mesh.size {} took {} iterations</p>\n",
                     number(results.coarse_mesh_sizes[k]), results.coarse_iterations[k]);
}

void timings_section(Out out, const post::Results& results) {
  out = fmt::format_to(out, "<h2>Timings</h2>\n<table>\n<tr><th>phase</th><th>seconds</th>"
                            "<th>calls</th></tr>\n");
  for (const auto& [phase, seconds] : results.timing.all())
    fmt::format_to(out,
                   "<tr><td>{}</td><td class=\"number\">{:.4g}</td><td "
                   "class=\"number\">{}</td></tr>\n",
                   html_escaped(phase), seconds, results.timing.counted(phase));
  fmt::format_to(out, "</table>\n");
}

/// Every key in the key table's order; a row is marked when its value is not
/// the default, with where it was set (a key given its default value is not marked).
void case_section(Out out, const Case& case_) {
  fmt::format_to(out,
                 "<h2>Case</h2>\n<p>Source: <code>{}</code>. Highlighted rows are not at their "
                 "defaults.</p>\n<table>\n<tr><th>key</th><th>value</th><th>default</th>"
                 "<th>set at</th></tr>\n",
                 html_escaped(case_.source));
  for (const CaseKey& key : case_keys()) {
    const std::string value = format_key_value(key.get(case_));
    const std::string fallback = format_key_value(key.default_value);
    const bool changed = value != fallback;
    std::string where;
    if (const auto found = case_.key_locations.find(std::string(key.name));
        found != case_.key_locations.end())
      where = found->second.line > 0 ? fmt::format("{}:{}", found->second.file, found->second.line)
                                     : found->second.file;
    fmt::format_to(out, "<tr{}><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                   changed ? " class=\"set\"" : "", html_escaped(key.name), html_escaped(value),
                   html_escaped(fallback),
                   html_escaped(changed && where.empty() ? "(derived)" : where));
  }
  fmt::format_to(out, "</table>\n");
}

} // namespace

std::string report_html(const Case& case_, const post::Results& results,
                        std::span<const ReportPicture> pictures) {
  std::string body;
  const Out out(body);
  fmt::format_to(out, "<h1>formflow {} report</h1>\n<p>Case <code>{}</code></p>\n",
                 FORMFLOW_VERSION, html_escaped(case_.source));
  outcome_section(out, case_, results);
  loads_section(out, case_, results);
  warnings_section(out, case_, results);
  pictures_section(out, pictures);
  history_section(out, results);
  timings_section(out, results);
  case_section(out, case_);
  return html_page("formflow report: " + case_.source, body);
}

} // namespace formflow::io
