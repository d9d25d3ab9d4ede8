// SPDX-License-Identifier: MIT
// The memory check in 3D: the factor-fill model against CHOLMOD's counts and the
// measured peaks, and a mesh.size hint that fits a rectangle's half widths.
#include "formflow/io/case.hpp"
#include "formflow/io/mesh_memory.hpp"
#include "formflow/mesh/fitting_sizes.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

namespace formflow::io {
namespace {

constexpr Real solid_mebibyte = 1024.0 * 1024.0;
constexpr Real solid_gibibyte = 1024.0 * solid_mebibyte;

Case round_rod() {
  return load_case(std::string(FORMFLOW_SOURCE_DIR) + "/cases/round-rod-3d.toml", {});
}

TEST(MeshMemory3D, EstimateIsBelowTheCountedFactorAndTheMeasuredPeaks) {
  // cases/round-rod-3d.toml (Q2): docs/benchmarks.md's 3D table measured 678 MiB at
  // h = 1/8 (48 825 dofs) and 6 880 MiB at h = 1/16 (360 297 dofs); CHOLMOD counted
  // 23 945 842 factor entries at h = 1/8 (summary.json linear_algebra.factor_nonzeros).
  Case case_ = round_rod();
  const auto at_8 = estimate_mesh_memory(case_, 0.125);
  const auto at_16 = estimate_mesh_memory(case_, 0.0625);
  ASSERT_TRUE(at_8 && at_16);
  EXPECT_LE(at_8->dofs, 48825.0);
  EXPECT_GT(at_8->dofs, 0.8 * 48825.0); // interior nodes only: boundary nodes missing
  EXPECT_LE(at_8->factor_entries, 23945842.0);
  EXPECT_LE(at_8->bytes, 678 * solid_mebibyte);
  EXPECT_LE(at_16->bytes, 6880 * solid_mebibyte);
  // The factor is most of it, and grows faster than the dofs: ×2^(4/3) per ×2 in dofs.
  EXPECT_GT(8.0 * at_8->factor_entries, run_bytes_per_dof * at_8->dofs);
  const Real growth = at_16->factor_entries / at_8->factor_entries;
  EXPECT_NEAR(growth, std::pow(at_16->dofs / at_8->dofs, 4.0 / 3.0), 1e-9 * growth);
}

TEST(MeshMemory3D, TheHintFitsTheRectanglesHalfWidths) {
  Case case_ = load_case("", {{"geometry.dimension", "3"},
                              {"geometry.section", "\"rectangle\""},
                              {"geometry.container_length", "1"},
                              {"geometry.entry_half_height", "1"},
                              {"geometry.exit_half_height", "0.5"},
                              {"geometry.exit_length", "1"},
                              {"geometry.entry_half_width", "1.5"},
                              {"geometry.exit_half_width", "0.75"},
                              {"mesh.size", "0.25"}});
  case_.mesh.size = 0.004; // 1 → 250 cells a side: some 10⁸ dofs
  const Real memory = 24 * solid_gibibyte;
  const auto problem = mesh_memory_problem(case_, memory);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->hint.find("8 per entry of the Cholesky factor"), std::string::npos)
      << problem->hint;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(problem->hint, match, std::regex("e\\.g\\. ([0-9.e+-]+)")))
      << problem->hint;
  const Real size = std::stod(match[1].str());
  // It divides every length, the half widths 1.5 and 0.75 included, and it fits ...
  EXPECT_TRUE(mesh::solid_lengths_fit(case_.mesh.geometry, case_.mesh.solid, size))
      << problem->hint;
  Case suggested = case_;
  suggested.mesh.size = size;
  EXPECT_FALSE(mesh_memory_problem(suggested, memory)) << problem->hint;
  // ... and is the finest that does: the next finer fitting size does not fit.
  const auto finer =
      mesh::nearest_fitting_sizes(mesh::solid_lengths_to_fit(case_.mesh.geometry, case_.mesh.solid),
                                  0.999 * size)
          .smaller;
  ASSERT_TRUE(finer);
  suggested.mesh.size = finer->size();
  EXPECT_TRUE(mesh_memory_problem(suggested, memory)) << finer->size();
}

} // namespace
} // namespace formflow::io
