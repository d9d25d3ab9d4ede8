// SPDX-License-Identifier: MIT
// OpenBLAS's thread count is capped around work its threads do not speed up, and only
// where the user did not choose it (solvers/blas_thread_limit.hpp).
#include "formflow/solvers/blas_runtime.hpp"
#include "formflow/solvers/blas_thread_limit.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace formflow::testing {
namespace {

int openblas_threads() {
  return solvers::blas_runtime().threads.value_or(0);
}

bool user_chose_threads() {
  return std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS") ||
         std::getenv("OMP_NUM_THREADS");
}

/// This test binary again, only `filter`, with the thread-count variables removed from
/// its environment (OpenBLAS reads them when it is loaded: only a new process sees
/// their absence). Returns its exit status.
int rerun_without_thread_variables(const std::string& filter) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::unsetenv("OPENBLAS_NUM_THREADS");
    ::unsetenv("GOTO_NUM_THREADS");
    ::unsetenv("OMP_NUM_THREADS");
    const std::string filter_flag = "--gtest_filter=" + filter;
    std::vector<char*> argv{const_cast<char*>("/proc/self/exe"),
                            const_cast<char*>(filter_flag.c_str()), nullptr};
    ::execv("/proc/self/exe", argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(BlasThreadLimit, CapsOnlyWhereTheUserDidNotChoose) {
  if (solvers::blas_runtime().library == "not OpenBLAS")
    GTEST_SKIP() << "the process's BLAS is not OpenBLAS";
  const int before = openblas_threads();
  if (user_chose_threads()) {
    {
      const solvers::BlasThreadLimit limit(1);
      EXPECT_EQ(openblas_threads(), before) << "the user's count was changed";
    }
    // The rest of the test needs a process that OpenBLAS started with its own count.
    EXPECT_EQ(rerun_without_thread_variables("BlasThreadLimit.CapsOnlyWhereTheUserDidNotChoose"),
              0);
    return;
  }
  if (before < 2) GTEST_SKIP() << "OpenBLAS runs on one thread here: nothing to cap";
  {
    const solvers::BlasThreadLimit limit(1);
    EXPECT_EQ(openblas_threads(), 1);
    {
      const solvers::BlasThreadLimit none(0); // 0: left as it is
      EXPECT_EQ(openblas_threads(), 1);
    }
    EXPECT_EQ(openblas_threads(), 1);
  }
  EXPECT_EQ(openblas_threads(), before) << "the count was not restored";
}

} // namespace
} // namespace formflow::testing
