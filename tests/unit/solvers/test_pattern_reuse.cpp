// SPDX-License-Identifier: MIT
// reuse_analysis: the symbolic analysis is done again only for a new pattern.
#include "formflow/solvers/pattern_reuse.hpp"

#include <gtest/gtest.h>

namespace formflow::solvers {
namespace {

/// Counts the calls the wrapper lets through; solves with the diagonal.
class CountingSolver final : public LinearSolver {
public:
  explicit CountingSolver(int& analyses) : analyses_(analyses) {}
  bool analyze(const assembly::SparseMatrix&) override { return ++analyses_, true; }
  bool factorize(const assembly::SparseMatrix& matrix) override {
    diagonal_ = matrix.diagonal();
    return true;
  }
  bool solve(const VectorX& rhs, VectorX& solution) override {
    solution = rhs.cwiseQuotient(diagonal_);
    return true;
  }
  std::string name() const override { return "counting"; }

private:
  int& analyses_;
  VectorX diagonal_;
};

assembly::SparseMatrix matrix(int n, bool with_corner, Real scale) {
  std::vector<Eigen::Triplet<Real, Index>> entries;
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, scale * (i + 1));
  if (with_corner) entries.emplace_back(n - 1, 0, 0.0); // an explicit zero: pattern, not value
  assembly::SparseMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

TEST(PatternReuse, AnalysesOncePerPatternAndFactorisesEveryTime) {
  int analyses = 0;
  const auto solver = reuse_analysis(std::make_unique<CountingSolver>(analyses));
  VectorX x;
  const VectorX b = VectorX::Ones(4);
  for (const Real scale : {1.0, 2.0, 4.0}) { // new values, same pattern
    const auto a = matrix(4, true, scale);
    ASSERT_TRUE(solver->analyze(a));
    ASSERT_TRUE(solver->factorize(a));
    ASSERT_TRUE(solver->solve(b, x));
    EXPECT_DOUBLE_EQ(x[3], 1.0 / (4 * scale)); // the values of this matrix, not the first
  }
  EXPECT_EQ(analyses, 1);
  EXPECT_TRUE(solver->analyze(matrix(4, false, 1.0))); // one entry fewer
  EXPECT_EQ(analyses, 2);
  EXPECT_TRUE(solver->analyze(matrix(5, false, 1.0))); // another size
  EXPECT_EQ(analyses, 3);
  EXPECT_TRUE(solver->analyze(matrix(5, false, 3.0)));
  EXPECT_EQ(analyses, 3);
  EXPECT_EQ(solver->name(), "counting");
}

} // namespace
} // namespace formflow::solvers
