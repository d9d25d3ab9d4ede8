// SPDX-License-Identifier: MIT
// The pictures rendered on several threads are the ones one thread renders, in order,
// and a drawing's failure reaches the caller.
#include "formflow/io/plot/picture_rendering.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace formflow::testing {

namespace {

namespace plot = io::plot;

/// Eight pictures, each a differently shaded square with its own label, so that a
/// picture written under another's name would be caught.
std::vector<plot::PictureJob> labelled_squares() {
  std::vector<plot::PictureJob> jobs;
  for (int k = 0; k < 8; ++k)
    jobs.push_back({"square" + std::to_string(k), [k](plot::Canvas& canvas) {
                      canvas.fill_rect({20.0 + 10 * k, 20, 200, 200}, {0.1 * k, 0.2, 0.5});
                      canvas.text({40, 260}, "picture " + std::to_string(k), plot::Font{14.0});
                    }});
  return jobs;
}

} // namespace

TEST(PictureRendering, EveryJobGetsItsOwnPngAndSvgInOrder) {
  const std::vector<plot::PictureJob> jobs = labelled_squares();
  const std::vector<plot::Picture> pictures = plot::render_jobs(jobs);
  ASSERT_EQ(pictures.size(), jobs.size());
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    EXPECT_EQ(pictures[k].name, jobs[k].name);
    // Cairo renders a drawing to the same pixels on any thread; the PNG encoder is
    // deterministic, so the bytes are those of the one-thread rendering.
    EXPECT_EQ(pictures[k].png,
              plot::render_png(plot::picture_width, plot::picture_height, jobs[k].draw));
    EXPECT_NE(pictures[k].svg.find("<svg"), std::string::npos);
    if (k > 0) {
      EXPECT_NE(pictures[k].png, pictures[k - 1].png);
    }
  }
}

TEST(PictureRendering, ADrawingsFailureReachesTheCaller) {
  std::vector<plot::PictureJob> jobs = labelled_squares();
  jobs[5].draw = [](plot::Canvas&) { throw std::runtime_error("picture 5 cannot be drawn"); };
  EXPECT_THROW(plot::render_jobs(jobs), std::runtime_error);
}

TEST(PictureRendering, NoJobsNoPictures) {
  EXPECT_TRUE(plot::render_jobs({}).empty());
}

} // namespace formflow::testing
