// SPDX-License-Identifier: MIT
// Case keys of the [solver] section (The nonlinear iteration): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

namespace {

KeySpec petsc_options_key() {
  KeySpec spec("solver.petsc_options", KeyType::Text, std::string());
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.solver.petsc_options = std::get<std::string>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.solver.petsc_options; };
  return spec;
}

} // namespace

std::vector<CaseKey> solver_keys() {
  return {
      real_key(
          "solver.tolerance", 1e-4, [](auto& c) -> auto& { return c.solver.tolerance; })
          .at_least(1e-15)
          .below(1)
          .why(tolerance_range)
          .doc("δ: the secant iteration stops when ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ"),
      integer_key(
          "solver.max_iterations", 500, [](auto& c) -> auto& { return c.solver.max_iterations; })
          .at_least(1)
          .at_most(1e9)
          .doc("iteration limit; reaching it is a result (not converged, exit 3), not an error"),
      real_key(
          "solver.initial_rate", 1.0, [](auto& c) -> auto& { return c.solver.initial_rate; })
          .within(1e-12, 1e12)
          .why(rate_range)
          .unit("1/time")
          .doc("ε̄̇ whose secant viscosity σ_p(ε̄̇)/ε̄̇ gives the constant-viscosity first "
               "iterate"),
      enum_key(
          "solver.linear", "cholmod",
          {{"cholmod", solvers::LinearSolverKind::Cholmod},
           {"umfpack", solvers::LinearSolverKind::Umfpack},
           {"petsc", solvers::LinearSolverKind::Petsc}},
          [](auto& c) -> auto& { return c.solver.linear; })
          .constraint("cholmod cannot serve the Taylor–Hood saddle point (formulation.pressure = "
                      "\"Q1\"), which takes umfpack unless cholmod is asked for; petsc only in a "
                      "build with FORMFLOW_WITH_PETSC")
          .doc("solver of the linear systems: cholmod (supernodal Cholesky LLᵀ of the "
               "symmetric positive definite velocity systems), umfpack (LU; also the "
               "indefinite Taylor–Hood saddle point) or petsc (PETSc KSP/PC configured by "
               "solver.petsc_options; by default a direct MUMPS Cholesky, or LU for the "
               "saddle point; docs/petsc.md). Run by mpirun on several ranks, a case that "
               "leaves this key unset takes petsc, the one distributed back-end"),
      petsc_options_key()
          .constraint("only with solver.linear = \"petsc\" (the default on several MPI ranks); "
                      "names start with '-', values follow their name; only solver and "
                      "preconditioner options, no viewer, monitor, log, options file or path "
                      "(docs/petsc.md); an option no PETSc object reads is refused before the "
                      "first solve")
          .doc("PETSc options database text for solver.linear = \"petsc\", e.g. \"-ksp_type cg "
               "-pc_type gamg\"; PETSc options on the command line (-ksp_*, -pc_*, -mat_*, ...) "
               "override it; empty: direct MUMPS"),
      enum_key(
          "solver.method", "newton",
          {{"newton", solvers::NonlinearMethod::Newton},
           {"secant", solvers::NonlinearMethod::Secant}},
          [](auto& c) -> auto& { return c.solver.method; })
          .doc("newton: Newton–Raphson with the consistent tangent and a line search; "
               "secant: the paper's secant-modulus (Kachanov) iteration (eq. 5.2–5.3)"),
      enum_key(
          "solver.acceleration", "none",
          {{"none", solvers::NonlinearAcceleration::None},
           {"anderson", solvers::NonlinearAcceleration::Anderson}},
          [](auto& c) -> auto& { return c.solver.acceleration; })
          .constraint("secant only (solver.method = \"secant\"): Newton's steps are not a "
                      "fixed-point map's")
          .doc("secant only: none = each step lags the coefficients at the last step's result; "
               "anderson = at a mix of the last solver.acceleration_depth results that "
               "minimises the mixed step's change (Anderson acceleration, Walker–Ni; restarted "
               "when the mix is ill-conditioned or does not reduce the change). The stop is "
               "still ‖G(u) − u‖/‖G(u)‖ < δ of one unmixed step (docs/benchmarks.md \"Anderson "
               "acceleration\")"),
      integer_key(
          "solver.acceleration_depth", 5,
          [](auto& c) -> auto& { return c.solver.acceleration_depth; })
          .at_least(1)
          .at_most(10)
          .constraint("only with solver.acceleration = \"anderson\"")
          .doc("Anderson's depth m: the last m steps' differences are mixed (memory 2m free "
               "velocity vectors); beyond 10 the columns are nearly dependent and the mix is "
               "restarted anyway"),
      real_key(
          "solver.newton_start", 0.5, [](auto& c) -> auto& { return c.solver.newton_start; })
          .within(1e-15, 1e6)
          .why("a relative change: below 1e-15 it is round-off, above 1e6 Newton starts at once")
          .doc("newton only: secant steps are taken while the relative change exceeds this "
               "(safeguard far from the solution)"),
      integer_key(
          "solver.coarse_levels", 2, [](auto& c) -> auto& { return c.solver.coarse_levels; })
          .at_least(0)
          .at_most(6)
          .doc("newton, and secant on a discontinuous pressure kept as a saddle point, only: first "
               "solve on this many coarser meshes (mesh.size times 2^L, ..., 2), each started from "
               "the previous one, and start from the last; 0: from the constant-viscosity "
               "solution; levels the geometry does not admit (or a mesh from a file) are skipped, "
               "and summary.json coarse_mesh_sizes lists those used"),
      enum_key(
          "solver.load_error", "auto",
          {{"auto", solvers::LoadErrorMethod::Auto},
           {"coarser", solvers::LoadErrorMethod::Coarser},
           {"refined", solvers::LoadErrorMethod::Refined},
           {"linearized", solvers::LoadErrorMethod::Linearized},
           {"none", solvers::LoadErrorMethod::None}},
          [](auto& c) -> auto& { return c.solver.load_error; })
          .doc("estimate of |p_h − p| for the load (summary.json pressure.ram_reaction_error, "
               "drawing_stress_error; docs/error-estimation.md): a geometric tail of load "
               "differences times F_s = 1.25, plus the load's change when d, d_N, d_T and the "
               "power law's α are doubled; coarser = p_h − p_{2h} with the ratio observed on "
               "4h, 2h, h (the structured channel must admit 2h and 4h; it adds "
               "25–45 % to a Newton run's time; cell indicators at 2h); refined = p_{h/2} from "
               "Newton on "
               "the mesh "
               "refined once, to δ, and the reaction's adjoint there (cell indicators; costs 4–8 "
               "times the run); linearized = the adjoint at the prolonged solution only "
               "(underestimates nearly rate-insensitive loads by ≈ 2.6×); auto = coarser where "
               "the mesh admits it, else refined when the refined mesh has at most 200 000 dofs "
               "(25 000 in 3D), "
               "else none (said why); none = no estimate. In a case with [adapt]: refined = "
               "the full (refined) estimate on every cycle; any other value, on Q2 (on Q1: "
               "linearized) = cheap intermediate cycles (the linearised estimate scaled by "
               "cycle 0's settled/linearised ratio), the full estimate from the first cycle "
               "whose prediction may stop on, and on the last"),
  };
}

} // namespace formflow::io::keys
