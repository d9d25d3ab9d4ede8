// SPDX-License-Identifier: MIT
// Rendering a run's pictures, PNG and SVG, on the machine's cores.
#include "formflow/io/plot/picture_rendering.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <future>
#include <thread>

namespace formflow::io::plot {

std::vector<Picture> render_jobs(const std::vector<PictureJob>& jobs) {
  std::vector<Picture> out(jobs.size());
  // Task 2k is picture k's PNG, 2k + 1 its SVG: the most even split of the work there is
  // (the two formats of one picture cost about the same).
  const std::size_t n_tasks = 2 * jobs.size();
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t task = next++; task < n_tasks; task = next++) {
      const PictureJob& job = jobs[task / 2];
      if (task % 2 == 0)
        out[task / 2].png = render_png(picture_width, picture_height, job.draw);
      else
        out[task / 2].svg = render_svg(picture_width, picture_height, job.draw);
    }
  };
  const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1,
                                                      std::max<std::size_t>(1, n_tasks));
  std::vector<std::future<void>> helpers;
  for (std::size_t k = 1; k < threads; ++k) helpers.push_back(std::async(std::launch::async, work));
  std::exception_ptr failure;
  try {
    work();
  } catch (...) {
    failure = std::current_exception();
    next = n_tasks; // the helpers take no new task
  }
  for (std::future<void>& helper : helpers) {
    try {
      helper.get();
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  for (std::size_t k = 0; k < jobs.size(); ++k) out[k].name = jobs[k].name;
  return out;
}

} // namespace formflow::io::plot
