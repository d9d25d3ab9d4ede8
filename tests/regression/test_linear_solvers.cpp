// SPDX-License-Identifier: MIT
// solver.linear (issue 13): every back-end that can serve a loop gives its numbers,
// and one that cannot is refused before the solve, naming the key.
#include "formflow/app/simulation.hpp"
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace formflow {
namespace {

post::Results solve_by_linear_solver(std::vector<io::Override> edits) {
  edits.insert(edits.begin(), {{"mesh.size", "2.5"}, {"solver.tolerance", "1e-10"}});
  const post::Results results = app::simulate(io::load_case("", edits)).results;
  EXPECT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  return results;
}

/// Both back-ends solve the same discrete problem to δ = 1e-10: the reactions agree to
/// the gold table's path-independence tolerance (1e-9 relative).
class EveryLoop : public ::testing::TestWithParam<std::vector<io::Override>> {};

TEST_P(EveryLoop, UmfpackGivesCholmodsReaction) {
  std::vector<io::Override> cholmod = GetParam(), umfpack = GetParam();
  cholmod.emplace_back("solver.linear", "cholmod");
  umfpack.emplace_back("solver.linear", "umfpack");
  const post::Results by_cholmod = solve_by_linear_solver(cholmod),
                      by_umfpack = solve_by_linear_solver(umfpack);
  EXPECT_NEAR(by_umfpack.pressure.ram_reaction, by_cholmod.pressure.ram_reaction,
              1e-9 * std::abs(by_cholmod.pressure.ram_reaction));
  EXPECT_EQ(by_umfpack.method, by_cholmod.method);
}

INSTANTIATE_TEST_SUITE_P(
    Loops, EveryLoop,
    ::testing::Values(std::vector<io::Override>{{"friction.mu", "0.1"}}, // Newton
                      std::vector<io::Override>{{"solver.method", "secant"}},
                      std::vector<io::Override>{{"formulation.type", "mixed"}, {"penalty.d", "0"}},
                      std::vector<io::Override>{{"friction.mu", "0.1"},
                                                {"friction.regularization", "none"}}));

TEST(LinearSolverChoice, TaylorHoodTakesAnLuUnlessCholeskyIsAskedFor) {
  const std::vector<io::Override> taylor_hood = {{"formulation.type", "mixed"},
                                                 {"formulation.pressure", "Q1"}};
  const post::Results by_default = solve_by_linear_solver(taylor_hood);
  EXPECT_EQ(by_default.method, "saddle point (umfpack) around secant");
  std::vector<io::Override> cholesky = taylor_hood;
  cholesky.emplace_back("solver.linear", "cholmod");
  try {
    io::load_case("", cholesky);
    FAIL() << "cholmod cannot factorise the indefinite saddle point";
  } catch (const InputError& error) {
    EXPECT_EQ(error.key, "solver.linear");
    EXPECT_NE(std::string(error.what()).find("umfpack"), std::string::npos) << error.what();
  }
}

} // namespace
} // namespace formflow
