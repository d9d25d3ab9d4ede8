// SPDX-License-Identifier: MIT
// Entry point of the formflow binary.
#include "formflow/app/cli.hpp"
#include "formflow/app/stop_signals.hpp"

#if FORMFLOW_WITH_PETSC
#include "formflow/solvers/petsc/petsc_session.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <initializer_list>
#include <string>
#include <vector>

namespace {

/// The first of the launcher's variables `names` that is set (OpenMPI's, then PMI's),
/// or `fallback` when no launcher started this process.
int launcher_value(std::initializer_list<const char*> names, int fallback) {
  for (const char* name : names)
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return fallback;
}

} // namespace
#endif

int main(int argc, char** argv) {
  formflow::app::install_stop_handlers();
#if FORMFLOW_WITH_PETSC
  // Distributed assembly is not there yet (issue 20, docs/petsc.md): N ranks would
  // each solve the whole case and write the same files. Refused, said once.
  const int ranks = launcher_value({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}, 1);
  if (ranks > 1) {
    if (launcher_value({"OMPI_COMM_WORLD_RANK", "PMI_RANK"}, 0) == 0)
      fmt::print(stderr,
                 "error: formflow was started on {} MPI ranks; distributed runs are not "
                 "implemented yet (docs/petsc.md): run it as one process\n",
                 ranks);
    return 2;
  }
  // PETSc's own options (-ksp_type cg, -pc_type gamg, ...) go to its options
  // database, over the case's solver.petsc_options; the rest to CLI11.
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  formflow::solvers::SplitCommandLine split = formflow::solvers::split_petsc_arguments(arguments);
  formflow::solvers::petsc::set_command_line(split.petsc);
  std::vector<char*> rest{argv[0]};
  for (std::string& argument : split.rest) rest.push_back(argument.data());
  rest.push_back(nullptr);
  return formflow::app::run_cli(static_cast<int>(rest.size()) - 1, rest.data());
#else
  return formflow::app::run_cli(argc, argv);
#endif
}
