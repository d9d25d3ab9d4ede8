// SPDX-License-Identifier: MIT
// A two-rank program for tests/mpi/test_agreed_exit_code.cpp: what petsc::agreed_exit_code
// does when the ranks leave alike, and when one leaves with an error while the other
// waits in a collective call for it (the hang it exists to end). Not a formflow run:
// no input makes formflow's ranks disagree, so the disagreement is made here.
//   exit_code_probe alike     both ranks leave with exit code 2
//   exit_code_probe diverge   rank 1 leaves with 2, rank 0 waits in MPI_Barrier
#include "formflow/solvers/petsc/petsc_session.hpp"

#include <mpi.h>
#include <unistd.h>

#include <cstring>

int main(int argc, char** argv) {
  namespace petsc = formflow::solvers::petsc;
  if (argc != 2) return 64;
  petsc::ensure_initialized();
  constexpr double patience_seconds = 2.0;
  const int rank = petsc::rank();
  if (std::strcmp(argv[1], "alike") == 0)
    return petsc::agreed_exit_code(2, STDERR_FILENO, patience_seconds);
  if (std::strcmp(argv[1], "diverge") == 0) {
    if (rank == 1) return petsc::agreed_exit_code(2, STDERR_FILENO, patience_seconds);
    MPI_Barrier(PETSC_COMM_WORLD); // never met: rank 1 is in another collective call
    return petsc::agreed_exit_code(0, STDERR_FILENO, patience_seconds);
  }
  return 64;
}
