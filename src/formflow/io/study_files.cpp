// SPDX-License-Identifier: MIT
// study.csv and the study pictures, published as one set.
#include "formflow/io/study_files.hpp"

#include "formflow/io/plot/load_error_dofs_plot.hpp"
#include "formflow/io/plot/study_plot.hpp"
#include "formflow/io/report_html.hpp"
#include "formflow/io/result_set.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <optional>
#include <vector>

namespace formflow::io {

namespace {

void append(std::string& out, std::optional<Real> value) {
  out += ',';
  if (value && std::isfinite(*value)) fmt::format_to(std::back_inserter(out), "{:.10g}", *value);
}

std::optional<Real> v_of(const std::optional<post::ErrorNorms>& norms) {
  return norms ? std::optional<Real>(norms->v_norm) : std::nullopt;
}
std::optional<Real> l2_of(const std::optional<post::ErrorNorms>& norms) {
  return norms ? std::optional<Real>(norms->l2) : std::nullopt;
}

} // namespace

std::string study_csv(const post::StudyTable& table) {
  std::string out =
      "key,value,parameter,dofs,iterations,stop_reason,seconds,ram_reaction,power_balance,"
      "total_power,mean_hydrostatic_near_ram,error_V,error_L2,error_hydrostatic_L2,difference_V,"
      "difference_L2,order_V,order_L2,pressure_order,pressure_extrapolated,rcond,"
      "load_error_estimate\n";
  for (const post::StudyRung& rung : table.rungs) {
    // Values are case-file numbers or words: no commas or quotes to escape.
    fmt::format_to(std::back_inserter(out), "{},{}", table.key, rung.value_text);
    append(out, rung.parameter);
    fmt::format_to(std::back_inserter(out), ",{},{},{}", rung.dofs, rung.iterations,
                   solvers::stop_reason_name(rung.stop_reason));
    append(out, rung.seconds);
    append(out, rung.pressure.ram_reaction);
    append(out, rung.pressure.power_balance);
    append(out, rung.pressure.total_power);
    append(out, rung.pressure.mean_hydrostatic_near_ram);
    append(out, v_of(rung.error));
    append(out, l2_of(rung.error));
    append(out, rung.error ? std::optional<Real>(rung.error->hydrostatic_l2) : std::nullopt);
    append(out, v_of(rung.difference));
    append(out, l2_of(rung.difference));
    append(out, rung.order_v);
    append(out, rung.order_l2);
    append(out, rung.pressure_order);
    append(out, rung.pressure_extrapolated);
    append(out, rung.reciprocal_condition);
    append(out, rung.load_error_estimate);
    out += '\n';
  }
  return out;
}

std::string corner_csv(const post::StudyTable& table) {
  std::string out = "key,value,radius,mean_rate,max_rate\n";
  for (const post::StudyRung& rung : table.rungs) {
    if (!rung.corner) continue;
    for (std::size_t k = 0; k < rung.corner->radius.size(); ++k) {
      fmt::format_to(std::back_inserter(out), "{},{}", table.key, rung.value_text);
      append(out, rung.corner->radius[k]);
      append(out, rung.corner->mean_rate[k]);
      append(out, rung.corner->max_rate[k]);
      out += '\n';
    }
  }
  return out;
}

std::string adaptive_csv(const post::StudyTable& table) {
  std::string out = "series,index,dofs,load,estimate,estimate_predicted,refined_mesh\n";
  for (std::size_t k = 0; k < table.rungs.size(); ++k) {
    const post::StudyRung& rung = table.rungs[k];
    fmt::format_to(std::back_inserter(out), "uniform,{},{}", k, rung.dofs);
    append(out, rung.pressure.ram_reaction);
    append(out, rung.load_error_estimate);
    out += ",false,false\n";
  }
  for (std::size_t k = 0; k < table.adaptive.cycles.size(); ++k) {
    const post::AdaptCycle& cycle = table.adaptive.cycles[k];
    fmt::format_to(std::back_inserter(out), "adaptive,{},{}", k, cycle.dofs);
    append(out, cycle.load);
    append(out, cycle.estimate);
    fmt::format_to(std::back_inserter(out), ",{},{}\n", cycle.estimate_predicted,
                   cycle.refined_mesh);
  }
  return out;
}

std::span<const std::string> study_file_names() {
  static const std::vector<std::string> names = {
      "study.csv",  "study.png",           "study.svg",           "corner.csv",   "corner.png",
      "corner.svg", "load_error_dofs.png", "load_error_dofs.svg", "adaptive.csv", "report.html"};
  return names;
}

void write_study(const std::string& directory, const post::StudyTable& table,
                 const StopRequested& stop_requested) {
  plot::Picture picture = plot::render_study_plot(table);
  const std::string csv = study_csv(table);
  std::vector<ReportPicture> report_pictures = {{"study", picture.svg}};
  std::vector<ResultFile> files = {{"study.csv", csv},
                                   {"study.png", std::move(picture.png)},
                                   {"study.svg", std::move(picture.svg)}};
  if (table.has_corner_profiles()) {
    plot::Picture corner = plot::render_corner_plot(table);
    report_pictures.push_back({"corner", corner.svg});
    files.push_back({"corner.csv", corner_csv(table)});
    files.push_back({"corner.png", std::move(corner.png)});
    files.push_back({"corner.svg", std::move(corner.svg)});
  }
  if (table.has_load_errors()) {
    plot::Picture load_error = plot::render_load_error_dofs_plot(table);
    report_pictures.push_back({"load error against dofs", load_error.svg});
    files.push_back({"adaptive.csv", adaptive_csv(table)});
    files.push_back({"load_error_dofs.png", std::move(load_error.png)});
    files.push_back({"load_error_dofs.svg", std::move(load_error.svg)});
  }
  files.push_back({"report.html", study_report_html(table, csv, report_pictures)});
  publish_result_set(directory, files, "study.csv", study_file_names(), stop_requested);
}

} // namespace formflow::io
