// SPDX-License-Identifier: MIT
// PETSc's lifetime (initialise once, finalise once) and the options each solve
// reads: solver.petsc_options, then the command line's PETSc options over them.
#pragma once

#include "formflow/solvers/petsc_option_text.hpp"

#include <petscsys.h>

#include <span>
#include <string>
#include <vector>

namespace formflow::solvers::petsc {

/// Keeps `command_line` (PETSc's own arguments, split off the program's by
/// split_petsc_arguments in app/main.cpp) as the options that override every case's
/// solver.petsc_options. Call before the first solve.
void set_command_line(const std::vector<std::string>& command_line);

/// Initialises PETSc (and MPI, when nobody has) for the lifetime of the object. Made
/// on first use by ensure_initialized(), so a run with another back-end never starts
/// MPI, and kept until the program exits.
class Session {
public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

private:
  bool initialised_here_ = false;
};

/// PETSc is initialised: by the app's Session, or else by one made now and kept until
/// the program exits.
void ensure_initialized();

/// The PETSc options given on the command line ("" if none).
const std::vector<PetscOption>& command_line_options();

/// The MPI ranks of PETSC_COMM_WORLD.
int n_ranks();
/// Whether the linear systems are the ranks' shares of one distributed system (set by
/// app/main.cpp for a distributed run). False by default: a program started by mpirun
/// without saying so (a test binary, Python) solves on every rank alone, serially.
void set_distributed_systems(bool distributed);
bool distributed_systems();
/// This process's rank in PETSC_COMM_WORLD.
int rank();
/// Every entry of `values` replaced by its sum over the ranks (collective; the same
/// bits on every rank: rank 0 sums and sends).
void sum_over_ranks(std::span<double> values);
/// The largest of `value` over the ranks (collective): the exit code they agree on.
int max_over_ranks(int value);
/// The run's exit code: max_over_ranks(`code`), except that a rank leaving with an error
/// (1 or 2: a refusal or a failure every rank should have met at the same point) waits
/// for the others at most `patience_seconds`. If they do not come, a decision differed
/// between the ranks and they wait in a collective call for this one: it says so on
/// `report_fd` (the rank's stderr from before rank 0 took the talking over) and ends
/// the run with MPI_Abort(`code`) instead of leaving it hanging. Codes 0, 3 and the
/// signals' wait as long as it takes (rank 0 may still be writing results).
int agreed_exit_code(int code, int report_fd, double patience_seconds);

/// solver.petsc_options in the options database while a solver lives: inserted,
/// then the command line's options inserted again over them (the command line wins);
/// removed again when the scope ends, so the next case starts clean.
class OptionsScope {
public:
  explicit OptionsScope(const std::string& case_options);
  ~OptionsScope();
  OptionsScope(const OptionsScope&) = delete;
  OptionsScope& operator=(const OptionsScope&) = delete;

  /// The options that no PETSc object has read (misspelt, or for a solver not in
  /// use, e.g. "-ksp_tyep"): the case's, and the command line's.
  struct Unused {
    std::vector<std::string> from_case, from_command_line;
  };
  /// `across_ranks` (a distributed solve; collective): an option counts as read if any
  /// rank read it, so every rank finds the same ones unused (rank 0 alone reads the
  /// partitioner's, and a rank that refused alone would leave the others waiting).
  Unused unused(bool across_ranks) const;
  /// Throws InputError for the first unused option: the command line's named as itself,
  /// the case's blamed on `case_key` (solver.petsc_options). Returns if none is unused.
  void refuse_unused(const char* case_key, bool across_ranks) const;

private:
  std::vector<PetscOption> case_options_;
};

/// Runs PETSc calls with their error messages captured instead of printed: the
/// first message of a failed call is kept (PETSc's own words, e.g. "Unknown type.
/// Check for miss-spelling ...: foo") for the caller to report.
class ErrorCapture {
public:
  ErrorCapture();
  ~ErrorCapture();
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;
  /// The first error message since construction, or "".
  const std::string& message() const { return message_; }

private:
  static PetscErrorCode handler(MPI_Comm, int, const char*, const char*, PetscErrorCode,
                                PetscErrorType, const char* message, void* self);
  std::string message_;
};

} // namespace formflow::solvers::petsc
