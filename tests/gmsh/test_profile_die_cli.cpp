// SPDX-License-Identifier: MIT
// Profiles through flat dies (geometry.section = "profile") from the command line: the
// L-angle's thin leg lags and a longer bearing on its thick leg evens the exit; a
// symmetric half model reports mirrored edges; what is no opening is refused by key,
// with nothing written.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using testing::has_text;
using testing::quoted;

const std::string l_angle = FORMFLOW_SOURCE_DIR "/cases/l-angle-flat-die.toml";
const std::string t_section = FORMFLOW_SOURCE_DIR "/cases/t-section-flat-die.toml";

struct ProfileRun {
  int exit_code = -1;
  std::string err;
  nlohmann::json summary;
};

ProfileRun run_profile(const testing::ScratchDirectory& scratch, const std::string& name,
                       const std::string& case_file, const std::string& settings) {
  const fs::path out = scratch / name;
  const testing::CliResult result = testing::run_cli("run -q -o " + quoted(out.string()) + " " +
                                                         quoted(case_file) + " " + settings,
                                                     scratch.path());
  ProfileRun run{result.exit_code, result.err, {}};
  if (fs::exists(out / "summary.json"))
    run.summary = nlohmann::json::parse(testing::read_text(out / "summary.json"));
  return run;
}

/// The area-weighted mean exit speed of outline edges [first, last].
double leg_speed(const nlohmann::json& summary, int first, int last) {
  double flux = 0, area = 0;
  for (int e = first; e <= last; ++e) {
    const nlohmann::json& edge = summary.at("exit").at("edges").at(e);
    flux += edge.at("area").get<double>() * edge.at("velocity_mean").get<double>();
    area += edge.at("area").get<double>();
  }
  return flux / area;
}

TEST(ProfileDieCli, TheThinLegLagsAndALongerThickBearingEvensTheExit) {
  testing::ScratchDirectory scratch("formflow-profile-cli");
  std::vector<double> nonuniformity;
  for (const double thick : {1.0, 2.0, 3.0}) {
    SCOPED_TRACE(thick);
    const std::string bearings = "[1, 1, 1, " + std::to_string(thick) + ", " +
                                 std::to_string(thick) + ", " + std::to_string(thick) + "]";
    const ProfileRun run =
        run_profile(scratch, "bearing-" + std::to_string(static_cast<int>(thick)), l_angle,
                    "--set mesh.size=2 --set " + quoted("geometry.bearing_length=" + bearings));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    ASSERT_TRUE(run.summary.at("converged").get<bool>());
    ASSERT_EQ(run.summary.at("exit").at("edges").size(), 6u);
    EXPECT_EQ(run.summary.at("exit").at("edges").at(4).at("bearing_length").get<double>(), thick);
    // Edges 0–2 bound the thin leg, 3–5 the thick one.
    if (thick == 1.0) EXPECT_LT(leg_speed(run.summary, 0, 2), leg_speed(run.summary, 3, 5));
    nonuniformity.push_back(run.summary.at("exit").at("nonuniformity").get<double>());
    // The faceted billet wall takes nodal contact normals unless the case says otherwise.
    EXPECT_EQ(run.summary.at("case").at("contact").at("normals"), "nodes");
    // The ram's work is the power dissipated by the field the loop stopped at: apart by
    // the residual's work, which the stop rule keeps below δ·p (δ = solver.tolerance).
    const double p = run.summary.at("pressure").at("ram_reaction").get<double>();
    const double delta = run.summary.at("case").at("solver").at("tolerance").get<double>();
    EXPECT_NEAR(run.summary.at("pressure").at("total_power").get<double>(), p, delta * p);
    // The exit's mean speed carries the billet's flux through the section's area.
    const nlohmann::json& exit = run.summary.at("exit");
    EXPECT_NEAR(exit.at("velocity").at("mean").get<double>() * exit.at("area").get<double>(),
                exit.at("exit_flux").get<double>(), 1e-9 * exit.at("exit_flux").get<double>());
  }
  EXPECT_GT(nonuniformity[0], nonuniformity[1]);
  EXPECT_GT(nonuniformity[1], nonuniformity[2]);
}

TEST(ProfileDieCli, AHalfModelReportsEveryEdgeMirrored) {
  testing::ScratchDirectory scratch("formflow-profile-cli");
  const ProfileRun run = run_profile(scratch, "t", t_section, "--set mesh.size=2");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(run.summary.at("converged").get<bool>());
  const nlohmann::json& edges = run.summary.at("exit").at("edges");
  ASSERT_EQ(edges.size(), 8u);
  // The model is y ≥ 0; each point stands for itself and its mirror, and the split by
  // nearest edge mirrors with the outline (a mirrored point's distances are the same
  // floating-point numbers: negating a coordinate is exact). Edge k and its mirror
  // (10 − k) mod 8 get the same products u_x·JxW added in the same order: equal sums,
  // bit for bit, on any CPU (no BLAS is involved).
  for (int e = 0; e < 8; ++e) {
    const int mirror = (10 - e) % 8;
    EXPECT_EQ(edges.at(mirror).at("velocity_mean").get<double>(),
              edges.at(e).at("velocity_mean").get<double>())
        << e;
  }
  // The web (edges 4–6), fed from the billet's centre, runs ahead of the flange's tips.
  EXPECT_GT(edges.at(5).at("velocity_mean").get<double>(),
            edges.at(0).at("velocity_mean").get<double>());
  EXPECT_TRUE(fs::exists(scratch / "t" / "exit_velocity.png"));
  EXPECT_TRUE(fs::exists(scratch / "t" / "contact_surface.png"));
}

TEST(ProfileDieCli, WhatIsNoOpeningIsRefusedByKey) {
  testing::ScratchDirectory scratch("formflow-profile-cli");
  {
    std::ofstream csv(scratch / "l.csv");
    csv << "y, z\n-2,-2\n4,-2\n4,-1\n0,-1\n0,4\n-2,4\n";
    std::ofstream bad(scratch / "bad.csv");
    bad << "y, z\n-2,-2\n4,-2,7\n";
  }
  const std::string from_file = "--set geometry.profile=[] --set geometry.profile_file=";
  const std::vector<std::pair<std::string, std::string>> refusals = {
      {"--set mesh.cell=hexahedron", "mesh.cell"},
      {"--set mesh.source=structured", "mesh.source"},
      {quoted("geometry.bearing_length=[1, 2]"), "geometry.bearing_length"},
      {"--set geometry.bearing_length=0.2", "geometry.bearing_length"},
      {"--set " + quoted("geometry.profile=[[0, 0], [2, 2], [2, 0], [0, 2]]"), "geometry.profile"},
      {"--set geometry.billet_radius=3", "geometry.billet_radius"},
      {"--set geometry.profile_symmetry=y", "geometry.profile_symmetry"},
      {"--set process.type=drawing", "process.type"},
      {"--set geometry.entry_half_height=8", "geometry.entry_half_height"},
      {"--set mesh.bearing_size=2", "mesh.bearing_size"},
      {"--set geometry.profile_file=missing.csv", "geometry.profile_file"},
      {from_file + quoted((scratch / "bad.csv").string()), "bad.csv:3: geometry.profile_file"},
  };
  for (const auto& [settings, key] : refusals) {
    SCOPED_TRACE(settings);
    const fs::path out = scratch / "out";
    const testing::CliResult result =
        testing::run_cli("run -q -o " + quoted(out.string()) + " " + quoted(l_angle) + " " +
                             (settings.rfind("--set", 0) == 0 ? settings : "--set " + settings),
                         scratch.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_TRUE(has_text(result.err, key));
    EXPECT_FALSE(fs::exists(out));
  }
  // The same outline from a CSV is a valid case; the profile keys without a profile are not.
  const testing::CliResult csv =
      testing::run_cli("check " + quoted(l_angle) + " " + from_file +
                           quoted((scratch / "l.csv").string()) + " --set mesh.size=2",
                       scratch.path());
  EXPECT_EQ(csv.exit_code, 0) << csv.err;
  const testing::CliResult stray =
      testing::run_cli("check " + quoted(FORMFLOW_SOURCE_DIR "/cases/paper-q2-2x2-mesh2.toml") +
                           " --set geometry.billet_radius=5",
                       scratch.path());
  EXPECT_EQ(stray.exit_code, 2);
  EXPECT_TRUE(has_text(stray.err, "geometry.billet_radius"));
}

} // namespace
} // namespace formflow
