// SPDX-License-Identifier: MIT
// Sparse SPD direct solver interface: analyse the pattern once, factorise per iteration.
#pragma once

#include "formflow/assembly/local_frame.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/linear_solver_kind.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace formflow::solvers {

/// The size of the last analysed factorisation, as the back-end counts it
/// (summary.json linear_algebra; the fill of docs/benchmarks.md's 3D table). A
/// count the back-end does not report is −1.
struct FactorSize {
  /// Nonzeros of the matrix as the back-end takes it (CHOLMOD: the lower triangle).
  double matrix_nonzeros = -1;
  /// Nonzeros of the factor (CHOLMOD: nnz(L) of its analysis, without the zeros
  /// that supernodal amalgamation stores).
  double factor_nonzeros = -1;
  double factor_flops = -1; ///< floating-point operations of one numeric factorisation
};

/// Direct solver of K x = b for a symmetric positive definite K given by its
/// lower triangle. Failures are reported by return value, never by exception.
class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Fill-reducing ordering and symbolic factorisation of the pattern of `lower`.
  virtual bool analyze(const assembly::SparseMatrix& lower) = 0;
  /// Numeric factorisation; same pattern as analysed. False if not positive definite.
  virtual bool factorize(const assembly::SparseMatrix& lower) = 0;
  /// Solves with the last factorisation. False on failure. In a distributed run (issue
  /// 20, the PETSc back-end) `rhs` is this rank's share, its own cells' loads (the
  /// ranks' add up); `solution` is ghosted: the rows of the rank's own cells' dofs, NaN
  /// elsewhere (NonlinearProblem::replicate).
  virtual bool solve(const VectorX& rhs, VectorX& solution) = 0;
  /// solve() for a right-hand side that every rank holds whole and alike (Newton's
  /// residual, the GMRES vectors): each rank gives its own rows. One process: solve().
  virtual bool solve_whole(const VectorX& rhs, VectorX& solution) { return solve(rhs, solution); }
  /// Whether the last solve's `solution` is finite: a ghosted solution's other rows are
  /// NaN by design, so a distributed back-end answers for the whole solution (alike on
  /// every rank). One process: every entry finite.
  virtual bool finite(const VectorX& solution) const { return solution.allFinite(); }
  virtual std::string name() const = 0;
  /// Krylov iterations of all solves so far (iterative back-ends), or −1 when the
  /// back-end is a direct factorisation with no such count.
  virtual long krylov_iterations() const { return -1; }
  /// The matrix and factor sizes of the last analyze (counts, not timings: they do
  /// not depend on the machine's load). Default: not reported.
  virtual FactorSize factor_size() const { return {}; }
  /// The two fields of the matrices to come (a saddle point): rows and columns
  /// [0, n_first) are the velocity, the rest the pressure; `near_null_space` holds
  /// vectors of length n_first that the velocity block nearly annihilates (its
  /// rigid-body modes). Call before analyze. A direct back-end has no use for it;
  /// PETSc's fieldsplit preconditioner takes its splits and AMG its modes from it.
  virtual void set_fields(Index n_first, std::vector<VectorX> near_null_space) {
    static_cast<void>(n_first);
    static_cast<void>(near_null_space);
  }
  /// The pressure block's preconditioning matrix for the Schur complement of the
  /// saddle point whose fields set_fields gave (the viscosity-scaled pressure mass,
  /// assembly::SaddlePointSystem::schur_preconditioner), new at every factorisation:
  /// call before each factorize. `cell_block` > 0: the matrix is block diagonal in
  /// blocks of that size (a discontinuous pressure's cells), so inverting it is cheap
  /// and exact, and an iterative back-end may make the block preconditioner its
  /// default. A direct back-end has no use for it.
  virtual void set_schur_preconditioner(const assembly::SparseMatrix& matrix, Index cell_block) {
    static_cast<void>(matrix);
    static_cast<void>(cell_block);
  }
  /// Orthogonal changes of basis of groups of unknowns (the Γ3 nodes' velocity dofs into
  /// their normal–tangent frame, assembly::contact_frames) that a back-end may solve in:
  /// Qᵀ K Q y = Qᵀ b, x = Q y — the same solution, the same condition number, but a
  /// stiff coupling along an inclined direction becomes a diagonal entry. Rows index the
  /// matrices to come; call before analyze. A direct back-end has no use for it; PETSc's
  /// iterative path (a pointwise smoother, algebraic multigrid) needs it.
  virtual void set_local_frames(std::vector<assembly::LocalFrame> frames) {
    static_cast<void>(frames);
  }
  /// A guess of the next solve's solution (a secant step's previous iterate): an iterative
  /// back-end starts its Krylov method from it instead of zero. Its stop test stays
  /// relative to the right-hand side's norm (PETSc's default), so the solution is as
  /// accurate as from zero, in fewer iterations when the guess is close. Serves the next
  /// solve only. A direct back-end has no use for it.
  virtual void set_initial_guess(VectorX guess) { static_cast<void>(guess); }
  /// Inexact solves: the next solves may stop once they have reduced the residual of
  /// their start (the guess of set_initial_guess, else zero) by the factor `reduction`,
  /// where that is looser than the back-end's own tolerance (-ksp_rtol relative to the
  /// right-hand side; never tighter than it); 0 restores the own tolerance. Returns
  /// whether the solves are now looser than the own tolerance (false for a direct
  /// back-end, which is exact).
  virtual bool set_solve_tolerance(Real reduction) {
    static_cast<void>(reduction);
    return false;
  }
  /// The node of each velocity row of the saddle point whose fields set_fields gave:
  /// `dof_of_velocity[i]` = node·components + component of velocity row i. An AMG that
  /// coarsens node by node (BoomerAMG's nodal options, GAMG's aggregates with the
  /// rigid-body modes) needs rows grouped by node with a constant block size, which the
  /// free dofs are not; PETSc's iterative path lays the block out so (docs/petsc.md).
  /// Call before analyze. A direct back-end has no use for it.
  virtual void set_velocity_nodes(int components, std::vector<Index> dof_of_velocity) {
    static_cast<void>(components);
    static_cast<void>(dof_of_velocity);
  }
  /// A helper's solver in a run whose own solver comes later (a distributed run's coarse
  /// levels, app/coarse_start.cpp): it reads only the options under `prefix` (PETSc's
  /// options prefix: "coarse_" reads -coarse_ksp_type, ...), so the run's options (the
  /// saddle point's fieldsplit ones) do not reach it, and it leaves the check for unread
  /// options to the run's own solver. Call before analyze. Back-ends without options
  /// ignore it.
  virtual void set_options_prefix(const std::string& prefix) { static_cast<void>(prefix); }
  /// The saddle point whose fields set_fields gave, as blocks [A Bᵀ; B C] rather than one
  /// matrix: `coupling` B (n_p × n_first) and `pressure_block` C (n_p × n_p, both
  /// triangles) stay fixed for the solver's life. A back-end that keeps the blocks apart
  /// anyway (PETSc's fieldsplit) returns true, and from then on analyze and factorize get
  /// the lower triangle of the velocity block A alone: the whole matrix (a second copy of
  /// A, with B twice) is never built. Default: false, give the whole matrix. Call after
  /// the other set_ calls, before the first analyze.
  virtual bool take_saddle_point_blocks(const assembly::SparseMatrix& coupling,
                                        const assembly::SparseMatrix& pressure_block) {
    static_cast<void>(coupling);
    static_cast<void>(pressure_block);
    return false;
  }
};

/// The key's spelling of `kind` ("cholmod", "umfpack").
std::string_view linear_solver_name(LinearSolverKind kind);

/// Whether `kind` can factorise matrices stored as `storage` (CHOLMOD LLᵀ: SPD only).
bool can_serve(LinearSolverKind kind, MatrixStorage storage);

/// The solver `kind` for matrices stored as `storage`; can_serve(kind, storage) holds.
/// `petsc_options` (solver.petsc_options) configures the PETSc back-end only.
std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind, MatrixStorage storage,
                                                 const std::string& petsc_options = {});

/// Whether this build has the back-end `kind` (PETSc only with FORMFLOW_WITH_PETSC).
bool is_built(LinearSolverKind kind);

/// CHOLMOD supernodal LLᵀ (BLAS-3 on supernodes) of the matrix in CHOLMOD's fill-reducing
/// order, formed once per factorisation by a gather (solvers/cholmod.cpp).
std::unique_ptr<LinearSolver> make_cholmod_solver();

/// How many CHOLMOD analyses so far were taken from the process's last two (a new
/// solver given a pattern analysed before gets that analysis: order, symbolic factor,
/// solve tree), not computed again.
std::size_t cholmod_analyses_reused();

/// UMFPACK LU through Eigen's UmfPackSupport, for general (indefinite, e.g. the
/// saddle-point) matrices: unlike the CHOLMOD solver it takes the *full* matrix
/// (both triangles) in analyze/factorize.
std::unique_ptr<LinearSolver> make_umfpack_solver();

} // namespace formflow::solvers
