// SPDX-License-Identifier: MIT
// `formflow --version` names the BLAS the process found and the kernels OpenBLAS chose
// (solvers/blas_runtime.hpp): read from the library at run time, so an environment that
// forces the kernels shows in the report.
#include "formflow/solvers/blas_runtime.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace {

using formflow::testing::CliResult;
using formflow::testing::has_text;
using formflow::testing::ScratchDirectory;

TEST(BlasReport, VersionNamesTheKernelsTheEnvironmentForces) {
  if (formflow::solvers::blas_runtime().library == "not OpenBLAS")
    GTEST_SKIP() << "this process's BLAS is not OpenBLAS: it reports no kernels";
  ScratchDirectory scratch("formflow-blas-report");
  // Prescott (SSE3) is the one kernel family every x86-64 CPU runs, so OpenBLAS honours
  // the request everywhere; the child inherits the variable.
  ASSERT_EQ(::setenv("OPENBLAS_CORETYPE", "Prescott", 1), 0);
  const CliResult forced = formflow::testing::run_cli("--version", scratch.path());
  ::unsetenv("OPENBLAS_CORETYPE");
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_TRUE(has_text(forced.out, "BLAS: OpenBLAS"));
  EXPECT_TRUE(has_text(forced.out, "kernels Prescott"));
}

} // namespace
