// SPDX-License-Identifier: MIT
// A solid (3D) run through the dimension-generic app code, post-processing and writers.
#include "formflow/app/simulation.hpp"
#include "formflow/io/results_writer.hpp"
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/hex_box_mesh.hpp"
#include "support/vtk_reader.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace formflow::testing {

namespace {

using mesh::BoundaryLabel;

/// A 2 × 1 × 1 box pushed at x = 0 along a frictionless channel: the walls
/// y = 1, z = 0 and z = 1 are the container (Γ3, penalised normal velocity),
/// y = 0 the symmetry plane, x = 2 the free front. The exact solution is the
/// rigid translation u = (u⁰, 0, 0): it lies in the Q1/Q2 space and meets
/// every condition exactly (no strain rate, u_N = 0 on the walls), so the
/// discrete solution is that translation up to the linear solver's rounding.
mesh::Mesh<3> channel_box(int order) {
  return mesh::make_hex_box_mesh(Point<3>(0.0, 0.0, 0.0), Point<3>(2.0, 1.0, 1.0), {2, 1, 1}, order,
                                 {BoundaryLabel::Rear, BoundaryLabel::Front,
                                  BoundaryLabel::Symmetry, BoundaryLabel::Container,
                                  BoundaryLabel::Container, BoundaryLabel::Container});
}

/// Every key path of a JSON document ("case.mesh.size", ...), values ignored.
void collect_keys(const nlohmann::json& value, const std::string& prefix,
                  std::set<std::string>& keys) {
  if (!value.is_object()) return;
  for (const auto& [key, child] : value.items()) {
    keys.insert(prefix + key);
    collect_keys(child, prefix + key + ".", keys);
  }
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class SolidRun : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    case_.element = GetParam() == 1 ? fem::ElementKind::Q1 : fem::ElementKind::Q2;
    case_.volumetric_points = GetParam(); // reduced rule: Q1–1 point, Q2–2 points
    simulation_ = app::simulate_on<3>(case_, channel_box(GetParam()));
  }
  io::Case case_;
  app::Simulation simulation_;
};

TEST_P(SolidRun, SolvesTheRigidTranslation) {
  const post::Results& results = simulation_.results;
  ASSERT_EQ(simulation_.dimension(), 3);
  ASSERT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  const int side = GetParam() + 1;
  EXPECT_EQ(results.n_cells, 2);
  EXPECT_EQ(results.n_nodes, (2 * GetParam() + 1) * side * side);
  EXPECT_EQ(results.n_dofs, 3 * results.n_nodes);
  ASSERT_EQ(results.fields.velocity.size(), 3 * results.n_nodes);
  // Rounding bound: ε · cond(K), cond(K) ≲ (1/d_N)/(σ_p/ε̄̇ at the start rate)
  // ≈ 1e6 · 1e2 for these settings, i.e. ≈ 2e-8 u⁰ at worst (measured: < 1e-13);
  // a real error (a missed constraint, a wrong dof layout) would be O(u⁰).
  const Real speed = case_.process.speed;
  for (Index n = 0; n < results.n_nodes; ++n)
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_NEAR(results.fields.velocity[3 * n + axis], axis == 0 ? speed : 0.0, 1e-7 * speed)
          << "node " << n << " axis " << axis;
  // Γ3: three walls of two faces each, (order + 1)² points a face, on the walls.
  ASSERT_EQ(results.contact.size(), static_cast<std::size_t>(6 * side * side));
  // The points come from the face maps (sums of shape function × node): a few ulps off.
  auto at = [](Real coordinate, Real wall) { return std::abs(coordinate - wall) < 1e-14; };
  for (const post::ContactSample& sample : results.contact) {
    const bool on_wall = at(sample.y, 1.0) || at(sample.z, 0.0) || at(sample.z, 1.0);
    EXPECT_TRUE(on_wall) << sample.x << " " << sample.y << " " << sample.z;
  }
  EXPECT_NEAR(results.container_zones.length, 3 * 2.0, 1e-12); // three 2 × 1 walls (areas)
}

TEST_P(SolidRun, WritesHexahedraThreeCoordinatesAndTheSolidPictures) {
  const auto directory =
      std::filesystem::temp_directory_path() /
      ("formflow_solid_" + std::to_string(GetParam()) + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  // A picture of an earlier plane run: the solid set has its own, so it must go.
  std::ofstream(directory / "strain_rate.png") << "old";
  io::write_results(directory.string(), case_, simulation_.mesh, simulation_.results);
  EXPECT_FALSE(std::filesystem::exists(directory / "strain_rate.png"));
  // The box has the symmetry plane y = 0 but walls at z = 0: the y = 0 section, the
  // unrolled die surface and the convergence are drawn, the z = 0 section is not.
  for (const std::string stem :
       {"strain_rate_y0", "pressure_y0", "contact_surface", "convergence"}) {
    const std::string png = read_file(directory / (stem + ".png"));
    EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n") << stem;
    EXPECT_NE(read_file(directory / (stem + ".svg")).find("<svg"), std::string::npos) << stem;
  }
  EXPECT_FALSE(std::filesystem::exists(directory / "strain_rate_z0.png"));

  const std::string contact = read_file(directory / "contact.csv");
  EXPECT_EQ(contact.substr(0, contact.find('\n')),
            "x,y,z,contact_pressure,friction_stress,slip_velocity,state,part");
  EXPECT_EQ(static_cast<std::size_t>(std::count(contact.begin(), contact.end(), '\n')),
            simulation_.results.contact.size() + 1);

  const nlohmann::json seen = read_with_vtk(read_file(directory / "fields.vtu"), "solid_run");
  ASSERT_TRUE(seen.contains("n_cells"));
  EXPECT_EQ(seen["n_cells"], 2);
  EXPECT_EQ(seen["n_points"], simulation_.results.n_nodes);
  for (const auto& type : seen["cell_types"]) EXPECT_EQ(type, GetParam() == 1 ? 12 : 29);

  // summary.json: the same keys as a plane run of the same case on a plane box.
  const mesh::Mesh<2> plane_box =
      mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(2.0, 1.0), 2, 1, GetParam());
  const app::Simulation plane = app::simulate_on<2>(case_, plane_box);
  std::set<std::string> solid_keys, plane_keys;
  collect_keys(nlohmann::json::parse(read_file(directory / "summary.json")), "", solid_keys);
  collect_keys(nlohmann::json::parse(io::summary_json(case_, plane.results)), "", plane_keys);
  EXPECT_EQ(solid_keys, plane_keys);
  std::filesystem::remove_all(directory);
}

INSTANTIATE_TEST_SUITE_P(Orders, SolidRun, ::testing::Values(1, 2));

} // namespace

} // namespace formflow::testing
