// SPDX-License-Identifier: MIT
// A reproducible vector of uniform entries, for right-hand sides and trial velocities.
#pragma once

#include "formflow/core/types.hpp"

#include <random>

namespace formflow::testing {

/// Uniform entries in [−1, 1] from a fixed seed.
inline VectorX random_vector(Index n, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX v(n);
  for (Index k = 0; k < n; ++k) v[k] = uniform(generator);
  return v;
}

} // namespace formflow::testing
