// SPDX-License-Identifier: MIT
// CSV writers for history.csv and contact.csv.
#include "formflow/io/csv.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/mesh.hpp"

#include <fmt/format.h>

#include <cmath>
#include <initializer_list>
#include <iterator>
#include <string_view>
#include <utility>

namespace formflow::io {

namespace {

/// Ten significant digits: more than any of these numbers is accurate to, and
/// enough that a reader recomputing ratios from the file loses nothing visible.
void append_reals(std::string& out, std::string_view file, std::size_t row,
                  std::initializer_list<std::pair<std::string_view, Real>> columns) {
  for (const auto& [name, value] : columns) {
    if (!std::isfinite(value))
      throw InternalError(
          fmt::format("{}: row {} column {} is not finite ({})", file, row, name, value));
    fmt::format_to(std::back_inserter(out), ",{:.10g}", value);
  }
}

std::string_view part_name(int part) {
  // ContactSample::part counts from Container in mesh::BoundaryLabel order.
  switch (part) {
  case 0: return mesh::label_name(mesh::BoundaryLabel::Container);
  case 1: return mesh::label_name(mesh::BoundaryLabel::Die);
  default: throw InternalError(fmt::format("contact.csv: unknown contact part {}", part));
  }
}

} // namespace

std::string not_converged_line(solvers::StopReason stop_reason) {
  if (stop_reason == solvers::StopReason::Converged) return {};
  return fmt::format("# not converged: {}\n", solvers::stop_reason_name(stop_reason));
}

std::string history_csv(std::span<const solvers::IterationRecord> history,
                        solvers::StopReason stop_reason) {
  std::string out =
      not_converged_line(stop_reason) + "iteration,relative_change,pressure,seconds\n";
  std::size_t row = 0;
  for (const auto& record : history) {
    ++row;
    fmt::format_to(std::back_inserter(out), "{}", record.iteration);
    append_reals(out, "history.csv", row,
                 {{"relative_change", record.relative_change},
                  {"pressure", record.pressure},
                  {"seconds", record.seconds}});
    out += '\n';
  }
  return out;
}

std::string contact_csv(std::span<const post::ContactSample> contact,
                        solvers::StopReason stop_reason, int dimension) {
  const bool solid = dimension == 3;
  std::string out = not_converged_line(stop_reason) + (solid ? "x,y,z" : "s,x,y") +
                    ",contact_pressure,friction_stress,slip_velocity,state,part\n";
  std::size_t row = 0;
  for (const auto& sample : contact) {
    ++row;
    std::string numbers;
    if (solid)
      append_reals(numbers, "contact.csv", row,
                   {{"x", sample.x}, {"y", sample.y}, {"z", sample.z}});
    else
      append_reals(numbers, "contact.csv", row,
                   {{"s", sample.arc_length}, {"x", sample.x}, {"y", sample.y}});
    append_reals(numbers, "contact.csv", row,
                 {{"contact_pressure", sample.contact_pressure},
                  {"friction_stress", sample.friction_stress},
                  {"slip_velocity", sample.slip_velocity}});
    // append_reals puts a comma before every value; the first column has none.
    out.append(numbers, 1);
    fmt::format_to(std::back_inserter(out), ",{},{}\n", sample.sticking ? "stick" : "slip",
                   part_name(sample.part));
  }
  return out;
}

} // namespace formflow::io
