// SPDX-License-Identifier: MIT
// A sparse SPD test matrix with a known structure, for the linear-solver tests.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/core/types.hpp"

#include <Eigen/SparseCore>

#include <vector>

namespace formflow::testing {

/// Lower triangle of the 5-point Laplacian on an m×m grid (SPD, Dirichlet): n = m², its
/// condition ≈ (2m/π)², its nested-dissection separators m long.
inline assembly::SparseMatrix grid_laplacian_lower(int m) {
  std::vector<Eigen::Triplet<Real, Index>> entries;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const Index k = j * m + i;
      entries.emplace_back(k, k, 4.0);
      if (i > 0) entries.emplace_back(k, k - 1, -1.0);
      if (j > 0) entries.emplace_back(k, k - m, -1.0);
    }
  assembly::SparseMatrix lower(m * m, m * m);
  lower.setFromTriplets(entries.begin(), entries.end());
  lower.makeCompressed();
  return lower;
}

} // namespace formflow::testing
