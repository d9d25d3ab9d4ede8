// SPDX-License-Identifier: MIT
// The dual variables of Newton's primal–dual linearisation: their Newton update
// along a step and their restart after a secant step (moved here from assembly:
// they are the Newton driver's state, read by assemble_newton, not assembly).
#include "formflow/solvers/newton_duals.hpp"

#include "formflow/core/parallel_tasks.hpp"
#include "formflow/physics/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace formflow::solvers {

namespace {

template <int dim>
void update_slip_duals(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                       const VectorX& step, bool primal, std::vector<Point<dim>>& slip_duals) {
  const std::vector<assembly::ContactPoint<dim>> state = problem.contact_state(u),
                                                 change = problem.contact_state(step);
  slip_duals.resize(state.size());
  const Real d_t = problem.settings().friction.d_t;
  for (std::size_t k = 0; k < state.size(); ++k) {
    const Point<dim>& slip = state[k].tangential_velocity;
    const Point<dim>& slip_change = change[k].tangential_velocity;
    const Real s = std::sqrt(slip.squaredNorm() + d_t * d_t);
    Point<dim>& lambda = slip_duals[k];
    if (primal) lambda = slip / s;
    // Newton on s λ − u_T = 0: λ + δλ = (u_T + δu_T)/s − λ (u_T·δu_T)/s².
    lambda = (slip + slip_change) / s - lambda * (slip.dot(slip_change) / (s * s));
    if (lambda.norm() > 1.0) lambda.normalize();
  }
}

/// Exact friction's trial tractions t = λ̂_T + r u_T at the Γ3 points of `state`.
template <int dim>
std::vector<Point<dim>>
trial_tractions(const assembly::FormingProblem<dim>& problem,
                const std::vector<assembly::ContactPoint<dim>>& state,
                const assembly::FrictionMultipliers<dim>* friction_multipliers) {
  const bool given = friction_multipliers && !friction_multipliers->traction.empty();
  std::vector<Point<dim>> trial(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) {
    const Point<dim>& n = state[k].normal;
    const Point<dim> lambda = given ? Point<dim>(friction_multipliers->traction[k] -
                                                 friction_multipliers->traction[k].dot(n) * n)
                                    : Point<dim>::Zero();
    trial[k] = lambda + problem.augmentation() * state[k].tangential_velocity;
  }
  return trial;
}

template <int dim>
void update_exact_slip_duals(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                             const VectorX& step, bool primal,
                             const assembly::FrictionMultipliers<dim>* friction_multipliers,
                             std::vector<Point<dim>>& slip_duals) {
  const std::vector<assembly::ContactPoint<dim>> state = problem.contact_state(u),
                                                 change = problem.contact_state(step);
  const std::vector<Point<dim>> trial = trial_tractions(problem, state, friction_multipliers);
  slip_duals.resize(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) {
    Point<dim>& lambda = slip_duals[k];
    const Real threshold = state[k].friction_threshold;
    if (threshold <= 0) {
      lambda.setZero();
      continue;
    }
    const Point<dim> trial_change = problem.augmentation() * change[k].tangential_velocity; // δt
    const Real size = trial[k].norm();
    if (size <= threshold) {
      lambda = (trial[k] + trial_change) / threshold; // stick: λ = t/τ_f is linear in t
    } else {
      if (primal) lambda = trial[k] / size;
      // Newton on |t| λ − t = 0: λ + δλ = (t + δt)/|t| − λ (t·δt)/|t|².
      lambda =
          (trial[k] + trial_change) / size - lambda * (trial[k].dot(trial_change) / (size * size));
    }
    if (lambda.norm() > 1.0) lambda.normalize();
  }
}

/// Calls `f(law_of)`, `law_of(cell, q)` the flow law at full-rule point q of `cell`: the
/// isothermal law bound once (one dispatch for the loop), or hot forming's law at the
/// point's temperature (FormingProblem::point_temperatures).
template <int dim, class F>
void for_each_point_law(const assembly::FormingProblem<dim>& problem, F&& f) {
  const std::vector<Real>& temperatures = problem.point_temperatures();
  if (temperatures.empty()) {
    problem.settings().law.visit_bound(
        [&](const auto& law) { f([&](Index, int) -> const auto& { return law; }); });
    return;
  }
  const int n_q = problem.full_rule().size();
  f([&](Index cell, int q) {
    return physics::FlowLawAt(problem.settings().law, temperatures[cell * n_q + q]);
  });
}

/// Cells per task of the point loops below (whose cells are independent: each writes
/// its own points' duals, so any split gives the same values).
constexpr Index cells_per_task = 512;

/// body(first, last) over consecutive ranges of the mesh's cells, on compute_threads().
/// A distributed run's ranks already take the machine's cores: one thread each.
template <int dim>
void for_cell_ranges(const assembly::FormingProblem<dim>& problem,
                     const std::function<void(Index, Index)>& body) {
  const Index n_cells = problem.mesh().n_cells();
  const Index n_tasks = std::max<Index>(1, (n_cells + cells_per_task - 1) / cells_per_task);
  const std::size_t threads =
      problem.discretisation().owned_dofs().distributed() ? 1 : compute_threads();
  run_tasks(static_cast<std::size_t>(n_tasks), threads, [&](std::size_t task) {
    const Index first = static_cast<Index>(task) * cells_per_task;
    body(first, std::min(n_cells, first + cells_per_task));
  });
}

} // namespace

template <int dim>
void update_duals(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                  const VectorX& step, const VectorX& next, assembly::NewtonDuals<dim>& all_duals,
                  const assembly::FrictionMultipliers<dim>* friction_multipliers) {
  const int n_q = problem.full_rule().size();
  const bool primal = all_duals.empty();
  if (problem.has_exact_friction())
    update_exact_slip_duals(problem, u, step, primal, friction_multipliers, all_duals.slip);
  else
    update_slip_duals(problem, u, step, primal, all_duals.slip);
  std::vector<Tensor3>& duals = all_duals.stress;
  duals.resize(static_cast<std::size_t>(problem.mesh().n_cells()) * n_q);
  // One law dispatch for the whole loop: it evaluates the law twice per point.
  for_each_point_law(problem, [&](const auto& law_of) {
    for_cell_ranges(problem, [&](Index first, Index last) {
      fem::CellValues<dim> values(problem.mesh().cell_type(), problem.full_rule());
      typename fem::CellValues<dim>::Gradients coordinates, velocities, step_velocities,
          next_velocities;
      for (Index cell = first; cell < last; ++cell) {
        if (!problem.discretisation().assembles(cell)) continue; // another rank's (its tangent)
        problem.gather(cell, &u, coordinates, velocities);
        problem.gather(cell, &step, coordinates, step_velocities);
        problem.gather(cell, &next, coordinates, next_velocities);
        problem.load_cell(cell, values, nullptr);
        for (int q = 0; q < n_q; ++q) {
          const auto& law = law_of(cell, q);
          const Tensor3 next_dev =
              physics::deviator(problem.strain_rate_at(values, next_velocities, q));
          const Real next_eps = std::sqrt(2.0 / 3.0 * next_dev.squaredNorm());
          Tensor3& w = duals[cell * n_q + q];
          // Where the law is linear the dual stress is just ν ė: nothing to gain.
          if (law.is_linear_at(next_eps)) {
            w = law.secant_viscosity(next_eps) * next_dev;
            continue;
          }
          const Tensor3 dev = physics::deviator(problem.strain_rate_at(values, velocities, q));
          const Real eps = std::sqrt(2.0 / 3.0 * dev.squaredNorm());
          const auto [nu, nu_derivative] = law.secant_viscosity_and_derivative(eps);
          if (primal) w = nu * dev;
          if (eps > 0) {
            // Newton on ε̄̇ w − σ_p(ε̄̇) ė = 0 at (u, w) along the step:
            // w + δw = ν ė + ν ė(δu) + (σ_p′ ė − w) dε̄̇/ε̄̇.
            const Tensor3 step_dev =
                physics::deviator(problem.strain_rate_at(values, step_velocities, q));
            const Real rate_change = 2.0 / 3.0 * dev.cwiseProduct(step_dev).sum() / eps; // dε̄̇
            w = nu * (dev + step_dev) + (nu_derivative * dev - w) * (rate_change / eps);
          } else {
            w = law.secant_viscosity(next_eps) * next_dev;
          }
          const Real cap = law.yield_stress(next_eps);
          const Real size = std::sqrt(2.0 / 3.0 * w.squaredNorm());
          if (size > cap) w *= cap / size;
        }
      }
    });
  });
}

template <int dim>
void secant_duals(const assembly::FormingProblem<dim>& problem, const VectorX* previous,
                  const VectorX& next, assembly::NewtonDuals<dim>& all_duals,
                  const assembly::FrictionMultipliers<dim>* friction_multipliers) {
  const int n_q = problem.full_rule().size();
  std::vector<Tensor3>& duals = all_duals.stress;
  duals.resize(static_cast<std::size_t>(problem.mesh().n_cells()) * n_q);
  for_each_point_law(problem, [&](const auto& law_of) {
    for_cell_ranges(problem, [&](Index first, Index last) {
      fem::CellValues<dim> values(problem.mesh().cell_type(), problem.full_rule());
      typename fem::CellValues<dim>::Gradients coordinates, previous_velocities, next_velocities;
      for (Index cell = first; cell < last; ++cell) {
        if (!problem.discretisation().assembles(cell)) continue; // another rank's (its tangent)
        if (previous) problem.gather(cell, previous, coordinates, previous_velocities);
        problem.gather(cell, &next, coordinates, next_velocities);
        problem.load_cell(cell, values, nullptr);
        for (int q = 0; q < n_q; ++q) {
          const auto& law = law_of(cell, q);
          const Tensor3 next_dev =
              physics::deviator(problem.strain_rate_at(values, next_velocities, q));
          const Real next_eps = std::sqrt(2.0 / 3.0 * next_dev.squaredNorm());
          Tensor3& w = duals[cell * n_q + q];
          if (law.is_linear_at(next_eps)) { // linear law: w = ν ė exactly
            w = law.secant_viscosity(next_eps) * next_dev;
            continue;
          }
          const Real previous_eps =
              previous ? physics::equivalent_strain_rate(
                             problem.strain_rate_at(values, previous_velocities, q))
                       : problem.settings().initial_rate;
          // The stress the secant solve balanced, ν(uⁿ⁻¹) ė(uⁿ), capped to the yield surface.
          w = law.secant_viscosity(previous_eps) * next_dev;
          const Real cap = law.yield_stress(next_eps);
          const Real size = std::sqrt(2.0 / 3.0 * w.squaredNorm());
          if (size > cap) w *= cap / size;
        }
      }
    });
  });
  // The slip direction the secant solve used, u_T(uⁿ)/s(uⁿ⁻¹), capped to |λ| ≤ 1.
  // The constant-viscosity solve had no friction (τ_f(0) = 0): λ = 0 there.
  const std::vector<assembly::ContactPoint<dim>> after = problem.contact_state(next);
  const std::vector<assembly::ContactPoint<dim>> before =
      previous ? problem.contact_state(*previous) : after;
  const Real d_t = problem.settings().friction.d_t;
  all_duals.slip.assign(after.size(), Point<dim>::Zero());
  if (problem.has_exact_friction()) {
    // The traction that secant step used over τ_f: s(previous) t(next)/τ_f = t(next)/max(τ_f,
    // |t|)(previous).
    if (!previous) return;
    const std::vector<Point<dim>> trial_after =
        trial_tractions(problem, after, friction_multipliers);
    const std::vector<Point<dim>> trial_before =
        trial_tractions(problem, before, friction_multipliers);
    for (std::size_t k = 0; k < after.size(); ++k) {
      const Real threshold = before[k].friction_threshold;
      if (threshold <= 0) continue;
      Point<dim>& lambda = all_duals.slip[k];
      lambda = trial_after[k] / std::max(threshold, trial_before[k].norm());
      if (lambda.norm() > 1.0) lambda.normalize();
    }
    return;
  }
  for (std::size_t k = 0; k < after.size() && previous; ++k) {
    const Real s = std::sqrt(before[k].tangential_velocity.squaredNorm() + d_t * d_t);
    Point<dim>& lambda = all_duals.slip[k];
    lambda = after[k].tangential_velocity / s;
    if (lambda.norm() > 1.0) lambda.normalize();
  }
}

template void update_duals<2>(const assembly::FormingProblem<2>&, const VectorX&, const VectorX&,
                              const VectorX&, assembly::NewtonDuals<2>&,
                              const assembly::FrictionMultipliers<2>*);
template void update_duals<3>(const assembly::FormingProblem<3>&, const VectorX&, const VectorX&,
                              const VectorX&, assembly::NewtonDuals<3>&,
                              const assembly::FrictionMultipliers<3>*);
template void secant_duals<2>(const assembly::FormingProblem<2>&, const VectorX*, const VectorX&,
                              assembly::NewtonDuals<2>&, const assembly::FrictionMultipliers<2>*);
template void secant_duals<3>(const assembly::FormingProblem<3>&, const VectorX*, const VectorX&,
                              assembly::NewtonDuals<3>&, const assembly::FrictionMultipliers<3>*);

} // namespace formflow::solvers
