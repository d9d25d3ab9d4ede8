// SPDX-License-Identifier: MIT
// Entry point of the formflow binary.
#include "formflow/app/cli.hpp"
#include "formflow/app/distributed_run.hpp"
#include "formflow/app/stop_signals.hpp"

#if FORMFLOW_WITH_PETSC
#include "formflow/solvers/petsc/ghost_exchange.hpp"
#include "formflow/solvers/petsc/graph_partition.hpp"
#include "formflow/solvers/petsc/petsc_session.hpp"

#include <unistd.h> // dup

#include <span>
#include <string>
#include <vector>
#endif

#include <cstdio>
#include <cstdlib>
#include <initializer_list>

namespace {

/// The first of the launcher's variables `names` that is set (OpenMPI's, then PMI's),
/// or `fallback` when no launcher started this process.
int launcher_value(std::initializer_list<const char*> names, int fallback) {
  for (const char* name : names)
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return fallback;
}

} // namespace

int main(int argc, char** argv) {
  formflow::app::install_stop_handlers();
#if FORMFLOW_WITH_PETSC
  // PETSc's own options (-ksp_type cg, -pc_type gamg, ...) go to its options
  // database, over the case's solver.petsc_options; the rest to CLI11.
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  formflow::solvers::SplitCommandLine split = formflow::solvers::split_petsc_arguments(arguments);
  formflow::solvers::petsc::set_command_line(split.petsc);
  std::vector<char*> rest{argv[0]};
  for (std::string& argument : split.rest) rest.push_back(argument.data());
  rest.push_back(nullptr);
  // Started by mpirun on N > 1 ranks (issue 20, docs/petsc.md): MPI now (a serial run
  // starts it only at its first PETSc solve, and a CHOLMOD run never), each rank its
  // own part of the cells (PT-Scotch); only rank 0 prints and writes, and every rank exits
  // with the largest code of all (a rank that failed makes the run fail).
  if (launcher_value({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}, 1) > 1) {
    namespace petsc = formflow::solvers::petsc;
    formflow::assembly::Distribution distribution;
    distribution.size = petsc::n_ranks();
    distribution.rank = petsc::rank();
    distribution.sum_over_ranks = [](std::span<formflow::Real> values) {
      petsc::sum_over_ranks(values);
    };
    distribution.partition_cells = petsc::partition_graph;         // PT-Scotch, broadcast by rank 0
    distribution.make_ghost_exchange = petsc::make_ghost_exchange; // VecCreateGhost
    // Every rank's own stderr, for the one message a rank must give itself (a run whose
    // ranks went apart: petsc::agreed_exit_code).
    const int own_stderr = ::dup(STDERR_FILENO);
    if (distribution.rank != 0) {
      // The same monitor lines and messages as rank 0's: said once, by rank 0.
      static_cast<void>(std::freopen("/dev/null", "w", stdout));
      static_cast<void>(std::freopen("/dev/null", "w", stderr));
    }
    formflow::app::set_distribution(std::move(distribution));
    petsc::set_distributed_systems(true); // the PETSc back-end sums the ranks' shares
    const int code = formflow::app::run_cli(static_cast<int>(rest.size()) - 1, rest.data());
    // A rank's error that the others did not share must not leave them waiting forever
    // in a collective call: a minute is ample for ranks that met it at the same point.
    constexpr double patience_seconds = 60.0;
    return petsc::agreed_exit_code(code, own_stderr, patience_seconds);
  }
  return formflow::app::run_cli(static_cast<int>(rest.size()) - 1, rest.data());
#else
  // Without MPI each rank would run the whole case into the same directory: refuse,
  // once (rank 0 says why), before anything is read or written.
  if (const int ranks = launcher_value({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}, 1); ranks > 1) {
    if (launcher_value({"OMPI_COMM_WORLD_RANK", "PMI_RANK"}, 0) == 0)
      std::fprintf(stderr,
                   "error: started by an MPI launcher on %d ranks, but this formflow was built "
                   "without PETSc/MPI (FORMFLOW_WITH_PETSC=OFF)\n"
                   "  hint: run it as one process, or build with -DFORMFLOW_WITH_PETSC=ON "
                   "(./run and ./test do)\n",
                   ranks);
    return 2;
  }
  return formflow::app::run_cli(argc, argv);
#endif
}
