// SPDX-License-Identifier: MIT
// Rendering a run's pictures, PNG and SVG, on the machine's cores.
#pragma once

#include "formflow/io/plot/canvas.hpp"
#include "formflow/io/plot/pictures.hpp"

#include <string>
#include <vector>

namespace formflow::io::plot {

/// One picture to render: its file stem and what draws it.
struct PictureJob {
  std::string name;
  DrawFunction draw;
};

/// Every job's PNG and SVG, in the jobs' order. The renderings are independent (each has
/// its own cairo surface; `draw` only reads what it captured), so they are shared among
/// up to std::thread::hardware_concurrency() threads: on a 2-core machine the pictures
/// of an 88 714-dof adaptive run took 1.27 s on one thread, most of writing its
/// results. The first exception of any rendering is rethrown here, after every thread
/// has stopped.
std::vector<Picture> render_jobs(const std::vector<PictureJob>& jobs);

} // namespace formflow::io::plot
