// SPDX-License-Identifier: MIT
// Refusing, at validation time, a mesh that cannot fit in this machine's memory.
#include "formflow/io/mesh_memory.hpp"

#include "formflow/fem/lagrange.hpp"
#include "formflow/io/case_validation_simplex.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/fitting_sizes.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace formflow::io {

namespace {

bool is_manufactured(const Case& case_) {
  return case_.manufactured != physics::ManufacturedSolution::None;
}

/// "571 MiB", "23.4 GiB", "1.2e+03 TiB".
std::string bytes_text(Real bytes) {
  const char* units[] = {"MiB", "GiB", "TiB"};
  Real value = bytes / (1024.0 * 1024.0);
  int unit = 0;
  while (unit < 2 && value >= 1024.0) {
    value /= 1024.0;
    ++unit;
  }
  return fmt::format("{:.3g} {}", value, units[unit]);
}

/// `value` rounded up to `digits` significant digits: 0.0051234 → 0.00513 (3 digits).
Real round_up(Real value, int digits) {
  const Real step = std::pow(10.0, std::floor(std::log10(value)) - (digits - 1));
  // Through the decimal text, so that the number is exactly the one printed.
  return std::stod(fmt::format("{:.{}g}", std::ceil(value / step * (1 - 1e-12)) * step, digits));
}

bool fits(const Case& case_, Real size, Real memory_bytes) {
  const auto estimate = estimate_mesh_memory(case_, size);
  return estimate && estimate->bytes <= memory_bytes;
}

/// A mesh.size at least `smallest` that fits in memory and is valid for the
/// mesh source: a divisor of every length for the structured grid, 1/n for the
/// unit square, any size (two significant digits) for Gmsh; "" if none is found.
std::string valid_size_text(const Case& case_, Real smallest, Real memory_bytes) {
  if (is_manufactured(case_)) {
    for (int n = std::max(1, static_cast<int>(std::floor(1.0 / smallest))); n >= 1; --n)
      if (fits(case_, 1.0 / n, memory_bytes))
        return fmt::format("{} (= 1/{})", format_key_value(1.0 / n), n);
    return "";
  }
  if (case_.mesh.source == mesh::MeshSource::Gmsh) {
    for (Real size = round_up(smallest, 2); size < 2 * smallest; size = round_up(1.01 * size, 2))
      if (fits(case_, size, memory_bytes)) return format_key_value(size);
    return "";
  }
  // A solid rectangle's half widths are cut into cells of mesh.size too.
  const std::vector<Real> lengths =
      case_.mesh.dimension == 3 ? mesh::solid_lengths_to_fit(case_.mesh.geometry, case_.mesh.solid)
                                : mesh::lengths_to_fit(case_.mesh.geometry);
  Real size = smallest;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto larger = mesh::nearest_fitting_sizes(lengths, size).larger;
    if (!larger) return "";
    if (fits(case_, larger->size(), memory_bytes))
      return fmt::format("{} (= {}/{})", format_key_value(larger->size()), larger->length,
                         larger->cells);
    size = larger->size() * 1.01;
  }
  return "";
}

} // namespace

std::optional<MeshMemoryEstimate> estimate_mesh_memory(const Case& case_, Real size) {
  Real cells = 0.0;
  if (is_manufactured(case_))
    cells = std::pow(1.0 / size, case_.mesh.dimension); // the unit square or cube
  else if (case_.mesh.source == mesh::MeshSource::File ||
           case_.mesh.source == mesh::MeshSource::Cad) // Gmsh decides the cells of a CAD solid
    return std::nullopt;
  else
    cells = case_.mesh.dimension == 3
                ? mesh::solid_channel_cell_count(case_.mesh.geometry, case_.mesh.solid, size)
                : mesh::die_channel_cell_count(case_.mesh.geometry, size);
  const int order = fem::element_order(case_.element);
  if (case_.mesh.dimension == 3) {
    const Real dofs = 3.0 * order * order * order * cells;
    const Real factor_entries = solid_factor_coefficient * std::pow(dofs, 4.0 / 3.0);
    return MeshMemoryEstimate{cells, dofs, run_bytes_per_dof * dofs + 8.0 * factor_entries,
                              factor_entries};
  }
  // Triangles halve the structured squares: the same lattice nodes, and a bubble node
  // per triangle (two per square) where the element has them.
  const mesh::CellType type = case_cell_type(case_);
  const Real bubble_nodes = type.is_simplex() && type.bubbles ? 2.0 : 0.0;
  const Real dofs = 2.0 * (order * order + bubble_nodes) * cells;
  return MeshMemoryEstimate{cells, dofs, run_bytes_per_dof * dofs};
}

std::optional<Real> parse_mem_total(std::string_view meminfo) {
  std::istringstream lines{std::string(meminfo)};
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("MemTotal:", 0) != 0) continue;
    std::istringstream fields(line.substr(9));
    Real kibibytes = 0.0;
    std::string unit;
    if (fields >> kibibytes >> unit && unit == "kB" && kibibytes > 0) return kibibytes * 1024.0;
    return std::nullopt;
  }
  return std::nullopt;
}

Real machine_memory_bytes() {
  // MemTotal is fixed while formflow runs: read once, not on every load_case
  // (a study plans dozens of cases, a fuzzer millions).
  static const Real total = [] {
    std::ifstream stream("/proc/meminfo");
    std::stringstream text;
    text << stream.rdbuf();
    return parse_mem_total(text.str()).value_or(fallback_memory_bytes);
  }();
  return total;
}

std::optional<KeyProblem> mesh_memory_problem(const Case& case_, Real memory_bytes) {
  const auto estimate = estimate_mesh_memory(case_, case_.mesh.size);
  if (!estimate || estimate->bytes <= memory_bytes) return std::nullopt;
  // The smallest size whose estimate fits, then a valid one above it. Cells grow as
  // 1/size^dim (the slab's layers too), so in 2D that size is a root; in 3D the
  // factor grows faster (bytes ~ size^−4), and the size is bisected between the one
  // asked and size · ratio^(1/3), which fits (each term falls at least by the ratio).
  const Real ratio = estimate->bytes / memory_bytes;
  Real smallest = case_.mesh.size * std::pow(ratio, 1.0 / case_.mesh.dimension);
  if (case_.mesh.dimension == 3) {
    Real lower = case_.mesh.size;
    while (!fits(case_, smallest, memory_bytes)) smallest *= 1.01; // cell counts round
    for (int step = 0; step < 60; ++step) {
      const Real middle = 0.5 * (lower + smallest);
      (fits(case_, middle, memory_bytes) ? smallest : lower) = middle;
    }
  }
  const std::string size = valid_size_text(case_, smallest, memory_bytes);
  return KeyProblem{
      fmt::format("value {} makes about {:.3g} cells ({:.3g} velocity dofs), which need at least "
                  "{} of memory; this machine has {}",
                  format_key_value(case_.mesh.size), estimate->cells, estimate->dofs,
                  bytes_text(estimate->bytes), bytes_text(memory_bytes)),
      fmt::format("{}; the estimate is {:.0f} bytes per dof{}, a lower bound from the runs in "
                  "docs/benchmarks.md",
                  size.empty() ? std::string("use a coarser mesh.size")
                               : "use mesh.size ≥ " + format_key_value(round_up(smallest, 3)) +
                                     ", e.g. " + size,
                  run_bytes_per_dof,
                  estimate->factor_entries > 0
                      ? fmt::format(" and 8 per entry of the Cholesky factor (about {:.3g} "
                                    "entries, growing as dofs^(4/3) in 3D)",
                                    estimate->factor_entries)
                      : std::string())};
}

} // namespace formflow::io
