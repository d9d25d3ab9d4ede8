// SPDX-License-Identifier: MIT
// The pressure pictures of docs/mixed.md. Writes PNGs into $FORMFLOW_PICTURES_DIR
// (default: a temporary directory); regenerate the docs' with
//   FORMFLOW_PICTURES_DIR=docs/img build/tests/test_long --gtest_filter='MixedPictures.*'
#include "formflow/app/simulation.hpp"
#include "formflow/io/plot/pictures.hpp"
#include "verification/checkerboard.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace formflow {
namespace {

namespace fs = std::filesystem;

constexpr Real size = 0.5;

fs::path pictures_dir() {
  const char* dir = std::getenv("FORMFLOW_PICTURES_DIR");
  const fs::path path = dir ? fs::path(dir) : fs::temp_directory_path() / "formflow-mixed-pictures";
  fs::create_directories(path);
  return path;
}

io::Case sticking_case(fem::ElementKind element, fem::PressureSpace space, Real d) {
  io::Case case_;
  case_.process.ram = physics::RamCondition::Sticking;
  case_.mesh.size = size;
  case_.element = element;
  case_.formulation.type = assembly::FormulationType::Mixed;
  case_.formulation.pressure = space;
  case_.penalty.d = d;
  return case_;
}

void save(const io::Case& case_, const app::Simulation& simulation, const std::string& name,
          const std::function<void(const io::plot::Canvas&, const io::plot::PictureData&)>& draw) {
  const io::plot::PictureData data{case_, simulation.plane_mesh(), simulation.results};
  const std::string png =
      io::plot::render_png(io::plot::picture_width, io::plot::picture_height,
                           [&](io::plot::Canvas& canvas) { draw(canvas, data); });
  std::ofstream(pictures_dir() / (name + ".png"), std::ios::binary) << png;
}

TEST(MixedPictures, CheckerboardOfQ1P0AndItsFilterAndTheSmoothQ2P1discPressure) {
  const io::Case q1p0_case = sticking_case(fem::ElementKind::Q1, fem::PressureSpace::P0, 1e-3);
  const app::Simulation q1p0 = app::simulate(q1p0_case);
  const VectorX raw = -q1p0.results.fields.cell_hydrostatic_stress;
  const VectorX filtered = testing::filter_checkerboard(q1p0.plane_mesh(), size, raw);
  save(q1p0_case, q1p0, "mixed_q1p0_cells", [&](const auto& canvas, const auto& data) {
    io::plot::draw_cell_pressure(canvas, data, raw,
                                 "Q1–P0 cell pressure (= Q1, 1×1 rule), d = 1e-3");
  });
  save(q1p0_case, q1p0, "mixed_q1p0_filtered", [&](const auto& canvas, const auto& data) {
    io::plot::draw_cell_pressure(canvas, data, filtered,
                                 "Q1–P0 cell pressure after the 2×2 macro filter");
  });

  const io::Case q2_case = sticking_case(fem::ElementKind::Q2, fem::PressureSpace::P1disc, 0.0);
  const app::Simulation q2 = app::simulate(q2_case);
  const VectorX q2_cells = -q2.results.fields.cell_hydrostatic_stress;
  save(q2_case, q2, "mixed_q2p1disc_cells", [&](const auto& canvas, const auto& data) {
    io::plot::draw_cell_pressure(canvas, data, q2_cells,
                                 "Q2–P1disc cell-mean pressure, d = 0 (exact)");
  });
  save(q2_case, q2, "mixed_q2p1disc_pressure", io::plot::draw_pressure);

  const double q1p0_share = testing::checkerboard_share(q1p0.plane_mesh(), size, raw, 10.0);
  const double q2_share = testing::checkerboard_share(q2.plane_mesh(), size, q2_cells, 10.0);
  std::printf("checkerboard share in the container: Q1-P0 %.3e, filtered %.3e, Q2-P1disc %.3e\n",
              q1p0_share, testing::checkerboard_share(q1p0.plane_mesh(), size, filtered, 10.0),
              q2_share);
  std::printf("ram pressure: Q1-P0 %.4f, Q2-P1disc (d = 0) %.4f\n",
              q1p0.results.pressure.ram_reaction, q2.results.pressure.ram_reaction);
  EXPECT_GT(q1p0_share, 10.0 * q2_share);
}

} // namespace
} // namespace formflow
