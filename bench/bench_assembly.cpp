// SPDX-License-Identifier: MIT
// Cost of the cell loops alone on the paper's benchmark (Q2, 2×2 volumetric rule,
// μ = 0.1), mesh II refined 8× (77 k dofs) and 16× (309 k dofs): one secant
// assembly, one Newton assembly with tangent and coupling, one residual-only
// Newton pass (the line search), one dual update and one matrix-free coupling
// product. The velocity is the constant-viscosity solution, the duals those of
// the secant step from it, so every branch of the loops is taken as in a solve.
// Results and machine notes: docs/benchmarks.md, section "Assembly".
#include "formflow/app/simulation.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/newton_duals.hpp"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

namespace {

using namespace formflow;

/// One refinement's problem and a realistic state, built once and shared by the benchmarks.
struct AssemblyFixture {
  mesh::Mesh<2> mesh;
  std::unique_ptr<assembly::FormingProblem<2>> problem;
  assembly::LinearSystem system;
  VectorX velocity, step, next, internal_force, x_free, y_free;
  std::vector<Real> thresholds;
  assembly::NewtonDuals<2> duals;
  assembly::UnsymmetricTangent<2> coupling;

  explicit AssemblyFixture(int refinement) {
    io::Case case_;
    case_.mesh.size = 1.0 / refinement;
    case_.friction.mu = 0.1;
    mesh = mesh::make_channel_mesh(case_.mesh.geometry, case_.mesh.size, 2);
    problem = std::make_unique<assembly::FormingProblem<2>>(mesh, app::problem_settings(case_));
    system = problem->plan().make_system();
    problem->assemble(nullptr, system);
    auto solver = solvers::make_cholmod_solver();
    VectorX free_solution;
    if (!solver->analyze(system.matrix) || !solver->factorize(system.matrix) ||
        !solver->solve(system.rhs, free_solution))
      throw std::runtime_error("the constant-viscosity solve failed");
    velocity = problem->plan().expand(free_solution, problem->constraints().values);
    thresholds = problem->friction_thresholds(velocity);
    solvers::secant_duals(*problem, nullptr, velocity, duals);
    // A step that keeps the prescribed values: 1 % of the free solution.
    step = problem->plan().expand(0.01 * free_solution, VectorX::Zero(problem->n_dofs()));
    next = velocity + step;
    problem->assemble_newton(velocity, thresholds, duals, internal_force, &system, &coupling);
    x_free = VectorX::LinSpaced(problem->plan().n_free(), -1.0, 1.0);
    y_free = VectorX::Zero(problem->plan().n_free());
  }
};

AssemblyFixture& fixture(int refinement) {
  static std::map<int, std::unique_ptr<AssemblyFixture>> fixtures;
  auto& entry = fixtures[refinement];
  if (!entry) entry = std::make_unique<AssemblyFixture>(refinement);
  return *entry;
}

void count_dofs(benchmark::State& state, const AssemblyFixture& f) {
  state.counters["dofs"] = f.problem->n_dofs();
  state.counters["cells"] = f.mesh.n_cells();
  state.counters["geometry_cache_mib"] =
      static_cast<double>(f.problem->geometry_cache_bytes()) / (1 << 20);
}

void secant_assembly(benchmark::State& state) {
  AssemblyFixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) f.problem->assemble(&f.velocity, f.system);
  count_dofs(state, f);
}

void newton_tangent_assembly(benchmark::State& state) {
  AssemblyFixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state)
    f.problem->assemble_newton(f.velocity, f.thresholds, f.duals, f.internal_force, &f.system,
                               &f.coupling);
  count_dofs(state, f);
  state.counters["coupling_points"] = static_cast<double>(f.coupling.cells.size());
}

void newton_residual(benchmark::State& state) {
  AssemblyFixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state)
    f.problem->assemble_newton(f.velocity, f.thresholds, f.duals, f.internal_force);
  count_dofs(state, f);
}

void dual_update(benchmark::State& state) {
  AssemblyFixture& f = fixture(static_cast<int>(state.range(0)));
  assembly::NewtonDuals<2> duals;
  // The update reads the previous duals: each run starts from the same ones. The
  // copy (81 doubles per cell) is timed too, as in the first version of this
  // benchmark, so that before/after medians compare the same work.
  for (auto _ : state) {
    duals = f.duals;
    solvers::update_duals(*f.problem, f.velocity, f.step, f.next, duals);
  }
  count_dofs(state, f);
}

void coupling_product(benchmark::State& state) {
  AssemblyFixture& f = fixture(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    f.y_free.setZero();
    f.problem->apply_coupling(f.coupling, f.x_free, f.y_free);
    benchmark::DoNotOptimize(f.y_free.data());
  }
  count_dofs(state, f);
}

} // namespace

BENCHMARK(secant_assembly)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(newton_tangent_assembly)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(newton_residual)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(dual_update)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(coupling_product)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
