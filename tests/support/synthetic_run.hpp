// SPDX-License-Identifier: MIT
// A complete, realistic-looking run without solving anything, for the output writers' tests.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"

namespace formflow::testing {

/// The benchmark channel meshed with `size` and Q`order` cells, with smooth
/// made-up fields, 27 iterations, pressures, powers, contact samples and timings
/// (defined in tests/unit/io/test_results_files.cpp, whose tests check them).
void make_synthetic_run(int order, double size, io::Case& case_, mesh::Mesh<2>& mesh,
                        post::Results& results);

} // namespace formflow::testing
