// SPDX-License-Identifier: MIT
// Rendering a run's pictures, PNG and SVG, on the machine's cores.
#include "formflow/io/plot/picture_rendering.hpp"

#include "formflow/core/parallel_tasks.hpp"

#include <algorithm>
#include <thread>

namespace formflow::io::plot {

std::vector<Picture> render_jobs(const std::vector<PictureJob>& jobs) {
  std::vector<Picture> out(jobs.size());
  // Task 2k is picture k's PNG, 2k + 1 its SVG: the most even split of the work there is
  // (the two formats of one picture cost about the same).
  run_tasks(2 * jobs.size(), std::max<std::size_t>(1, std::thread::hardware_concurrency()),
            [&](std::size_t task) {
              const PictureJob& job = jobs[task / 2];
              if (task % 2 == 0)
                out[task / 2].png = render_png(picture_width, picture_height, job.draw);
              else
                out[task / 2].svg = render_svg(picture_width, picture_height, job.draw);
            });
  for (std::size_t k = 0; k < jobs.size(); ++k) out[k].name = jobs[k].name;
  return out;
}

} // namespace formflow::io::plot
