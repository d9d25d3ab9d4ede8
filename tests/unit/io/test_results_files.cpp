// SPDX-License-Identifier: MIT
// summary.json, history.csv and contact.csv: keys, headers, values, and the non-finite guard.
#include "formflow/core/error.hpp"
#include "formflow/io/case_json.hpp"
#include "formflow/io/csv.hpp"
#include "formflow/io/results_writer.hpp"
#include "formflow/mesh/cell_diameter.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "support/approx.hpp"
#include "support/synthetic_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace formflow::testing {

namespace {

/// Effective channel height of the synthetic flow: 10 in the container, 5 in
/// the exit, shrinking smoothly along the dead-metal boundary x ∈ [5, 10].
double channel_height(double x, double* slope) {
  const double t = std::clamp((x - 5.0) / 5.0, 0.0, 1.0);
  if (slope) *slope = (x > 5.0 && x < 10.0) ? -5.0 * (6.0 * t - 6.0 * t * t) / 5.0 : 0.0;
  return 10.0 - 5.0 * (3.0 * t * t - 2.0 * t * t * t);
}

/// Synthetic nodal fields shaped like an extrusion solution: divergence-free
/// flow u = (10/h, 10·y·h'/h²) below y = h(x), still metal above it (the
/// dead zone at the corner (10, 10)), a strain-rate band along the dead zone
/// boundary peaking at the die corner (10, 5), pressure falling from the ram
/// to slight tension at the exit surface.
void fill_fields(const mesh::Mesh<2>& mesh, post::Fields& fields) {
  const Index n = mesh.n_nodes();
  fields.velocity.resize(2 * n);
  fields.equivalent_strain_rate.resize(n);
  fields.hydrostatic_stress.resize(n);
  fields.contact_pressure = VectorX::Zero(n);
  fields.friction_stress = VectorX::Zero(n);
  for (Index node = 0; node < n; ++node) {
    const double x = mesh.nodes(0, node), y = mesh.nodes(1, node);
    double slope = 0.0;
    const double h = channel_height(x, &slope);
    const bool flowing = y <= h + 1e-12;
    fields.velocity[2 * node] = flowing ? 10.0 / h : 0.0;
    fields.velocity[2 * node + 1] = flowing ? -10.0 * y * slope / (h * h) : 0.0;
    const double band = std::abs(x + y - 15.0) / std::sqrt(2.0); // distance to the shear line
    const double corner = std::hypot(x - 10.0, y - 5.0);
    const double plastic = std::exp(-band * band / 2.0) * (1.0 + 3.0 / (1.0 + 4.0 * corner));
    fields.equivalent_strain_rate[node] = 1e-3 + (flowing ? plastic : 0.02 * plastic * 1e-2);
    const double pressure = x <= 10.0 ? 2.6 - 0.22 * x + 1.5 * std::exp(-corner * corner / 0.3)
                                      : 0.4 - 0.04 * (x - 10.0) - 0.3 * y / 5.0;
    fields.hydrostatic_stress[node] = -pressure;
    const bool on_wall = std::abs(y - 10.0) < 1e-12 || (std::abs(x - 10.0) < 1e-12 && y >= 5.0);
    if (on_wall) {
      fields.contact_pressure[node] = pressure;
      fields.friction_stress[node] = 0.1 * pressure;
    }
  }
  fields.cell_equivalent_strain_rate.resize(mesh.n_cells());
  fields.cell_hydrostatic_stress.resize(mesh.n_cells());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    double rate = 0.0, stress = 0.0;
    for (int local = 0; local < mesh.nodes_per_cell(); ++local) {
      rate += fields.equivalent_strain_rate[mesh.cells(local, cell)];
      stress += fields.hydrostatic_stress[mesh.cells(local, cell)];
    }
    fields.cell_equivalent_strain_rate[cell] = rate / mesh.nodes_per_cell();
    fields.cell_hydrostatic_stress[cell] = stress / mesh.nodes_per_cell();
  }
}

/// Two samples per unit length along the container wall, then the die face;
/// the die face sticks in the dead-metal zone (s < 13).
std::vector<post::ContactSample> contact_samples() {
  std::vector<post::ContactSample> samples;
  for (double s = 0.25; s < 15.0; s += 0.5) {
    post::ContactSample sample;
    sample.arc_length = s;
    sample.part = s < 10.0 ? 0 : 1;
    sample.x = s < 10.0 ? s : 10.0;
    sample.y = s < 10.0 ? 10.0 : 20.0 - s;
    sample.contact_pressure = s < 10.0 ? 2.6 - 0.1 * s : 3.2 + 0.3 * (s - 10.0);
    sample.sticking = s > 10.0 && s < 13.0;
    sample.slip_velocity = sample.sticking ? 1e-7 * s : (s < 10.0 ? 1.0 : 1.5);
    sample.friction_stress = (sample.sticking ? 0.06 : 0.1) * sample.contact_pressure;
    samples.push_back(sample);
  }
  return samples;
}

} // namespace

// Declared in support/synthetic_run.hpp, used by test_vtu.cpp and test_plots.cpp too.
void make_synthetic_run(int order, double size, io::Case& case_, mesh::Mesh<2>& mesh,
                        post::Results& results) {
  case_ = io::Case{};
  case_.element = order == 1 ? fem::ElementKind::Q1 : fem::ElementKind::Q2;
  case_.mesh.size = size;
  case_.friction.mu = 0.1;
  case_.source = "synthetic";
  mesh = mesh::make_channel_mesh(case_.mesh.geometry, size, order);
  results = post::Results{};
  results.stop_reason = solvers::StopReason::Converged;
  results.iterations = 27;
  for (int i = 1; i <= 27; ++i)
    results.history.push_back(
        {i, 0.8 * std::pow(0.7, i - 1), 2.6 + 0.5 * std::pow(0.7, i), 0.01 * i + 1.0 / 3.0});
  results.n_cells = mesh.n_cells();
  results.n_nodes = mesh.n_nodes();
  results.n_dofs = 2 * mesh.n_nodes();
  const mesh::CellDiameterRange diameters = mesh::cell_diameter_range(mesh);
  results.min_cell_diameter = diameters.smallest;
  results.max_cell_diameter = diameters.largest;
  results.pressure = {2.6123, 2.598, 2.6121, 2.71};
  results.power = {25.98, 26.01, 0.07, 0.003, 0.04};
  fill_fields(mesh, results.fields);
  results.max_equivalent_strain_rate = results.fields.equivalent_strain_rate.maxCoeff();
  results.contact = contact_samples();
  results.timing.add("total", 1.5);
  results.timing.add("assembly", 0.7);
  results.timing.add("mesh", 0.01);
  results.timing.count("factorization", 9);
  results.timing.count("krylov iterations", 12);
}

namespace {

/// A fresh directory under the system temp dir, removed with everything in it.
struct ScratchDirectory {
  std::filesystem::path path;
  explicit ScratchDirectory(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("formflow_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  std::set<std::string> entries() const {
    std::set<std::string> names;
    if (std::filesystem::exists(path))
      for (const auto& entry : std::filesystem::directory_iterator(path))
        names.insert(entry.path().filename().string());
    return names;
  }
};

std::vector<std::vector<std::string>> read_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

class ResultsFiles : public ::testing::Test {
protected:
  void SetUp() override { make_synthetic_run(2, 1.0, case_, mesh_, results_); }
  /// summary.json's "mesh" block of the run as it stands.
  nlohmann::json summary_mesh() const {
    return nlohmann::json::parse(io::summary_json(case_, results_)).at("mesh");
  }
  io::Case case_;
  mesh::Mesh<2> mesh_;
  post::Results results_;
};

TEST_F(ResultsFiles, SummaryMeshSizeIsNullForAFileMeshAndTheDiametersDescribeIt) {
  // A .msh file has no single cell size: mesh.size (its default here) would describe nothing.
  case_.mesh.source = mesh::MeshSource::File;
  case_.mesh.file = "die.msh";
  results_.min_cell_diameter = 0.03;
  results_.max_cell_diameter = 0.4;
  const auto mesh = summary_mesh();
  EXPECT_EQ(mesh.at("source"), "file");
  ASSERT_TRUE(mesh.contains("size"));
  EXPECT_TRUE(mesh.at("size").is_null());
  EXPECT_EQ(mesh.at("min_cell_diameter"), 0.03);
  EXPECT_EQ(mesh.at("max_cell_diameter"), 0.4);
  // Gmsh meshes the channel with mesh.size as its target size.
  case_.mesh.source = mesh::MeshSource::Gmsh;
  case_.mesh.size = 0.3;
  const auto gmsh = summary_mesh();
  EXPECT_EQ(gmsh.at("source"), "gmsh");
  EXPECT_EQ(gmsh.at("size"), 0.3);
}

TEST_F(ResultsFiles, SummaryMeshOfAManufacturedRunIsTheBox) {
  // The verification box is built from mesh.size, whatever mesh.source says.
  case_.manufactured = physics::ManufacturedSolution::Smooth;
  case_.mesh.source = mesh::MeshSource::File;
  case_.mesh.size = 0.125;
  const auto mesh = summary_mesh();
  EXPECT_EQ(mesh.at("source"), "box");
  EXPECT_EQ(mesh.at("size"), 0.125);
}

TEST_F(ResultsFiles, SummaryHasEveryKeyWithItsValue) {
  const auto summary = nlohmann::json::parse(io::summary_json(case_, results_));
  EXPECT_EQ(summary.at("converged"), true);
  EXPECT_EQ(summary.at("stop_reason"), "converged");
  EXPECT_EQ(summary.at("iterations"), 27);
  const auto& mesh = summary.at("mesh");
  EXPECT_EQ(mesh.at("elements"), mesh_.n_cells());
  EXPECT_EQ(mesh.at("nodes"), mesh_.n_nodes());
  EXPECT_EQ(mesh.at("dofs"), 2 * mesh_.n_nodes());
  EXPECT_EQ(mesh.at("element"), "Q2");
  EXPECT_EQ(mesh.at("size"), 1.0);
  EXPECT_EQ(mesh.at("source"), "structured");
  EXPECT_EQ(mesh.at("min_cell_diameter"), std::sqrt(2.0)); // unit squares
  EXPECT_EQ(mesh.at("max_cell_diameter"), std::sqrt(2.0));
  // JSON doubles are written with round-trip precision: exact comparisons.
  const auto& pressure = summary.at("pressure");
  EXPECT_EQ(pressure.at("ram_reaction"), 2.6123);
  EXPECT_EQ(pressure.at("power_balance"), 2.598);
  EXPECT_EQ(pressure.at("total_power"), 2.6121);
  EXPECT_EQ(pressure.at("mean_hydrostatic_near_ram"), 2.71);
  EXPECT_FALSE(pressure.contains("drawing_stress")); // extrusion
  const auto& power = summary.at("power");
  EXPECT_EQ(power.at("plastic_dissipation"), 25.98);
  EXPECT_EQ(power.at("viscous_form"), 26.01);
  EXPECT_EQ(power.at("volumetric_penalty"), 0.07);
  EXPECT_EQ(power.at("contact_penalty"), 0.003);
  EXPECT_EQ(power.at("friction"), 0.04);
  EXPECT_EQ(power.at("total"), results_.power.total());
  EXPECT_EQ(summary.at("max_equivalent_strain_rate"), results_.max_equivalent_strain_rate);
  ASSERT_EQ(summary.at("history").size(), 27u);
  ASSERT_EQ(summary.at("history_pressure").size(), 27u);
  for (std::size_t i = 0; i < 27; ++i) {
    EXPECT_EQ(summary["history"][i], results_.history[i].relative_change);
    EXPECT_EQ(summary["history_pressure"][i], results_.history[i].pressure);
  }
  const auto& timing = summary.at("timing_s");
  EXPECT_EQ(timing.at("total"), 1.5);
  EXPECT_EQ(timing.at("assembly"), 0.7);
  EXPECT_EQ(timing.at("mesh"), 0.01);
  EXPECT_EQ(timing.at("factorization"), 0.0); // absent phases are present as 0
  EXPECT_EQ(timing.at("solve"), 0.0);
  const auto& linear_algebra = summary.at("linear_algebra");
  EXPECT_EQ(linear_algebra.at("factorizations"), 9);
  EXPECT_EQ(linear_algebra.at("krylov_iterations"), 12);
  // Phases added as seconds only (no timer) ran 0 counted times; every timed phase is listed.
  EXPECT_EQ(summary.at("timing_calls").at("assembly"), 0);
  EXPECT_EQ(summary.at("timing_calls").size(), 3u); // total, assembly, mesh
  EXPECT_EQ(summary.at("case"), nlohmann::json(io::case_to_json(case_)));
  // Read in file order, the case block keeps the key table's order.
  const auto ordered = nlohmann::ordered_json::parse(io::summary_json(case_, results_));
  EXPECT_EQ(ordered.at("case"), io::case_to_json(case_));
  EXPECT_EQ(summary.at("formflow_version"), FORMFLOW_VERSION);
}

TEST_F(ResultsFiles, SummaryReportsStickAndSlipPerContactPart) {
  results_.container_zones = {10.0, 0.0};
  results_.die_zones = {5.0, 2.0};
  auto contact = nlohmann::json::parse(io::summary_json(case_, results_)).at("contact");
  EXPECT_EQ(contact.at("regularization"), "regularized");
  EXPECT_EQ(contact.at("die").at("length"), 5.0);
  EXPECT_EQ(contact.at("die").at("stick_length"), 2.0);
  EXPECT_EQ(contact.at("die").at("slip_length"), 3.0);
  EXPECT_EQ(contact.at("die").at("stick_fraction"), 0.4);
  EXPECT_EQ(contact.at("container").at("stick_fraction"), 0.0);
  EXPECT_FALSE(contact.contains("augmented_lagrangian")); // only for exact friction
  EXPECT_EQ(contact.at("points"), "faces");

  case_.friction.regularization = physics::FrictionRegularization::None;
  results_.augmentation = {12, 3e-5, 4e-6, 2e-7};
  contact = nlohmann::json::parse(io::summary_json(case_, results_)).at("contact");
  EXPECT_EQ(contact.at("regularization"), "none");
  EXPECT_EQ(contact.at("augmented_lagrangian").at("outer_iterations"), 12);
  EXPECT_EQ(contact.at("augmented_lagrangian").at("multiplier_change"), 3e-5);
  EXPECT_EQ(contact.at("friction_residual"), 4e-6);
  EXPECT_EQ(contact.at("power_residual"), 2e-7);
  // The exact law's default under Newton: the semismooth Newton on nodal points, stick
  // read off the slip speed; the old path by key; the secant loop's active set.
  EXPECT_EQ(contact.at("stick"), "exact");
  EXPECT_EQ(contact.at("stick_given"), false);
  EXPECT_EQ(contact.at("points"), "nodes");
  EXPECT_EQ(contact.at("stick_criterion"), "|u_T| <= solver.tolerance * process.speed");
  // The case block names the points that ran, so that it reruns the same way.
  const auto block = nlohmann::json::parse(io::summary_json(case_, results_)).at("case");
  EXPECT_EQ(block.at("contact").at("normals"), "nodes");
  EXPECT_EQ(block.at("friction").at("stick"), "auto");
  case_.friction_stick = io::StickEnforcement::Augmented;
  contact = nlohmann::json::parse(io::summary_json(case_, results_)).at("contact");
  EXPECT_EQ(contact.at("stick"), "augmented");
  EXPECT_EQ(contact.at("stick_given"), true);
  EXPECT_EQ(contact.at("points"), "faces");
  EXPECT_EQ(contact.at("stick_criterion"), "|u_T| <= solver.tolerance * process.speed");
  case_.solver.method = solvers::NonlinearMethod::Secant;
  contact = nlohmann::json::parse(io::summary_json(case_, results_)).at("contact");
  EXPECT_EQ(contact.at("stick"), "augmented (secant loop)");
  EXPECT_TRUE(contact.at("stick_criterion").get<std::string>().find("Alart") != std::string::npos);
}

TEST_F(ResultsFiles, SummaryOfAnUnconvergedDrawingRun) {
  case_.process.type = physics::ProcessType::Drawing;
  case_.element = fem::ElementKind::Q1;
  results_.stop_reason = solvers::StopReason::MaxIterations;
  const auto summary = nlohmann::json::parse(io::summary_json(case_, results_));
  EXPECT_EQ(summary.at("converged"), false);
  EXPECT_EQ(summary.at("stop_reason"), "max_iterations");
  EXPECT_EQ(summary.at("mesh").at("element"), "Q1");
  EXPECT_EQ(summary.at("pressure").at("drawing_stress"), 2.6123);
}

TEST_F(ResultsFiles, SummaryIsPrettyWithTwoSpaces) {
  const std::string text = io::summary_json(case_, results_);
  EXPECT_EQ(text.substr(0, 4), "{\n  ");
  EXPECT_EQ(text.back(), '\n');
}

TEST_F(ResultsFiles, NonFiniteSummaryValueThrowsNamingTheKey) {
  results_.pressure.total_power = std::numeric_limits<double>::quiet_NaN();
  try {
    io::summary_json(case_, results_);
    FAIL() << "no exception";
  } catch (const InternalError& error) {
    EXPECT_NE(std::string(error.what()).find("pressure.total_power"), std::string::npos)
        << error.what();
  }
  results_.pressure.total_power = 1.0;
  results_.history[3].pressure = std::numeric_limits<double>::infinity();
  EXPECT_THROW(io::summary_json(case_, results_), InternalError);
  results_.history[3].pressure = 1.0;
  case_.material.parameters_of<physics::PiecewisePower>().alpha =
      std::numeric_limits<double>::quiet_NaN(); // inside the "case" object
  try {
    io::summary_json(case_, results_);
    FAIL() << "no exception";
  } catch (const InternalError& error) {
    EXPECT_NE(std::string(error.what()).find("case.material.alpha"), std::string::npos)
        << error.what();
  }
}

TEST_F(ResultsFiles, NonFiniteValueLeavesNoFilesBehind) {
  const ScratchDirectory scratch("nonfinite");
  results_.power.friction = std::numeric_limits<double>::infinity();
  EXPECT_THROW(io::write_results(scratch.path.string(), case_, mesh_, results_), InternalError);
  EXPECT_FALSE(std::filesystem::exists(scratch.path / "summary.json"));
  EXPECT_TRUE(scratch.entries().empty()); // no other file and no temporary either
}

TEST_F(ResultsFiles, WriteResultsWritesExactlyTheListedFiles) {
  const ScratchDirectory scratch("all_files");
  io::write_results((scratch.path / "nested" / "out").string(), case_, mesh_, results_);
  std::set<std::string> expected = {"summary.json", "history.csv", "contact.csv", "fields.vtu",
                                    "report.html"};
  for (const char* picture : {"strain_rate", "velocity", "pressure", "contact", "convergence",
                              "load_error", "exit_velocity"}) {
    expected.insert(std::string(picture) + ".png");
    expected.insert(std::string(picture) + ".svg");
  }
  std::set<std::string> written;
  for (const auto& entry : std::filesystem::directory_iterator(scratch.path / "nested" / "out"))
    written.insert(entry.path().filename().string());
  EXPECT_EQ(written, expected);
  std::ifstream file(scratch.path / "nested" / "out" / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, io::summary_json(case_, results_));
}

TEST_F(ResultsFiles, HistoryCsvRoundTrips) {
  const auto rows = read_csv(io::history_csv(results_.history));
  ASSERT_EQ(rows.size(), results_.history.size() + 1);
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{"iteration", "relative_change", "pressure", "seconds"}));
  for (std::size_t i = 0; i < results_.history.size(); ++i) {
    const auto& record = results_.history[i];
    ASSERT_EQ(rows[i + 1].size(), 4u);
    EXPECT_EQ(std::stoi(rows[i + 1][0]), record.iteration);
    // {:.10g} keeps ten significant digits: a relative error below 1e-9.
    EXPECT_TRUE(approx(std::stod(rows[i + 1][1]), record.relative_change, 1e-9));
    EXPECT_TRUE(approx(std::stod(rows[i + 1][2]), record.pressure, 1e-9));
    EXPECT_TRUE(approx(std::stod(rows[i + 1][3]), record.seconds, 1e-9));
  }
}

TEST_F(ResultsFiles, ContactCsvRoundTrips) {
  const auto rows = read_csv(io::contact_csv(results_.contact));
  ASSERT_EQ(rows.size(), results_.contact.size() + 1);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"s", "x", "y", "contact_pressure", "friction_stress",
                                               "slip_velocity", "state", "part"}));
  for (std::size_t i = 0; i < results_.contact.size(); ++i) {
    const auto& sample = results_.contact[i];
    const auto& row = rows[i + 1];
    ASSERT_EQ(row.size(), 8u);
    // {:.10g}: relative error below 1e-9; slip velocities ~1e-7 are kept relatively too.
    EXPECT_TRUE(approx(std::stod(row[0]), sample.arc_length, 1e-9));
    EXPECT_TRUE(approx(std::stod(row[1]), sample.x, 1e-9));
    EXPECT_TRUE(approx(std::stod(row[2]), sample.y, 1e-9));
    EXPECT_TRUE(approx(std::stod(row[3]), sample.contact_pressure, 1e-9));
    EXPECT_TRUE(approx(std::stod(row[4]), sample.friction_stress, 1e-9));
    EXPECT_TRUE(approx(std::stod(row[5]), sample.slip_velocity, 1e-9));
    EXPECT_EQ(row[6], sample.sticking ? "stick" : "slip");
    EXPECT_EQ(row[7], sample.part == 0 ? "container" : "die");
  }
  EXPECT_EQ(rows[1][7], "container");
  EXPECT_EQ(rows.back()[7], "die");
  EXPECT_EQ(rows[23][6], "stick"); // s = 11.25, inside the sticking dead zone
}

TEST_F(ResultsFiles, NonFiniteCsvValueThrowsNamingRowAndColumn) {
  results_.contact[4].slip_velocity = std::numeric_limits<double>::quiet_NaN();
  try {
    io::contact_csv(results_.contact);
    FAIL() << "no exception";
  } catch (const InternalError& error) {
    EXPECT_NE(std::string(error.what()).find("row 5 column slip_velocity"), std::string::npos)
        << error.what();
  }
  results_.history[0].seconds = -std::numeric_limits<double>::infinity();
  EXPECT_THROW(io::history_csv(results_.history), InternalError);
}

TEST_F(ResultsFiles, CsvOfAnUnconvergedRunStartsWithACommentNamingTheStopReason) {
  // Issue 14: the not-converged mark was in summary.json only.
  const std::string converged = io::history_csv(results_.history);
  const std::string history = io::history_csv(results_.history, solvers::StopReason::Diverged);
  EXPECT_EQ(history, "# not converged: diverged\n" + converged);
  const std::string contact = io::contact_csv(results_.contact, solvers::StopReason::MaxIterations);
  EXPECT_EQ(contact, "# not converged: max_iterations\n" + io::contact_csv(results_.contact));
  EXPECT_EQ(converged.find('#'), std::string::npos); // a converged run has no comment
}

TEST_F(ResultsFiles, EveryFileOfAnUnconvergedRunSaysSo) {
  const ScratchDirectory scratch("unconverged");
  results_.stop_reason = solvers::StopReason::MaxIterations;
  io::write_results(scratch.path.string(), case_, mesh_, results_);
  auto read = [&](const char* name) {
    std::ifstream file(scratch.path / name);
    return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(nlohmann::json::parse(read("summary.json")).at("converged"), false);
  for (const char* csv : {"history.csv", "contact.csv"})
    EXPECT_EQ(read(csv).rfind("# not converged: max_iterations\n", 0), 0u) << csv;
  const std::string vtu = read("fields.vtu");
  EXPECT_NE(vtu.find("Name=\"converged\" NumberOfTuples=\"1\" format=\"ascii\">0<"),
            std::string::npos);
  EXPECT_NE(vtu.find("NOT CONVERGED (max_iterations)"), std::string::npos);
}

TEST_F(ResultsFiles, EmptyTablesHaveOnlyTheHeader) {
  EXPECT_EQ(io::history_csv({}), "iteration,relative_change,pressure,seconds\n");
  EXPECT_EQ(io::contact_csv({}),
            "s,x,y,contact_pressure,friction_stress,slip_velocity,state,part\n");
}

} // namespace
} // namespace formflow::testing
