// SPDX-License-Identifier: MIT
// Why a nonlinear iteration stopped, and the record of each iteration.
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/solvers/linear_solver_kind.hpp"

#include <string>
#include <string_view>

namespace formflow::solvers {

/// Stalled: the loop stopped making progress (no new minimum of its merit over a
/// window of iterations, solvers/stall_watch.hpp) before meeting the tolerance.
/// CouplingLimit: hot forming's staggered loop took thermal.max_coupling_iterations
/// steps, each flow solve converged, without meeting thermal.coupling_tolerance.
enum class StopReason {
  Converged,
  MaxIterations,
  Diverged,
  NonFinite,
  SolverFailed,
  Stalled,
  CouplingLimit
};

inline std::string_view stop_reason_name(StopReason reason) {
  switch (reason) {
  case StopReason::Converged: return "converged";
  case StopReason::MaxIterations: return "max_iterations";
  case StopReason::Diverged: return "diverged";
  case StopReason::NonFinite: return "non_finite";
  case StopReason::SolverFailed: return "solver_failed";
  case StopReason::Stalled: return "stalled";
  case StopReason::CouplingLimit: return "max_coupling_iterations";
  }
  return "unknown";
}

/// The nonlinear method: the paper's secant-modulus (Kachanov) iteration, or
/// Newton–Raphson with the consistent tangent (solvers/newton_iteration.hpp).
enum class NonlinearMethod { Secant, Newton };

/// Acceleration of the secant loop's fixed-point map (solver.acceleration): none, or
/// Anderson mixing of the last solver.acceleration_depth steps
/// (solvers/anderson_acceleration.hpp).
enum class NonlinearAcceleration { None, Anderson };

/// Stopping rule of the secant iteration (SPEC §3): ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < tolerance.
/// Newton uses the same rule on its (damped) steps, so counts are comparable.
/// The load's error estimate (docs/error-estimation.md): none; the adjoint at the
/// solution prolonged to the mesh refined once (one factorisation, linearised); the
/// same after a Newton solve on the refined mesh (the nonlinearity settled first);
/// the loads solved on the structured channel coarsened once and twice (2h, 4h: no
/// refined mesh, a fraction of the run's cost); or auto, the cheapest of these that is
/// reliable for the run's mesh (app/load_error.cpp).
enum class LoadErrorMethod { None, Linearized, Refined, Coarser, Auto };

struct IterationControl {
  Real tolerance = 1e-4;    ///< δ
  int max_iterations = 500; ///< iteration limit; reaching it is a stop reason, not an error
  Real initial_rate = 1.0;  ///< ε̄̇ whose secant viscosity starts the iteration
  NonlinearMethod method = NonlinearMethod::Newton;
  /// Secant only: how the loop's next iterate is made from the last steps.
  NonlinearAcceleration acceleration = NonlinearAcceleration::None;
  /// Anderson's depth m: difference columns mixed at most.
  int acceleration_depth = 5;
  /// Newton only: secant steps are taken while the relative change exceeds this.
  Real newton_start = 0.5;
  /// Newton only: solve first on this many coarser meshes (sizes 2^L h, ..., 2h)
  /// and start from the last coarse solution (app/coarse_start.hpp); 0: no.
  int coarse_levels = 2;
  /// solver.linear: the direct solver of the velocity systems (Taylor–Hood's saddle
  /// point always takes an LU, UMFPACK).
  LinearSolverKind linear = LinearSolverKind::Cholmod;
  /// solver.petsc_options: PETSc options database text for solver.linear = "petsc".
  std::string petsc_options;
  /// solver.load_error: how the load's discretisation error is estimated after the
  /// solve (post/load_error_estimate.hpp, docs/error-estimation.md).
  LoadErrorMethod load_error = LoadErrorMethod::Auto;
};

/// One line of the iteration history.
struct IterationRecord {
  int iteration = 0;
  Real relative_change = 0.0; ///< ‖uⁿ⁺¹ − uⁿ‖ / ‖uⁿ⁺¹‖
  Real pressure = 0.0;        ///< current process pressure (ram reaction / height)
  Real seconds = 0.0;         ///< wall time of this iteration
  /// Hot forming: > 0 on the record that closes staggered coupling step `coupling`
  /// (its relative_change is the temperature's, `force_change` the load's); 0 on every
  /// iteration of a flow solve.
  int coupling = 0;
  Real force_change = 0.0;    ///< coupling records: |pᵏ − pᵏ⁻¹|/|pᵏ|
  Real max_temperature = 0.0; ///< coupling records: max T
  /// Krylov iterations of the linear solves of this iteration (an iterative back-end,
  /// solver.linear = "petsc"; a direct KSP "preonly" counts 1 per solve); −1 where the
  /// back-end has none (CHOLMOD, UMFPACK).
  long linear_iterations = -1;
  /// Anderson acceleration: the difference columns mixed into the iterate this step
  /// started from (0: a plain step, the last step's result).
  int mixed_columns = 0;
  /// Which solve the iteration belongs to when a run makes several: empty for the run's
  /// own, else e.g. "error estimate: the mesh refined once, 88714 dofs" or "adapt cycle 3,
  /// 2938 dofs" (app::with_stage), so that a monitor can say what is being solved
  /// while the error estimate's levels run.
  std::string stage = {};
};

} // namespace formflow::solvers
