// SPDX-License-Identifier: MIT
// Shared by the Newton-system tests: a small extrusion at a velocity far from the
// solution, its residual and Jacobian over the free dofs, and central finite
// differences to check the one against the other.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "support/random_vector.hpp"

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace formflow::testing {

/// A strongly rate-sensitive law whose power range covers every rate in these
/// tests, so that ν′ is large and smooth (the break points would make FD one-sided).
inline physics::FlowLaw sensitive_law() {
  physics::FlowLaw law;
  law.as<physics::PiecewisePower>().A = 2.0;
  law.as<physics::PiecewisePower>().alpha = 0.25;
  law.rate1 = 1e-8;
  law.rate2 = 1e8;
  return law;
}

/// Central differences, the step scaled by 1 + max|u|.
inline MatrixX finite_difference_jacobian(const std::function<VectorX(const VectorX&)>& residual,
                                          const VectorX& u, double h) {
  MatrixX jacobian(u.size(), u.size());
  const double step = h * (1.0 + u.cwiseAbs().maxCoeff());
  for (Index k = 0; k < u.size(); ++k) {
    VectorX plus = u, minus = u;
    plus[k] += step;
    minus[k] -= step;
    jacobian.col(k) = (residual(plus) - residual(minus)) / (2 * step);
  }
  return jacobian;
}

// Central differences with h = 1e-6 on O(1) smooth functions carry truncation
// error ~h² and cancellation ~1e-16/h ≈ 1e-10 relative to ‖J‖: 1e-7 separates
// an exact tangent from one missing any term (the ν′ term is O(α) = 25 % here).
constexpr double fd_tolerance = 1e-7;

/// The plane channel 2 × 2 → 1 of the Newton-system tests, Q2, h = 1.
inline mesh::Mesh<2> small_channel_mesh() {
  return mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 1.0, 2);
}

/// A small extrusion (default: small_channel_mesh()) with the given settings, the
/// penalties and d_T raised by the caller so that the residual is smooth on the
/// finite-difference scale, and a velocity 0.3 × random away from the Dirichlet
/// data (prescribed values kept). `friction_multipliers` (exact friction, not
/// owned, may be null) are passed to every Newton assembly.
template <int dim> struct SmallExtrusionIn {
  mesh::Mesh<dim> mesh;
  assembly::ProblemSettings settings;
  std::unique_ptr<assembly::FormingProblem<dim>> problem;
  VectorX u;
  const assembly::FrictionMultipliers<dim>* friction_multipliers = nullptr;
  std::unique_ptr<assembly::ConstraintMultipliers<dim>> mixed_pressure;

  explicit SmallExtrusionIn(const assembly::ProblemSettings& settings_, mesh::Mesh<dim> mesh_)
      : mesh(std::move(mesh_)), settings(settings_) {
    problem = std::make_unique<assembly::FormingProblem<dim>>(mesh, settings);
    const assembly::ScatterPlan& plan = problem->plan();
    u = problem->constraints().values + 0.3 * random_vector(problem->n_dofs(), 5);
    for (Index dof = 0; dof < plan.n_dofs(); ++dof)
      if (plan.free_index(dof) < 0) u[dof] = problem->constraints().values[dof];
  }
  /// The mixed formulation (3.7) with its pressure condensed at d = settings.penalty.d.
  void attach_mixed_pressure(fem::PressureSpace space) {
    assembly::Formulation formulation;
    formulation.type = assembly::FormulationType::Mixed;
    formulation.pressure = space;
    mixed_pressure = std::make_unique<assembly::ConstraintMultipliers<dim>>(
        mesh, settings.penalty, formulation, problem->full_rule(), problem->n_contact_points());
    problem->attach_multipliers(mixed_pressure.get());
  }
  VectorX free_part(const VectorX& full) const {
    VectorX free_values(problem->plan().n_free());
    for (Index dof = 0; dof < problem->plan().n_dofs(); ++dof)
      if (problem->plan().free_index(dof) >= 0)
        free_values[problem->plan().free_index(dof)] = full[dof];
    return free_values;
  }
  /// R(u_f) on the free dofs (the residual-only path), with τ_f frozen at
  /// `thresholds`, or with τ_f(u) when they are null (the exact residual).
  VectorX free_residual(const VectorX& free_u, const std::vector<Real>* thresholds) const {
    const VectorX full = problem->plan().expand(free_u, problem->constraints().values);
    VectorX force;
    problem->assemble_newton(full, thresholds ? *thresholds : problem->friction_thresholds(full),
                             {}, force, nullptr, nullptr, friction_multipliers);
    return free_part(force);
  }
  /// T + N at u as a dense matrix over the free dofs (T alone in `symmetric_part`).
  MatrixX jacobian(const std::vector<Real>& thresholds, MatrixX* symmetric_part = nullptr) const {
    assembly::LinearSystem tangent = problem->plan().make_system();
    assembly::UnsymmetricTangent<dim> coupling;
    VectorX force;
    problem->assemble_newton(u, thresholds, {}, force, &tangent, &coupling, friction_multipliers);
    const MatrixX t =
        MatrixX(assembly::SparseMatrix(tangent.matrix.selfadjointView<Eigen::Lower>()));
    if (symmetric_part) *symmetric_part = t;
    MatrixX j = t;
    for (Index k = 0; k < j.cols(); ++k) {
      VectorX column = j.col(k);
      problem->apply_coupling(coupling, VectorX::Unit(j.cols(), k), column);
      j.col(k) = column;
    }
    return j;
  }
};

/// The plane small extrusion of most Newton-system tests.
struct SmallExtrusion : SmallExtrusionIn<2> {
  explicit SmallExtrusion(const assembly::ProblemSettings& settings_)
      : SmallExtrusionIn<2>(settings_, small_channel_mesh()) {}
};

} // namespace formflow::testing
