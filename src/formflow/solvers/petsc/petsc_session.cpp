// SPDX-License-Identifier: MIT
// PETSc initialisation, the command line's options and the per-case options scope.
#include "formflow/solvers/petsc/petsc_session.hpp"

#include "formflow/core/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdio.h> // dprintf (POSIX): a message on a descriptor kept from before freopen

#include <chrono>
#include <memory>
#include <thread>

namespace formflow::solvers::petsc {

namespace {

std::vector<PetscOption>& stored_command_line() {
  static std::vector<PetscOption> options;
  return options;
}

std::string joined(const std::vector<PetscOption>& options) {
  std::string text;
  for (const PetscOption& option : options) text += option.name + " " + option.value + " ";
  return text;
}

/// The program's Session: PETSc stays initialised until exit, when this finalises it.
std::unique_ptr<Session>& fallback_session() {
  static std::unique_ptr<Session> session;
  return session;
}

/// An option a KSP, PC or Mat reads while a solver is set up (the rest, such as
/// -log_view, PETSc reads at initialisation or finalisation).
bool is_solve_option(const std::string& name) {
  for (const char* family : {"-ksp_", "-pc_", "-mat_", "-fieldsplit_", "-mg_", "-sub_"})
    if (name.rfind(family, 0) == 0) return true;
  return false;
}

} // namespace

void set_command_line(const std::vector<std::string>& command_line) {
  std::string text;
  for (const std::string& argument : command_line) text += argument + " ";
  stored_command_line() = parse_petsc_options(text);
}

Session::Session() {
  PetscBool initialised = PETSC_FALSE;
  PetscInitialized(&initialised);
  if (initialised) return;
  // No argc/argv: PETSc would read every argument (the case path, --set ...) as an
  // option. The command line's options are inserted per solver (OptionsScope), after
  // the case's, so they win. PETSC_OPTIONS in the environment still applies.
  // PETSc prints nothing itself: its errors come back as return codes (ErrorCapture).
  // Its signal handlers stay out: SIGINT/SIGTERM are formflow's (app/stop_signals.hpp).
  PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
  // Before initialisation, so that -log_view, -info and -malloc_* take effect.
  PetscOptionsInsertString(nullptr, joined(command_line_options()).c_str());
  if (PetscInitializeNoArguments() != 0)
    throw InternalError("PetscInitialize failed (is MPI usable here?)");
  initialised_here_ = true;
}

Session::~Session() {
  if (initialised_here_) PetscFinalize();
}

void ensure_initialized() {
  PetscBool initialised = PETSC_FALSE;
  PetscInitialized(&initialised);
  if (!initialised) fallback_session() = std::make_unique<Session>();
}

const std::vector<PetscOption>& command_line_options() {
  return stored_command_line();
}

int n_ranks() {
  ensure_initialized();
  PetscMPIInt size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return size;
}

namespace {
bool& distributed_flag() {
  static bool distributed = false;
  return distributed;
}
} // namespace

void set_distributed_systems(bool distributed) {
  distributed_flag() = distributed;
}

bool distributed_systems() {
  return distributed_flag() && n_ranks() > 1;
}

int rank() {
  ensure_initialized();
  PetscMPIInt rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  return rank;
}

void sum_over_ranks(std::span<double> values) {
  ensure_initialized();
  // Summed on rank 0 and sent from there, not MPI_Allreduce: MPI promises each rank a
  // sum, not the same rounding of it on every rank, and a distributed run's ranks take
  // their decisions (line search, stop rule) from these sums: a last-bit difference
  // would send them down different branches, each waiting for the others.
  const auto count = static_cast<int>(values.size());
  PetscMPIInt rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0)
    MPI_Reduce(MPI_IN_PLACE, values.data(), count, MPI_DOUBLE, MPI_SUM, 0, PETSC_COMM_WORLD);
  else
    MPI_Reduce(values.data(), nullptr, count, MPI_DOUBLE, MPI_SUM, 0, PETSC_COMM_WORLD);
  MPI_Bcast(values.data(), count, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
}

int max_over_ranks(int value) {
  ensure_initialized();
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  return value;
}

int agreed_exit_code(int code, int report_fd, double patience_seconds) {
  if (code != 1 && code != 2) return max_over_ranks(code);
  ensure_initialized();
  int agreed = code;
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Iallreduce(&code, &agreed, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD, &request);
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return agreed;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        patience_seconds)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (report_fd >= 0)
    dprintf(report_fd,
            "error: MPI rank %d stopped with exit code %d, and the other ranks did not follow "
            "within %.0f s (they took another decision and wait for this rank): the run is "
            "aborted. This is a bug: please report it with the command line.\n",
            rank(), code, patience_seconds);
  MPI_Abort(PETSC_COMM_WORLD, code);
  return code;
}

OptionsScope::OptionsScope(const std::string& case_options)
    : case_options_(parse_petsc_options(case_options)) {
  ensure_initialized();
  PetscOptionsInsertString(nullptr, joined(case_options_).c_str());
  PetscOptionsInsertString(nullptr, joined(command_line_options()).c_str());
}

OptionsScope::~OptionsScope() {
  for (const PetscOption& option : case_options_)
    PetscOptionsClearValue(nullptr, option.name.c_str());
  // A command-line option of the same name was cleared with the case's: put it back.
  PetscOptionsInsertString(nullptr, joined(command_line_options()).c_str());
}

OptionsScope::Unused OptionsScope::unused(bool across_ranks) const {
  const std::vector<PetscOption>& command_line = command_line_options();
  // Read flags of the case's options, then the command line's.
  std::vector<int> read;
  for (const auto* options : {&case_options_, &command_line})
    for (const PetscOption& option : *options) {
      PetscBool used = PETSC_FALSE;
      // The database keeps names without their '-'.
      PetscOptionsUsed(nullptr, option.name.c_str() + 1, &used);
      read.push_back(used ? 1 : 0);
    }
  if (across_ranks && !read.empty())
    MPI_Allreduce(MPI_IN_PLACE, read.data(), static_cast<int>(read.size()), MPI_INT, MPI_LOR,
                  PETSC_COMM_WORLD);
  Unused names;
  std::size_t k = 0;
  for (auto [options, unused] : {std::pair{&case_options_, &names.from_case},
                                 std::pair{&command_line, &names.from_command_line}})
    for (const PetscOption& option : *options)
      // -log_view and the like are read at PetscFinalize, not by a solve.
      if (read[k++] == 0 && is_solve_option(option.name)) unused->push_back(option.name);
  return names;
}

void OptionsScope::refuse_unused(const char* case_key, bool across_ranks) const {
  const Unused names = unused(across_ranks);
  const auto hint = [](const std::vector<std::string>& options) -> std::string {
    // The cells are split when the mesh is distributed, before a case's options are in
    // the database: only the command line's reach the partitioner.
    if (options.front().rfind("-mat_partitioning_", 0) == 0)
      return "the partitioner reads its options from the command line only (mpirun -n N "
             "formflow run CASE -mat_partitioning_type ptscotch)";
    return "check the spelling (-ksp_type, -pc_type, -pc_factor_mat_solver_type, ...) and that "
           "the option belongs to the solver and preconditioner in use";
  };
  const auto text = [](const std::vector<std::string>& options) {
    return fmt::format("{} {} read by no PETSc object of this solve", fmt::join(options, " "),
                       options.size() == 1 ? "was" : "were");
  };
  if (!names.from_command_line.empty())
    throw InputError("command line", 0, names.from_command_line.front(),
                     text(names.from_command_line), hint(names.from_command_line));
  if (!names.from_case.empty())
    throw InputError("", 0, case_key, text(names.from_case), hint(names.from_case));
}

ErrorCapture::ErrorCapture() {
  PetscPushErrorHandler(&ErrorCapture::handler, this);
}

ErrorCapture::~ErrorCapture() {
  PetscPopErrorHandler();
}

PetscErrorCode ErrorCapture::handler(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                                     PetscErrorType type, const char* message, void* self) {
  auto& capture = *static_cast<ErrorCapture*>(self);
  if (type == PETSC_ERROR_INITIAL && capture.message_.empty() && message)
    capture.message_ = message;
  return code;
}

} // namespace formflow::solvers::petsc
