// SPDX-License-Identifier: MIT
// The exit code of a distributed run (petsc::agreed_exit_code, app/main.cpp): ranks that
// leave alike agree on it at once; a rank that leaves with an error while another waits
// for it in a collective call ends the run (MPI_Abort with its code, a message on its own
// stderr) after its patience instead of hanging. The ranks are made to disagree by a
// probe program (tests/mpi_probe/exit_code_probe.cpp, patience 2 s).
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <string>

namespace formflow {
namespace {

struct ProbeRun {
  int exit_code = -1;
  std::string err;
};

ProbeRun run_probe(const std::string& mode, const testing::ScratchDirectory& scratch) {
  // `timeout` bounds the test itself should the abort not come (a hang is the failure
  // this test is about: 60 s is 30 times the probe's patience).
  const std::string command =
      "OMPI_MCA_mpi_yield_when_idle=1 OMPI_MCA_btl_vader_single_copy_mechanism=none timeout 60 " +
      testing::quoted(FORMFLOW_MPIEXEC) + " -n 2 --oversubscribe --allow-run-as-root " +
      testing::quoted(FORMFLOW_EXIT_CODE_PROBE) + " " + mode + " > /dev/null 2> " +
      testing::quoted((scratch / "err.txt").string());
  const int status = std::system(command.c_str());
  ProbeRun run;
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  run.err = testing::read_text(scratch / "err.txt");
  return run;
}

const std::string abort_message = "did not follow within";

TEST(AgreedExitCode, RanksThatLeaveAlikeAgreeWithoutAnAbort) {
  testing::ScratchDirectory scratch("formflow-exit-probe");
  const ProbeRun run = run_probe("alike", scratch);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.find(abort_message), std::string::npos) << run.err;
}

TEST(AgreedExitCode, ARankLeftAloneWithAnErrorEndsTheRunInsteadOfHanging) {
  testing::ScratchDirectory scratch("formflow-exit-probe");
  const ProbeRun run = run_probe("diverge", scratch);
  // Its own code (not timeout's 124), and its message, once.
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const auto first = run.err.find(abort_message);
  ASSERT_NE(first, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(abort_message, first + 1), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("MPI rank 1 stopped with exit code 2"), std::string::npos) << run.err;
}

} // namespace
} // namespace formflow
