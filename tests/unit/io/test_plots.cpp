// SPDX-License-Identifier: MIT
// Pictures: every PNG decodes at the stated size and shows the physics where it should; SVGs exist.
#include "formflow/io/case.hpp"
#include "formflow/io/plot/canvas.hpp"
#include "formflow/io/plot/colour_map.hpp"
#include "formflow/io/plot/pictures.hpp"
#include "formflow/io/plot/ticks.hpp"
#include "formflow/io/results_writer.hpp"
#include "support/synthetic_run.hpp"

// The library links cairo; its include directory is not propagated, but the
// header finds its siblings relative to itself.
#include <cairo/cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace formflow::testing {

namespace {

namespace plot = io::plot;
using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

/// Decodes a PNG with cairo; null if it does not decode.
SurfacePtr decode_png(const std::filesystem::path& path) {
  SurfacePtr surface(cairo_image_surface_create_from_png(path.c_str()), &cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return {nullptr, &cairo_surface_destroy};
  cairo_surface_flush(surface.get());
  return surface;
}

/// The colour at pixel (x, y) of a decoded RGB24/ARGB32 surface (alpha ignored).
plot::Rgb pixel(cairo_surface_t* surface, double x, double y) {
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  std::uint32_t value;
  std::memcpy(&value, data + static_cast<int>(y) * stride + 4 * static_cast<int>(x), 4);
  return {((value >> 16) & 0xff) / 255.0, ((value >> 8) & 0xff) / 255.0, (value & 0xff) / 255.0};
}

/// Decodes PNG bytes held in memory; null if they do not decode.
SurfacePtr decode_png_bytes(const std::string& bytes) {
  struct Reader {
    const std::string& bytes;
    std::size_t at = 0;
  } reader{bytes};
  auto read = [](void* closure, unsigned char* data, unsigned int length) {
    auto* source = static_cast<Reader*>(closure);
    if (source->at + length > source->bytes.size()) return CAIRO_STATUS_READ_ERROR;
    std::memcpy(data, source->bytes.data() + source->at, length);
    source->at += length;
    return CAIRO_STATUS_SUCCESS;
  };
  SurfacePtr surface(cairo_image_surface_create_from_png_stream(read, &reader),
                     &cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return {nullptr, &cairo_surface_destroy};
  cairo_surface_flush(surface.get());
  return surface;
}

/// Pixels in `area` that are strongly red (the not-converged mark's colour).
int red_pixels(cairo_surface_t* surface, const plot::Rect& area) {
  int count = 0;
  for (int y = static_cast<int>(area.y); y < static_cast<int>(area.bottom()); ++y)
    for (int x = static_cast<int>(area.x); x < static_cast<int>(area.right()); ++x) {
      const plot::Rgb colour = pixel(surface, x, y);
      count += colour.r > 0.6 && colour.g < 0.3 && colour.b < 0.3;
    }
  return count;
}

std::size_t distinct_colours(cairo_surface_t* surface) {
  std::set<std::uint32_t> colours;
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < cairo_image_surface_get_height(surface); ++y)
    for (int x = 0; x < cairo_image_surface_get_width(surface); ++x) {
      std::uint32_t value;
      std::memcpy(&value, data + y * stride + 4 * x, 4);
      colours.insert(value & 0xffffff);
    }
  return colours.size();
}

std::string head(const std::filesystem::path& path, std::size_t n) {
  std::ifstream file(path, std::ios::binary);
  std::string text(n, '\0');
  file.read(text.data(), static_cast<std::streamsize>(n));
  text.resize(static_cast<std::size_t>(file.gcount()));
  return text;
}

/// Writes a run's files into a scratch directory. With FORMFLOW_TEST_PICTURES_DIR
/// set, the files are written there instead and kept, to look at them.
class Pictures : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    make_synthetic_run(GetParam(), 1.0, case_, mesh_, results_);
    const char* keep = std::getenv("FORMFLOW_TEST_PICTURES_DIR");
    const std::string name = "q" + std::to_string(GetParam());
    keep_ = keep != nullptr;
    directory_ = keep_ ? std::filesystem::path(keep) / name
                       : std::filesystem::temp_directory_path() /
                             ("formflow_pictures_" + name + "_" + std::to_string(::getpid()));
    io::write_results(directory_.string(), case_, mesh_, results_);
  }
  void TearDown() override {
    if (!keep_) std::filesystem::remove_all(directory_);
  }
  /// The PNG pixel showing data point (x, y) in a field picture.
  plot::Rgb field_pixel(cairo_surface_t* surface, double x, double y) const {
    const plot::Pixel at = plot::field_layout({case_, mesh_, results_}).axes.at(x, y);
    return pixel(surface, at[0], at[1]);
  }

  io::Case case_;
  mesh::Mesh<2> mesh_;
  post::Results results_;
  std::filesystem::path directory_;
  bool keep_ = false;
};

TEST_P(Pictures, EveryPngDecodesAtItsSizeAndEverySvgIsSvg) {
  for (const char* name : {"strain_rate", "velocity", "pressure", "contact", "convergence"}) {
    const auto png = directory_ / (std::string(name) + ".png");
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    const SurfacePtr surface = decode_png(png);
    ASSERT_TRUE(surface) << png << " does not decode";
    EXPECT_EQ(cairo_image_surface_get_width(surface.get()), plot::picture_width) << name;
    EXPECT_EQ(cairo_image_surface_get_height(surface.get()), plot::picture_height) << name;
    // Text, lines and fills: far more than a handful of colours in any real picture.
    EXPECT_GT(distinct_colours(surface.get()), 30u) << name;
    const std::string svg = head(directory_ / (std::string(name) + ".svg"), 5);
    EXPECT_TRUE(svg == "<?xml" || svg.starts_with("<svg")) << name << ": " << svg;
  }
}

TEST_P(Pictures, StrainRateShowsTheDeadMetalZoneAsLowRate) {
  const SurfacePtr surface = decode_png(directory_ / "strain_rate.png");
  ASSERT_TRUE(surface);
  // Dead zone by the corner (10, 10): the dark (purple) end of viridis.
  const plot::Rgb dead = field_pixel(surface.get(), 9.5, 9.5);
  EXPECT_LT(dead.g, 0.25);
  EXPECT_GT(dead.b, dead.g);
  // On the shear band along the dead zone: the bright (green/yellow) end.
  const plot::Rgb band = field_pixel(surface.get(), 7.3, 7.4);
  EXPECT_GT(band.g, 0.5);
}

TEST_P(Pictures, PressureIsRedInCompressionAndBlueInTension) {
  const SurfacePtr surface = decode_png(directory_ / "pressure.png");
  ASSERT_TRUE(surface);
  // Near the ram −σ_H ≈ 2.3 (compression) …
  const plot::Rgb ram = field_pixel(surface.get(), 1.5, 5.5);
  EXPECT_GT(ram.r, ram.b + 0.2);
  // … at the exit surface −σ_H ≈ −0.25 (tension).
  const plot::Rgb exit = field_pixel(surface.get(), 19.5, 4.5);
  EXPECT_GT(exit.b, exit.r + 0.05);
}

TEST_P(Pictures, DieIsDrawnAsAThickDarkLine) {
  const SurfacePtr surface = decode_png(directory_ / "velocity.png");
  ASSERT_TRUE(surface);
  for (const double y : {6.3, 8.7}) { // the die face x = 10, 5 < y < 10
    const plot::Rgb die = field_pixel(surface.get(), 10.0, y);
    EXPECT_LT(die.r + die.g + die.b, 0.6) << "y = " << y;
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, Pictures, ::testing::Values(1, 2),
                         [](const auto& info) { return "Q" + std::to_string(info.param); });

TEST(PicturesWithoutData, EmptyHistoryAndContactStillRender) {
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 2.5, case_, mesh, results);
  results.history.clear();
  results.contact.clear();
  results.stop_reason = solvers::StopReason::SolverFailed;
  const auto pictures = plot::render_pictures(case_, mesh, results);
  ASSERT_EQ(pictures.size(), 7u); // the exit section (synthetic: none) draws "no data"
  for (const auto& picture : pictures) {
    EXPECT_EQ(picture.png.substr(1, 3), "PNG") << picture.name;
    EXPECT_GT(picture.svg.size(), 100u) << picture.name;
  }
}

TEST(PicturesOfAnUnconvergedRun, EveryPictureCarriesARedMark) {
  // Issue 14: only the grey subtitle said "NOT converged"; a picture of the last
  // iterate must not pass for a solution at a glance.
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 2.5, case_, mesh, results);
  const plot::Rect left_edge{0, 100, 3, 400}, corner_label{8, 8, 130, 34};
  for (const bool converged : {true, false}) {
    results.stop_reason =
        converged ? solvers::StopReason::Converged : solvers::StopReason::MaxIterations;
    for (const auto& picture : plot::render_pictures(case_, mesh, results)) {
      const SurfacePtr surface = decode_png_bytes(picture.png);
      ASSERT_TRUE(surface) << picture.name;
      const int frame = red_pixels(surface.get(), left_edge);
      const int label = red_pixels(surface.get(), corner_label);
      if (converged) {
        EXPECT_EQ(frame, 0) << picture.name;
        EXPECT_EQ(label, 0) << picture.name;
      } else {
        EXPECT_EQ(frame, 3 * 400) << picture.name; // the frame covers the edge entirely
        EXPECT_GT(label, 200) << picture.name;     // bold letters, not a stray pixel
      }
    }
  }
}

TEST(PictureSubtitle, FormingRunNamesProcessMeshFrictionAndRamPressure) {
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 2.5, case_, mesh, results);
  EXPECT_EQ(plot::run_description(case_, results),
            "extrusion · Q2, h = 2.5 · μ_{f} = 0.1 · converged in 27 iterations · "
            "ram pressure 2.612");
}

TEST(PictureSubtitle, ManufacturedRunNamesSolutionElementAndH) {
  // A verification run has no process, friction or ram: none of them may be named.
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(1, 2.5, case_, mesh, results);
  case_.manufactured = physics::ManufacturedSolution::Smooth;
  case_.mesh.size = 0.125;
  EXPECT_EQ(plot::run_description(case_, results),
            "manufactured solution \"smooth\" · Q1, h = 0.125 · uniform cells · "
            "converged in 27 iterations");
  case_.manufactured = physics::ManufacturedSolution::Extension;
  case_.mesh.distortion = {mesh::Distortion::Random, 0.2, 3};
  results.stop_reason = solvers::StopReason::MaxIterations;
  const std::string text = plot::run_description(case_, results);
  EXPECT_EQ(text, "manufactured solution \"extension\" · Q1, h = 0.125 · random distortion 0.2 · "
                  "NOT converged (max_iterations, 27 iterations)");
}

TEST(PlotTicks, NiceNumbersAndLabels) {
  EXPECT_DOUBLE_EQ(plot::nice_step(10.0, 5), 2.0);
  EXPECT_DOUBLE_EQ(plot::nice_step(0.7, 7), 0.1);
  EXPECT_EQ(plot::linear_ticks(0.0, 20.0, 5), (std::vector<double>{0, 5, 10, 15, 20}));
  EXPECT_EQ(plot::decade_ticks(2e-3, 50.0), (std::vector<double>{1e-2, 1e-1, 1, 10}));
  const auto levels = plot::log_125_levels(3e-3, 4.0);
  EXPECT_DOUBLE_EQ(levels.front(), 2e-3);
  EXPECT_DOUBLE_EQ(levels.back(), 5.0);
  EXPECT_EQ(levels.size(), 11u); // 2e-3 5e-3 1e-2 2e-2 5e-2 0.1 0.2 0.5 1 2 5
  EXPECT_EQ(plot::tick_label(-1.5, 0.5), "−1.5");
  EXPECT_EQ(plot::tick_label(2.0, 0.5), "2.0");
  EXPECT_EQ(plot::tick_label(0.0, 0.5), "0");
  EXPECT_EQ(plot::log_tick_label(1e-3, false), "0.001");
  EXPECT_EQ(plot::log_tick_label(100.0, false), "100");
  EXPECT_EQ(plot::log_tick_label(1e-6, true), "10⁻⁶");
  EXPECT_EQ(plot::log_tick_label(0.01, true), "10⁻²");
  EXPECT_TRUE(plot::log_labels_as_powers(1e-5, 1.0));
  EXPECT_FALSE(plot::log_labels_as_powers(1e-3, 1e4));
}

TEST(PlotColours, AFieldConstantToRoundOffGetsOneBand) {
  // A rigid translation's u_x: 1 and its neighbour double. Its span is below the values'
  // resolution, where a step of a tenth of it would never advance past the first level.
  const double one = 1.0, next = std::nextafter(1.0, 2.0);
  const auto scale = plot::ColourScale::linear(one, next, 10, plot::Palette::Sequential);
  EXPECT_LE(scale.n_bands(), 12u);
  EXPECT_LE(scale.boundaries().front(), one);
  EXPECT_GE(scale.boundaries().back(), next);
}

TEST(PlotColours, ScalesAndMaps) {
  const auto scale = plot::ColourScale::linear(-0.3, 2.9, 12, plot::Palette::Diverging);
  EXPECT_LE(scale.boundaries().front(), -0.3);
  EXPECT_GE(scale.boundaries().back(), 2.9);
  EXPECT_EQ(scale.band_of(-100.0), 0u);
  EXPECT_EQ(scale.band_of(100.0), scale.n_bands() - 1);
  // Diverging: the bands touching zero are nearly white, the top one red.
  const plot::Rgb above_zero = scale.band_colour(scale.band_of(0.01));
  EXPECT_GT(above_zero.r + above_zero.g + above_zero.b, 2.6);
  const plot::Rgb top = scale.band_colour(scale.n_bands() - 1);
  EXPECT_GT(top.r, top.b + 0.3);
  EXPECT_LT(plot::viridis(0.0).g, 0.05);
  EXPECT_GT(plot::viridis(1.0).r, 0.95);
}

TEST(PlotText, CombiningMarksAddNoWidth) {
  // ε̄̇ must be as wide as ε: the macron and dot are drawn over it, not after it.
  plot::render_png(50, 20, [](plot::Canvas& canvas) {
    const plot::Font font{20.0};
    EXPECT_DOUBLE_EQ(canvas.text_width("ε\u0304\u0307", font), canvas.text_width("ε", font));
    EXPECT_LT(canvas.text_width("σ_{H}", font), canvas.text_width("σH", font));
  });
}

} // namespace
} // namespace formflow::testing
