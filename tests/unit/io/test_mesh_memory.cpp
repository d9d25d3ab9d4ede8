// SPDX-License-Identifier: MIT
// The memory check of the case validation: estimates against measured runs, the
// refusal of meshes that cannot fit, and the valid mesh.size it suggests.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/mesh_memory.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/fitting_sizes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace formflow::io {
namespace {

constexpr Real mebibyte = 1024.0 * 1024.0;
constexpr Real gibibyte = 1024.0 * mebibyte;

bool memory_message_has_text(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The value after "e.g. " in a hint, as written: the suggested mesh.size.
std::string suggested_size(const std::string& hint) {
  std::smatch match;
  EXPECT_TRUE(std::regex_search(hint, match, std::regex("e\\.g\\. ([0-9.e+-]+)"))) << hint;
  return match.empty() ? std::string("0") : match[1].str();
}

/// The default case with these mesh settings, bypassing load_case (whose own
/// check uses this machine's memory, which the tests must not depend on).
Case mesh_case(Real size, fem::ElementKind element = fem::ElementKind::Q2,
               mesh::MeshSource source = mesh::MeshSource::Structured) {
  Case case_ = load_case("", {});
  case_.mesh.size = size;
  case_.element = element;
  case_.mesh.source = source;
  return case_;
}

TEST(MeshMemory, EstimateIsALowerBoundOfTheMeasuredRuns) {
  // docs/benchmarks.md: mesh II refined 8 and 16 times (Q2), 145 and 571 MiB peak.
  Case case_ = mesh_case(1.0);
  for (const auto& [size, measured_dofs, measured_mib] :
       {std::tuple{0.125, 77762.0, 145.0}, std::tuple{0.0625, 309122.0, 571.0}}) {
    const auto estimate = estimate_mesh_memory(case_, size);
    ASSERT_TRUE(estimate);
    EXPECT_EQ(
        estimate->cells,
        static_cast<Real>(mesh::make_die_channel_mesh(case_.mesh.geometry, size, 2).n_cells()));
    EXPECT_LE(estimate->dofs, measured_dofs);
    // order² nodes per cell misses one boundary row and column: 1.2 % at 77 k dofs.
    EXPECT_GT(estimate->dofs, 0.98 * measured_dofs);
    EXPECT_LE(estimate->bytes, measured_mib * mebibyte);
    EXPECT_GT(estimate->bytes, 0.9 * measured_mib * mebibyte) << "a bound too low to be useful";
  }
  // Q1 at the same dofs measured 553 MiB (docs/benchmarks.md).
  case_.element = fem::ElementKind::Q1;
  const auto q1 = estimate_mesh_memory(case_, 0.03125);
  ASSERT_TRUE(q1);
  EXPECT_LE(q1->bytes, 553 * mebibyte);
}

TEST(MeshMemory, FileMeshesAreNotEstimated) {
  Case case_;
  case_.mesh.source = mesh::MeshSource::File;
  EXPECT_FALSE(estimate_mesh_memory(case_, 1e-6));
  EXPECT_FALSE(mesh_memory_problem(case_, 1.0));
}

TEST(MeshMemory, MemTotalIsReadFromMeminfo) {
  EXPECT_EQ(parse_mem_total("MemTotal:       24562184 kB\nMemFree:        1 kB\n"),
            24562184.0 * 1024);
  EXPECT_EQ(parse_mem_total("MemFree:  12 kB\nMemTotal:  2048 kB\n"), 2048.0 * 1024);
  EXPECT_FALSE(parse_mem_total("MemFree:        1 kB\n"));
  EXPECT_FALSE(parse_mem_total("MemTotal: lots\n"));
  std::ifstream stream("/proc/meminfo");
  std::stringstream text;
  text << stream.rdbuf();
  EXPECT_EQ(machine_memory_bytes(), parse_mem_total(text.str()).value_or(fallback_memory_bytes));
  EXPECT_GT(machine_memory_bytes(), 0.0);
}

TEST(MeshMemory, WhatFitsIsAccepted) {
  // 24 GiB, the machine of docs/benchmarks.md: the benchmark ladder and 1.5e6 cells fit.
  for (const Real size : {1.0, 0.0625, 0.01})
    EXPECT_FALSE(mesh_memory_problem(mesh_case(size), 24 * gibibyte)) << size;
  EXPECT_FALSE(mesh_memory_problem(mesh_case(0.01, fem::ElementKind::Q1), 24 * gibibyte));
}

TEST(MeshMemory, TooLargeAStructuredMeshNamesCellsEstimateAndAValidSize) {
  const Case case_ = mesh_case(0.001, fem::ElementKind::Q1);
  const auto problem = mesh_memory_problem(case_, 24 * gibibyte);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->message,
            "value 0.001 makes about 1.5e+08 cells (3e+08 velocity dofs), which need at least "
            "503 GiB of memory; this machine has 24 GiB");
  // The suggestion divides every length and fits ...
  const Real size = std::stod(suggested_size(problem->hint));
  for (const Real length : mesh::lengths_to_fit(case_.mesh.geometry))
    EXPECT_GT(mesh::cells_along(length, size), 0) << problem->hint;
  EXPECT_FALSE(mesh_memory_problem(mesh_case(size, fem::ElementKind::Q1), 24 * gibibyte))
      << problem->hint;
  // ... and is the finest that does: the next finer divisor of the lengths does not fit.
  const auto finer =
      mesh::nearest_fitting_sizes(mesh::lengths_to_fit(case_.mesh.geometry), 0.999 * size).smaller;
  ASSERT_TRUE(finer);
  EXPECT_TRUE(mesh_memory_problem(mesh_case(finer->size(), fem::ElementKind::Q1), 24 * gibibyte));
}

TEST(MeshMemory, GmshAndManufacturedSuggestTheirOwnValidSizes) {
  const Case gmsh = mesh_case(0.0007, fem::ElementKind::Q2, mesh::MeshSource::Gmsh);
  const auto gmsh_problem = mesh_memory_problem(gmsh, 8 * gibibyte);
  ASSERT_TRUE(gmsh_problem);
  const std::string gmsh_size = suggested_size(gmsh_problem->hint);
  EXPECT_LE(gmsh_size.size(), 6u) << "two significant digits: " << gmsh_problem->hint;
  EXPECT_FALSE(mesh_memory_problem(
      mesh_case(std::stod(gmsh_size), fem::ElementKind::Q2, mesh::MeshSource::Gmsh), 8 * gibibyte));

  Case box = mesh_case(1e-4);
  box.manufactured = physics::ManufacturedSolution::Smooth;
  const auto box_problem = mesh_memory_problem(box, 8 * gibibyte);
  ASSERT_TRUE(box_problem);
  EXPECT_TRUE(memory_message_has_text(box_problem->message, "about 1e+08 cells"))
      << box_problem->message;
  EXPECT_TRUE(memory_message_has_text(box_problem->hint, "(= 1/")) << box_problem->hint;
  box.mesh.size = std::stod(suggested_size(box_problem->hint));
  EXPECT_GT(mesh::cells_along(1.0, box.mesh.size), 0) << box_problem->hint;
  EXPECT_FALSE(mesh_memory_problem(box, 8 * gibibyte));
}

TEST(MeshMemory, LoadCaseRefusesAMeshNoMachineHolds) {
  // 1.5e10 Q1 cells: some 50 TiB, on any machine this runs on.
  try {
    load_case("", {{"mesh.size", "1e-4"}});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key, "mesh.size");
    EXPECT_EQ(error.file, "--set");
    EXPECT_TRUE(memory_message_has_text(error.what(), "1.5e+10 cells")) << error.what();
    EXPECT_TRUE(memory_message_has_text(error.hint, "use mesh.size ≥ ")) << error.hint;
  }
}

} // namespace
} // namespace formflow::io
