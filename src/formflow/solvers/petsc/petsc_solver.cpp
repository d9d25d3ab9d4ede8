// SPDX-License-Identifier: MIT
// PETSc KSP/PC behind the LinearSolver interface: direct MUMPS by default, any
// Krylov method and preconditioner through the options database.
#include "formflow/solvers/petsc/petsc_solver.hpp"

#include "formflow/core/error.hpp"
#include "formflow/solvers/petsc/distributed_saddle_point.hpp"
#include "formflow/solvers/petsc/distributed_system.hpp"
#include "formflow/solvers/petsc/krylov_start.hpp"
#include "formflow/solvers/petsc/mumps_workspace.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"
#include "formflow/solvers/petsc/petsc_saddle_point.hpp"
#include "formflow/solvers/petsc/petsc_session.hpp"
#include "formflow/solvers/petsc/sequential_system.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace formflow::solvers {

namespace {

constexpr const char* options_key = "solver.petsc_options";
/// Four doublings take MUMPS' work space margin from 20 % to 320 %.
constexpr int max_workspace_retries = 4;

class PetscSolver final : public LinearSolver {
public:
  PetscSolver(MatrixStorage storage, const std::string& options)
      : storage_(storage), options_(options), distributed_(petsc::distributed_systems()) {}
  ~PetscSolver() override {
    if (ksp_) KSPDestroy(&ksp_);
    for (IS& field : fields_)
      if (field) ISDestroy(&field);
    if (matrix_) MatDestroy(&matrix_);
    if (schur_matrix_) MatDestroy(&schur_matrix_);
    if (rhs_) VecDestroy(&rhs_);
    if (solution_) VecDestroy(&solution_);
  }
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;

  bool analyze(const assembly::SparseMatrix& matrix) override {
    copy(matrix);
    return agreed(matrix_ != nullptr);
  }

  bool factorize(const assembly::SparseMatrix& matrix) override {
    copy(matrix);
    if (!agreed(matrix_ != nullptr)) return false;
    petsc::ErrorCapture capture;
    if (!ksp_ && !make_ksp(capture)) return false;
    // MUMPS short of work space (the paper case at h = 0.5 on 3 ranks) factorises again
    // with more room, in a new factor (mumps_workspace.hpp), a few times.
    std::optional<petsc::ScopedPetscOption> more_room;
    for (int retry = 0;; ++retry) {
      // The KSP sees new values on the same pattern: the factorisation (or the AMG
      // hierarchy) is recomputed at KSPSetUp.
      if (KSPSetOperators(ksp_, matrix_, matrix_) != 0) return false;
      const PetscErrorCode setup = KSPSetUp(ksp_);
      if (setup != 0) {
        // A type that does not exist is the user's; anything else is numerical
        // (a zero pivot, a failed factorisation): a stop reason, not an error.
        if (setup == PETSC_ERR_ARG_UNKNOWN_TYPE || setup == PETSC_ERR_ARG_WRONG)
          refuse(capture.message(), "give a type PETSc 3.18 has (see -help output of the "
                                    "option's family) or leave the key unset for direct MUMPS");
        return false;
      }
      const std::optional<PetscInt> relaxation =
          retry < max_workspace_retries ? petsc::enlarged_mumps_relaxation(ksp_) : std::nullopt;
      if (!relaxation) break;
      // The factor takes MUMPS' controls from the options database at its analysis.
      more_room.reset();
      more_room.emplace("-" + options_prefix_ + "mat_mumps_icntl_14", std::to_string(*relaxation));
      KSPDestroy(&ksp_);
      if (!make_ksp(capture)) return false;
    }
    // The splits' own set-up (the velocity AMG hierarchy) here, not at the first
    // application inside the solve: on the saddle point's nest the outer set-up leaves
    // it to them, and the phases' times should say where it went.
    PC outer = nullptr;
    KSPGetPC(ksp_, &outer);
    const PetscErrorCode splits = petsc::set_up_splits(outer);
    if (!checked_unused_) {
      checked_unused_ = true;
      if (splits == PETSC_ERR_ARG_UNKNOWN_TYPE || splits == PETSC_ERR_ARG_WRONG)
        refuse(capture.message(), "give a type PETSc 3.18 has for that split");
      if (splits != 0) return false;
      krylov_start_.inexact_allowed(ksp_); // reads -formflow_inexact_steps before the check
      // What nothing read by now; a helper's solver (set_options_prefix) leaves it to the
      // run's own one, which reads the options meant for it later.
      if (options_prefix_.empty()) options_scope_.refuse_unused(options_key, distributed_);
    }
    if (splits != 0) return false;
    PCFailedReason failed = PC_NOERROR;
    PC preconditioner = nullptr;
    KSPGetPC(ksp_, &preconditioner);
    PCGetFailedReason(preconditioner, &failed);
    return agreed(failed == PC_NOERROR); // a PC's failure is its rank's own
  }

  bool solve(const VectorX& rhs, VectorX& solution) override {
    return solve_loaded(rhs, solution, false);
  }

  bool solve_whole(const VectorX& rhs, VectorX& solution) override {
    return solve_loaded(rhs, solution, true);
  }

  /// solve() (`whole` false: a distributed rhs is the rank's share) or solve_whole().
  bool solve_loaded(const VectorX& rhs, VectorX& solution, bool whole) {
    if (!ksp_) return false;
    petsc::ErrorCapture capture;
    const auto n = static_cast<PetscInt>(rhs.size());
    if (distributed_ && whole) {
      distributed_system_.write_owned_rows(rhs_, in_solved_unknowns(rhs));
    } else if (distributed_) {
      // The rank's rhs is its own cells' loads. In the frames: Qᵀ of a share is the
      // share of Qᵀ b (Q is node-local).
      distributed_system_.sum_shares(rhs_, in_solved_unknowns(rhs));
    } else {
      write(rhs_, in_solved_unknowns(rhs)); // Qᵀ b: the system is Qᵀ K Q y = Qᵀ b
    }
    // A guess (set_initial_guess), also in the unknowns PETSc solves for. Not for a
    // direct solve: PETSc's preonly refuses a nonzero initial guess.
    std::optional<VectorX> guess = krylov_start_.take_guess(rhs.size());
    // Distributed: the guess is ghosted like the velocity it comes from (every rank holds
    // at least the rows it owns), and each rank writes its own rows.
    const bool guessed = guess && petsc::is_iterative(ksp_);
    if (guessed && distributed_)
      distributed_system_.write_owned_rows(solution_, in_solved_unknowns(std::move(*guess)));
    else if (guessed)
      write(solution_, in_solved_unknowns(std::move(*guess)));
    KSPSetInitialGuessNonzero(ksp_, guessed ? PETSC_TRUE : PETSC_FALSE);
    krylov_start_.apply_tolerance(ksp_, matrix_, rhs_, solution_, guessed);
    const bool solved = KSPSolve(ksp_, rhs_, solution_) == 0;
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt iterations = 0;
    if (solved) {
      KSPGetConvergedReason(ksp_, &reason);
      KSPGetIterationNumber(ksp_, &iterations);
    }
    iterations_ += iterations;
    // All ranks reach the solution's scatter below, or none.
    if (!agreed(solved && reason >= 0)) return false;
    const PetscScalar* result = nullptr;
    solution.resize(n);
    if (distributed_) {
      // Finite as a whole, alike on every rank: a NaN or an overflow makes the 2-norm's
      // sum over the ranks non-finite in any order (a max could drop a NaN).
      PetscReal size = 0;
      VecNorm(solution_, NORM_2, &size);
      solution_finite_ = std::isfinite(size);
      VectorX solved = distributed_system_.ghosted(solution_); // laid out, if it is
      solution = layout_.empty() ? std::move(solved)
                                 : layout_.restrict(std::span<const Real>(
                                       solved.data(), static_cast<std::size_t>(solved.size())));
      assembly::from_frames(frames_, solution); // x = Q y
      return true;
    }
    VecGetArrayRead(solution_, &result);
    if (layout_.empty()) {
      std::copy(result, result + n, solution.data());
    } else {
      solution = layout_.restrict(
          std::span<const Real>(result, static_cast<std::size_t>(layout_.n_embedded())));
    }
    VecRestoreArrayRead(solution_, &result);
    assembly::from_frames(frames_, solution); // x = Q y
    return true;
  }

  std::string name() const override {
    if (!ksp_) return "petsc";
    KSPType ksp_type = nullptr;
    PCType pc_type = nullptr;
    PC preconditioner = nullptr;
    KSPGetType(ksp_, &ksp_type);
    KSPGetPC(ksp_, &preconditioner);
    PCGetType(preconditioner, &pc_type);
    return fmt::format("petsc-{}-{}", ksp_type ? ksp_type : "?", pc_type ? pc_type : "?");
  }

  long krylov_iterations() const override { return iterations_; }

  /// Distributed: whether every rank succeeded (collective). A rank that failed alone (a
  /// PC's failure is reported on its own rank) would otherwise leave the loop while the
  /// others wait for it in the next collective call.
  bool agreed(bool ok) const { return !distributed_ || petsc::max_over_ranks(ok ? 0 : 1) == 0; }

  bool finite(const VectorX& solution) const override {
    return distributed_ ? solution_finite_ : solution.allFinite();
  }

  void set_fields(Index n_first, std::vector<VectorX> near_null_space) override {
    n_first_ = n_first;
    near_null_space_ = std::move(near_null_space);
  }

  void set_schur_preconditioner(const assembly::SparseMatrix& matrix, Index cell_block) override {
    if (distributed_) {
      // The rank's share (its own cells' blocks), copied once the saddle point's rows
      // are numbered (copy).
      schur_block_ = cell_block;
      schur_share_ = matrix;
      schur_share_.makeCompressed();
      return;
    }
    petsc::ErrorCapture capture;
    schur_block_ = cell_block;
    petsc::copy_schur_matrix(matrix, cell_block, &schur_matrix_);
  }

  void set_local_frames(std::vector<assembly::LocalFrame> frames) override {
    frames_ = std::move(frames);
    frame_matrix_ = {};
  }

  void set_initial_guess(VectorX guess) override { krylov_start_.set_guess(std::move(guess)); }

  bool set_solve_tolerance(Real reduction) override {
    krylov_start_.ask_reduction(reduction);
    return reduction > 0 && krylov_start_.inexact_allowed(ksp_);
  }

  void set_options_prefix(const std::string& prefix) override { options_prefix_ = prefix; }

  void set_velocity_nodes(int components, std::vector<Index> dof_of_velocity) override {
    components_ = components;
    dof_of_velocity_ = std::move(dof_of_velocity);
  }

  bool take_saddle_point_blocks(const assembly::SparseMatrix& coupling,
                                const assembly::SparseMatrix& pressure_block) override {
    if (matrix_ || !nest_the_saddle_point()) return false;
    coupling_ = coupling;
    pressure_block_ = pressure_block;
    return true;
  }

private:
  /// x in the unknowns PETSc solves for: y = Qᵀ x (set_local_frames), laid out node by
  /// node (lay_out_nodes) where it is.
  VectorX in_solved_unknowns(VectorX x) const {
    assembly::to_frames(frames_, x);
    return layout_.empty() ? x : layout_.embed(x);
  }

  /// The velocity block's rigid-body modes (set_fields) in the unknowns PETSc solves
  /// for: y = Qᵀ x, laid out node by node where it is (zero on the prescribed
  /// components' slots, which are decoupled); n_first_solved() entries each.
  std::vector<VectorX> solved_modes() const {
    std::vector<VectorX> modes;
    for (const VectorX& mode : near_null_space_) {
      FF_ASSERT(mode.size() == n_first_, "one mode entry per velocity dof");
      VectorX padded = VectorX::Zero(layout_.empty() ? n_first_ : layout_.n_rows());
      padded.head(n_first_) = mode;
      modes.push_back(in_solved_unknowns(std::move(padded)).head(n_first_solved()));
    }
    return modes;
  }

  /// Copies `values` into the sequential vector `target`.
  static void write(Vec target, Eigen::Ref<const VectorX> values) {
    PetscScalar* entries = nullptr;
    VecGetArray(target, &entries);
    std::copy(values.data(), values.data() + values.size(), entries);
    VecRestoreArray(target, &entries);
  }

  /// The KSP with formflow's defaults, then the options database over them.
  bool make_ksp(petsc::ErrorCapture& capture) {
    if (KSPCreate(distributed_ ? PETSC_COMM_WORLD : PETSC_COMM_SELF, &ksp_) != 0) return false;
    if (!options_prefix_.empty()) KSPSetOptionsPrefix(ksp_, options_prefix_.c_str());
    PC preconditioner = nullptr;
    KSPGetPC(ksp_, &preconditioner);
    KSPSetType(ksp_, KSPPREONLY);
    PCSetType(preconditioner, storage_ == MatrixStorage::SymmetricLower ? PCCHOLESKY : PCLU);
    PCFactorSetMatSolverType(preconditioner, MATSOLVERMUMPS);
    // The nonlinear loops stop at δ ≥ 1e-15 relative change; an iterative solve
    // asked for by the options gets a relative residual well below the smallest
    // δ that makes sense for a run (1e-10), unless -ksp_rtol says otherwise.
    KSPSetTolerances(ksp_, 1e-10, PETSC_DEFAULT, PETSC_DEFAULT, 10000);
    // A saddle point with a block-diagonal pressure preconditioner (a discontinuous
    // pressure): the iterative block preconditioner by default (issue 20).
    if (n_first_ > 0 && schur_block_ > 0 && schur_matrix_)
      petsc::set_saddle_point_defaults(ksp_, defaults_);
    const PetscErrorCode configured = KSPSetFromOptions(ksp_);
    if (configured != 0)
      refuse(capture.message(), "give a value PETSc 3.18 accepts for that option, or "
                                "leave the key unset for direct MUMPS");
    PetscBool fieldsplit = PETSC_FALSE;
    PetscObjectTypeCompare(reinterpret_cast<PetscObject>(preconditioner), PCFIELDSPLIT,
                           &fieldsplit);
    if (fieldsplit) return split_fields(preconditioner);
    return true;
  }

  /// PCFIELDSPLIT's two splits, "u" (velocity) and "p" (pressure), from set_fields;
  /// the rigid-body modes go with "u" as its near-null space (fieldsplit hands a
  /// "nearnullspace" composed on a split's IS to that split's matrix, which GAMG reads).
  bool split_fields(PC preconditioner) {
    PetscInt n = 0;
    MatGetSize(matrix_, &n, nullptr);
    if (n_first_ <= 0 || n_first_ >= (layout_.empty() ? n : layout_.n_rows()))
      refuse("-pc_type fieldsplit needs a saddle point (velocity and pressure fields), and "
             "this loop's systems have the velocity only",
             "use fieldsplit with formulation.type = \"mixed\" and formulation.pressure = "
             "\"Q1\"; for the velocity systems try -pc_type gamg or the default");
    if (distributed_) return split_distributed_fields(preconditioner);
    const auto n_first =
        static_cast<PetscInt>(layout_.empty() ? n_first_ : layout_.n_velocity_embedded());
    ISCreateStride(PETSC_COMM_SELF, n_first, 0, 1, &fields_[0]);
    ISCreateStride(PETSC_COMM_SELF, n - n_first, n_first, 1, &fields_[1]);
    // Laid out node by node: the split's matrix gets the block size (MatCreateSubMatrix
    // takes it from the IS), which BoomerAMG's nodal options and GAMG read.
    if (!layout_.empty()) ISSetBlockSize(fields_[0], layout_.components());
    if (!near_null_space_.empty()) {
      std::vector<Vec> modes;
      for (const VectorX& mode : solved_modes()) {
        VecCreateSeq(PETSC_COMM_SELF, n_first, &modes.emplace_back());
        write(modes.back(), mode);
      }
      petsc::compose_near_null_space(fields_[0], modes);
    }
    PCFieldSplitSetIS(preconditioner, "u", fields_[0]);
    PCFieldSplitSetIS(preconditioner, "p", fields_[1]);
    if (schur_matrix_) petsc::attach_schur_matrix(preconditioner, schur_matrix_);
    return true;
  }

  /// split_fields on several ranks: the splits' index sets in PETSc's distributed rows
  /// (each rank its own), the modes as distributed vectors and the Schur matrix as
  /// MPIAIJ, all made at the copy (petsc::DistributedSystem).
  bool split_distributed_fields(PC preconditioner) {
    const petsc::DistributedFields* fields = distributed_system_.fields();
    FF_ASSERT(fields, "the fields are numbered at the first copy");
    if (!near_null_space_.empty())
      petsc::attach_distributed_near_null_space(solved_modes(), *fields);
    // Laid out node by node: each rank owns whole nodes (share_pattern), so the split's
    // index set has the block size that systems BoomerAMG reads.
    if (!layout_.empty()) ISSetBlockSize(fields->velocity(), layout_.components());
    PCFieldSplitSetIS(preconditioner, "u", fields->velocity());
    PCFieldSplitSetIS(preconditioner, "p", fields->pressure());
    if (schur_matrix_) petsc::attach_schur_matrix(preconditioner, schur_matrix_);
    return true;
  }

  /// Whether set_schur_preconditioner gave this step's Schur matrix (distributed: its share,
  /// which waits for the rows' numbering at the copy).
  bool schur_given() const {
    return distributed_ ? schur_share_.rows() > 0 : schur_matrix_ != nullptr;
  }

  /// Whether the velocity block is laid out node by node (NodeBlockLayout), for a saddle
  /// point whose velocity nodes set_velocity_nodes gave: by default where the iterative
  /// default serves (a block-diagonal Schur matrix, make_ksp), since BoomerAMG then
  /// coarsens each velocity component on its own (hypre's systems AMG, block size dim)
  /// and needed fewer iterations at half the operator complexity in 3D
  /// (docs/benchmarks.md "Velocity AMG settings in 3D"); the option
  /// -formflow_velocity_node_blocks (read here, so it counts as used) says otherwise.
  /// Decided at the first copy.
  bool lay_out_nodes(Index n_rows) {
    if (!layout_decided_) {
      layout_decided_ = true;
      PetscBool wanted = schur_block_ > 0 && schur_given() ? PETSC_TRUE : PETSC_FALSE;
      PetscBool given = PETSC_FALSE;
      PetscOptionsGetBool(nullptr, nullptr, "-formflow_velocity_node_blocks", &wanted, &given);
      if (wanted && n_first_ > 0 && static_cast<Index>(dof_of_velocity_.size()) == n_first_)
        layout_ = petsc::NodeBlockLayout(components_, dof_of_velocity_, n_rows);
    }
    return !layout_.empty();
  }

  /// Whether the saddle point goes to PETSc as four blocks (petsc::SaddlePointNest,
  /// take_saddle_point_blocks): where the iterative default serves (a block-diagonal
  /// Schur matrix, make_ksp) and the options do not ask for another preconditioner than
  /// fieldsplit (a direct solver needs one AIJ matrix); -formflow_saddle_point_nest 0
  /// says otherwise (one AIJ matrix of the whole saddle point, as before session 13).
  bool nest_the_saddle_point() {
    if (n_first_ <= 0 || schur_block_ <= 0 || !schur_given()) return false;
    PetscBool wanted = PETSC_TRUE, given = PETSC_FALSE;
    PetscOptionsGetBool(nullptr, nullptr, "-formflow_saddle_point_nest", &wanted, &given);
    char type[64] = "";
    PetscBool typed = PETSC_FALSE;
    PetscOptionsGetString(nullptr, nullptr, "-pc_type", type, sizeof type, &typed);
    return wanted && (!typed || std::string_view(type) == PCFIELDSPLIT);
  }

  /// Copies `matrix` (its lower triangle for SymmetricLower; A alone after
  /// take_saddle_point_blocks) into PETSc's matrix in the unknowns PETSc solves for: the
  /// contact nodes' frames and the node layout decided here, the matrix itself by
  /// petsc::SequentialSystem, or in a distributed run (issue 20; app/main.cpp said so)
  /// by petsc::DistributedSystem from this rank's share (its own cells' entries,
  /// assembly/discretisation.hpp).
  void copy(const assembly::SparseMatrix& matrix) {
    const bool blocks = coupling_.rows() > 0; // take_saddle_point_blocks: `matrix` is A
    const Index n_rows = matrix.rows() + (blocks ? coupling_.rows() : 0);
    if (!frames_.empty() && frame_matrix_.rows() != matrix.rows())
      frame_matrix_ = assembly::frame_matrix(frames_, matrix.rows());
    const assembly::SparseMatrix no_frames;
    const assembly::SparseMatrix& frames = frames_.empty() ? no_frames : frame_matrix_;
    lay_out_nodes(n_rows);
    const bool lower_only = storage_ == MatrixStorage::SymmetricLower;
    const Index n_velocity = n_first_ > 0 ? n_first_ : n_rows;
    petsc::CopyOutcome copied = petsc::CopyOutcome::refused;
    if (blocks) {
      // The velocity block's own layout: the same rows as the saddle point's layout gives
      // the velocity (they depend on the velocity's nodes alone), no pressure rows.
      const petsc::NodeBlockLayout velocity_layout =
          layout_.empty() ? petsc::NodeBlockLayout()
                          : petsc::NodeBlockLayout(components_, dof_of_velocity_, matrix.rows());
      const PetscInt block_size = layout_.empty() ? 1 : layout_.components();
      copied =
          distributed_
              ? distributed_system_.copy_saddle_point(matrix, coupling_, pressure_block_, frames,
                                                      velocity_layout, block_size, n_first_solved(),
                                                      &matrix_, &rhs_, &solution_)
              : sequential_system_.copy_saddle_point(
                    matrix, coupling_, pressure_block_, frames, velocity_layout, block_size,
                    layout_.empty() ? n_rows : layout_.n_embedded(), &matrix_, &rhs_, &solution_);
    } else {
      copied = distributed_
                   ? distributed_system_.copy(matrix, lower_only, frames, layout_, n_velocity,
                                              n_first_ > 0 ? n_first_solved() : 0, &matrix_, &rhs_,
                                              &solution_)
                   : sequential_system_.copy(matrix, lower_only, frames, layout_, n_velocity,
                                             &matrix_, &rhs_, &solution_);
    }
    if (!distributed_ || copied == petsc::CopyOutcome::refused) return;
    // The Schur matrix lives on the fields' rows: made again with them.
    if (copied == petsc::CopyOutcome::rebuilt && schur_matrix_) MatDestroy(&schur_matrix_);
    // The Schur matrix's share given for this step (set_schur_preconditioner).
    if (const petsc::DistributedFields* fields = distributed_system_.fields();
        fields && schur_share_.rows() == distributed_system_.n_solved() - n_first_solved()) {
      petsc::copy_distributed_schur_matrix(schur_share_, *fields, schur_block_, &schur_matrix_);
      schur_share_ = {};
    }
  }

  /// The velocity rows PETSc solves for: the free ones, or the layout's.
  Index n_first_solved() const {
    return layout_.empty() ? n_first_ : layout_.n_velocity_embedded();
  }

  [[noreturn]] void refuse(const std::string& message, const std::string& hint) const {
    throw InputError("", 0, options_key,
                     fmt::format("value \"{}\": {}", options_,
                                 message.empty() ? "refused by "
                                                   "PETSc"
                                                 : message),
                     hint);
  }

  MatrixStorage storage_;
  std::string options_;
  petsc::OptionsScope options_scope_{options_};
  Mat matrix_ = nullptr;
  Vec rhs_ = nullptr, solution_ = nullptr;
  KSP ksp_ = nullptr;
  petsc::SequentialSystem sequential_system_;        ///< one process: the AIJ matrix or the nest
  assembly::SparseMatrix coupling_, pressure_block_; ///< take_saddle_point_blocks' B and C
  bool distributed_ = false;    ///< the ranks' shares of one system (petsc::distributed_systems)
  bool solution_finite_ = true; ///< distributed: the last solution, every rank's rows
  petsc::DistributedSystem distributed_system_; ///< distributed: numbering, COO, ghosts
  Index n_first_ = 0;                           ///< velocity dofs of a saddle point (set_fields)
  std::vector<VectorX> near_null_space_;        ///< the velocity block's rigid-body modes
  IS fields_[2] = {nullptr, nullptr};           ///< fieldsplit's "u" and "p"
  Mat schur_matrix_ = nullptr;                  ///< the Schur complement's preconditioning matrix
  assembly::SparseMatrix schur_share_;          ///< distributed: its share, until copied
  Index schur_block_ = 0;                       ///< its cell block size (0: not block diagonal)
  std::vector<assembly::LocalFrame> frames_;    ///< PETSc solves for y, x = Q y (set_local_frames)
  assembly::SparseMatrix frame_matrix_;         ///< Q, made at the first copy
  int components_ = 1;                          ///< velocity components per node
  std::vector<Index> dof_of_velocity_;          ///< velocity row → mesh dof (set_velocity_nodes)
  petsc::NodeBlockLayout layout_;               ///< the velocity block node by node, if asked
  bool layout_decided_ = false;
  petsc::DefaultOptions defaults_; ///< the saddle-point defaults in the database
  long iterations_ = 0;
  bool checked_unused_ = false;
  std::string options_prefix_;      ///< a helper's solver: its options' prefix (set_options_prefix)
  petsc::KrylovStart krylov_start_; ///< the next solve's guess and tolerance
};

} // namespace

std::unique_ptr<LinearSolver> make_petsc_solver(MatrixStorage storage, const std::string& options) {
  return std::make_unique<PetscSolver>(storage, options);
}

} // namespace formflow::solvers
