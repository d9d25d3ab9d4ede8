// SPDX-License-Identifier: MIT
// study.csv and the study pictures, written atomically.
#include "formflow/io/study_files.hpp"

#include "formflow/io/atomic_file.hpp"
#include "formflow/io/plot/study_plot.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <optional>

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
      "difference_L2,order_V,order_L2,pressure_order,pressure_extrapolated,rcond\n";
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

void write_study(const std::string& directory, const post::StudyTable& table) {
  const std::filesystem::path folder(directory);
  std::filesystem::create_directories(folder);
  const plot::Picture picture = plot::render_study_plot(table);
  write_file_atomically(folder / "study.csv", study_csv(table));
  write_file_atomically(folder / "study.png", picture.png);
  write_file_atomically(folder / "study.svg", picture.svg);
  if (!table.has_corner_profiles()) return;
  const plot::Picture corner = plot::render_corner_plot(table);
  write_file_atomically(folder / "corner.csv", corner_csv(table));
  write_file_atomically(folder / "corner.png", corner.png);
  write_file_atomically(folder / "corner.svg", corner.svg);
}

} // namespace formflow::io
