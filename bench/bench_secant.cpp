// SPDX-License-Identifier: MIT
// Cost of the secant iteration on the paper's benchmark, mesh II refined k times
// (Q2, 2×2 volumetric rule), against one bare CHOLMOD factorisation of the same
// matrix; and secant vs Newton, whole solves, for μ = 0, 0.1, 0.2 on the same
// meshes. Results and machine notes: docs/benchmarks.md.
#include "formflow/app/simulation.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/solvers/linear_solver.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace formflow;

/// Peak resident memory of this process so far, in MiB (VmHWM).
double peak_memory_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

io::Case refined_case(int refinement) {
  io::Case case_;
  case_.solver.load_error = solvers::LoadErrorMethod::None; // the solve's cost alone
  case_.mesh.size = 1.0 / refinement;
  case_.solver.method =
      solvers::NonlinearMethod::Secant; // the per-iteration cost of the paper's method
  // Up to 4 refinements the whole solve is timed; beyond, 10 iterations give
  // the per-iteration cost without a many-minute run (the count is reported).
  if (refinement > 4) case_.solver.max_iterations = 10;
  case_.solver.method = solvers::NonlinearMethod::Secant;
  return case_;
}

/// Seconds of the nonlinear solve proper (everything but mesh, setup and post).
double solver_seconds(const post::Results& results) {
  double seconds = 0.0;
  for (const char* phase :
       {"assembly", "analysis", "factorization", "solve", "krylov", "line search", "dual update"})
    seconds += results.timing.get(phase);
  return seconds;
}

/// The secant matrix at the constant viscosity of `case_`'s mesh, analysed and
/// factorised `repetitions` times: the median seconds of one numeric factorisation.
/// Timed in the process of the solve it is compared with, right after it, since on
/// this shared VM the same factorisation varies by up to 1.5× between processes.
double median_bare_factorization_seconds(const io::Case& case_, int repetitions = 3) {
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(case_.mesh.geometry, case_.mesh.size, 2);
  const assembly::FormingProblem<2> problem(mesh, assembly::ProblemSettings{});
  assembly::LinearSystem system = problem.plan().make_system();
  problem.assemble(nullptr, system);
  auto solver = solvers::make_cholmod_solver();
  solver->analyze(system.matrix);
  std::vector<double> seconds;
  for (int k = 0; k < repetitions; ++k) {
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(solver->factorize(system.matrix));
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

/// Whole solve to δ = 1e-4 of mesh II refined range(0) times with μ = range(1)/10,
/// by the method range(2) (0 secant, 1 Newton). Secant beyond k = 4 would take
/// minutes per case: those rows are Newton only.
void method_solve(benchmark::State& state) {
  io::Case case_;
  case_.solver.load_error = solvers::LoadErrorMethod::None; // the solve's cost alone
  case_.mesh.size = 1.0 / static_cast<double>(state.range(0));
  case_.friction.mu = static_cast<double>(state.range(1)) / 10.0;
  case_.solver.method =
      state.range(2) == 1 ? solvers::NonlinearMethod::Newton : solvers::NonlinearMethod::Secant;
  case_.solver.max_iterations = 2000;
  post::Results results;
  for (auto _ : state) results = app::simulate(case_).results;
  state.counters["dofs"] = results.n_dofs;
  state.counters["iterations"] = results.iterations;
  int coarse_iterations = 0; // Newton's mesh-sequencing start (solver.coarse_levels)
  for (const int count : results.coarse_iterations) coarse_iterations += count;
  state.counters["coarse_iterations"] = coarse_iterations;
  state.counters["converged"] = results.converged() ? 1 : 0;
  state.counters["total_s"] = results.timing.get("total");
  state.counters["solver_s"] = solver_seconds(results);
  state.counters["factorization_s"] = results.timing.get("factorization");
  state.counters["ram_reaction"] = results.pressure.ram_reaction;
  state.counters["factorizations"] = static_cast<double>(results.timing.counted("factorization"));
  state.counters["krylov_iterations"] =
      static_cast<double>(results.timing.counted("krylov iterations"));
  state.counters["peak_mib"] = peak_memory_mib();
  state.counters["bare_factorization_s"] = median_bare_factorization_seconds(case_);
}

void secant_solve(benchmark::State& state) {
  const io::Case case_ = refined_case(static_cast<int>(state.range(0)));
  post::Results results;
  for (auto _ : state) results = app::simulate(case_).results;
  const double iterations = results.iterations + 1; // + the constant-viscosity start
  state.counters["dofs"] = results.n_dofs;
  state.counters["iterations"] = results.iterations;
  state.counters["total_s"] = results.timing.get("total");
  state.counters["per_iteration_s"] =
      (results.timing.get("assembly") + results.timing.get("factorization") +
       results.timing.get("solve")) /
      iterations;
  state.counters["assembly_per_it_s"] = results.timing.get("assembly") / iterations;
  state.counters["factorization_per_it_s"] = results.timing.get("factorization") / iterations;
  state.counters["solve_per_it_s"] = results.timing.get("solve") / iterations;
  state.counters["analysis_s"] = results.timing.get("analysis");
  state.counters["post_s"] = results.timing.get("post");
  state.counters["peak_mib"] = peak_memory_mib();
}

void bare_factorization(benchmark::State& state) {
  const io::Case case_ = refined_case(static_cast<int>(state.range(0)));
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(case_.mesh.geometry, case_.mesh.size, 2);
  assembly::ProblemSettings settings;
  const assembly::FormingProblem<2> problem(mesh, settings);
  assembly::LinearSystem system = problem.plan().make_system();
  problem.assemble(nullptr, system);
  auto solver = solvers::make_cholmod_solver();
  solver->analyze(system.matrix);
  for (auto _ : state) benchmark::DoNotOptimize(solver->factorize(system.matrix));
  state.counters["dofs"] = problem.n_dofs();
  state.counters["nonzeros_lower"] = static_cast<double>(system.matrix.nonZeros());
}

} // namespace

BENCHMARK(secant_solve)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK(bare_factorization)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);

BENCHMARK(method_solve)
    ->ArgsProduct({{1, 2, 4}, {0, 1, 2}, {0, 1}})
    ->ArgsProduct({{8, 16}, {0, 1, 2}, {1}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

BENCHMARK_MAIN();
