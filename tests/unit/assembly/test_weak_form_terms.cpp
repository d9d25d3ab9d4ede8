// SPDX-License-Identifier: MIT
// The weak-form terms agree with themselves across the assembler's passes: each term
// writes its internal force twice (from its secant matrix, K_e u_e − F_e, in the
// tangent pass; from the stresses in the force pass) and its power once; the three
// must be one form. Run for every term set Newton covers: penalty and condensed
// mixed, plane and axisymmetric, regularised and exact friction, Coulomb and Tresca.
#include "formflow/assembly/forming_problem.hpp"
#include "support/newton_fixture.hpp"

#include <gtest/gtest.h>

#include <string>

namespace formflow::testing {
namespace {

struct TermCase {
  std::string name;
  physics::Symmetry symmetry = physics::Symmetry::Plane;
  physics::FrictionRegularization regularization = physics::FrictionRegularization::Regularized;
  physics::FrictionLaw law = physics::FrictionLaw::Coulomb;
  bool mixed = false;
};

std::ostream& operator<<(std::ostream& out, const TermCase& c) {
  return out << c.name;
}

class WeakFormTerms : public ::testing::TestWithParam<TermCase> {
protected:
  static assembly::ProblemSettings settings_for(const TermCase& c) {
    assembly::ProblemSettings settings;
    settings.law = sensitive_law();
    settings.symmetry = c.symmetry;
    settings.friction.law = c.law;
    settings.friction.mu = 0.2;
    settings.friction.m = 0.5;
    settings.friction.d_t = 0.05;
    settings.friction.regularization = c.regularization;
    settings.friction.augmentation = 1.0;
    settings.penalty.d = 0.1;
    settings.penalty.d_n = 0.1;
    return settings;
  }
};

/// The assembled secant system at w = u as one dense matrix over all dofs (free and
/// prescribed rows and columns), for the round-off bound Σ_j |K_ij| |u_j| + |F_i|.
MatrixX full_matrix(const assembly::FormingProblem<2>& problem, const assembly::LinearSystem& s) {
  const assembly::ScatterPlan& plan = problem.plan();
  const Index n = plan.n_dofs();
  MatrixX k = MatrixX::Zero(n, n);
  const MatrixX free = MatrixX(assembly::SparseMatrix(s.matrix.selfadjointView<Eigen::Lower>()));
  const MatrixX reactions = MatrixX(s.reaction_rows);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) {
      const Index fi = plan.free_index(i), fj = plan.free_index(j);
      if (fi >= 0 && fj >= 0)
        k(i, j) = free(fi, fj);
      else if (fi < 0)
        k(i, j) = reactions(plan.prescribed_index(i), j);
      else
        k(i, j) = reactions(plan.prescribed_index(j), i); // symmetric
    }
  return k;
}

TEST_P(WeakFormTerms, ForceFromTheMatrixEqualsForceFromTheStressesAndPowerIsItsWork) {
  const TermCase& c = GetParam();
  SmallExtrusion extrusion(settings_for(c));
  if (c.mixed) extrusion.attach_mixed_pressure(fem::PressureSpace::P1disc);
  const assembly::FormingProblem<2>& problem = *extrusion.problem;
  const VectorX& u = extrusion.u;

  // Exact friction at a nonzero frozen multiplier λ̂, so that its load is exercised.
  assembly::FrictionMultipliers<2> multipliers;
  if (c.regularization == physics::FrictionRegularization::None) {
    const std::vector<assembly::ContactPoint<2>> points = problem.contact_state(u);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Point<2> tangent(-points[k].normal[1], points[k].normal[0]);
      multipliers.traction.push_back(0.05 * std::sin(1.0 + k) * tangent);
    }
    extrusion.friction_multipliers = &multipliers;
  }
  const std::vector<Real> thresholds = problem.friction_thresholds(u);
  VectorX stress_force, matrix_force;
  problem.assemble_newton(u, thresholds, {}, stress_force, nullptr, nullptr,
                          extrusion.friction_multipliers);
  assembly::LinearSystem tangent = problem.plan().make_system();
  problem.assemble_newton(u, thresholds, {}, matrix_force, &tangent, nullptr,
                          extrusion.friction_multipliers);

  // Round-off bound: every entry of f is a sum of at most n_q · (cells per node) · n_local
  // = 9 · 4 · 18 < 10³ products, each below |K_ij u_j| or |F_i| in size; their rounding
  // is ≤ 10³ ε (Σ_j |K_ij| |u_j| + |F_i|) (Higham, §3.1).
  assembly::LinearSystem secant = problem.plan().make_system();
  problem.assemble(&u, secant, extrusion.friction_multipliers);
  const MatrixX k = full_matrix(problem, secant);
  // F itself: the rhs of a free row is F_f − K_fc u_c.
  VectorX prescribed_part = VectorX::Zero(u.size());
  for (Index dof = 0; dof < u.size(); ++dof)
    if (problem.plan().free_index(dof) < 0) prescribed_part[dof] = u[dof];
  const VectorX moved = k * prescribed_part;
  VectorX load(u.size());
  for (Index dof = 0; dof < u.size(); ++dof) {
    const Index free = problem.plan().free_index(dof);
    load[dof] = free >= 0 ? secant.rhs[free] + moved[dof]
                          : secant.prescribed_loads[problem.plan().prescribed_index(dof)];
  }
  const VectorX scale = k.cwiseAbs() * u.cwiseAbs() + load.cwiseAbs();
  const Real eps = std::numeric_limits<Real>::epsilon();
  ASSERT_GT(stress_force.cwiseAbs().maxCoeff(), 0.0);
  for (Index i = 0; i < u.size(); ++i)
    EXPECT_NEAR(stress_force[i], matrix_force[i], 1e3 * eps * scale[i]) << "dof " << i;

  // The powers of the terms sum to the work of the internal force, u·f(u) (each term's
  // power is its own u·f: a(u; u, u), ∫ ε̇_V²/d, cᵀBu, ∫ u_N²/d_N, ∫ λ_T·u_T).
  const assembly::PowerTerms power =
      problem.powers(u, problem.contact_state(u, extrusion.friction_multipliers));
  const Real work = u.dot(stress_force);
  EXPECT_NEAR(power.total(), work, 1e3 * eps * u.cwiseAbs().dot(scale));
  EXPECT_GT(power.friction, 0.0);
  EXPECT_GT(power.contact_penalty, 0.0);
  EXPECT_GT(power.volumetric_penalty, 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Terms, WeakFormTerms,
    ::testing::Values(TermCase{"PenaltyRegularisedCoulomb"},
                      TermCase{"PenaltyExactCoulomb", physics::Symmetry::Plane,
                               physics::FrictionRegularization::None},
                      TermCase{"PenaltyRegularisedTresca", physics::Symmetry::Plane,
                               physics::FrictionRegularization::Regularized,
                               physics::FrictionLaw::Tresca},
                      TermCase{"AxisymmetricRegularisedCoulomb", physics::Symmetry::Axisymmetric},
                      TermCase{"AxisymmetricExactHybrid", physics::Symmetry::Axisymmetric,
                               physics::FrictionRegularization::None, physics::FrictionLaw::Hybrid},
                      TermCase{"CondensedMixedRegularisedCoulomb", physics::Symmetry::Plane,
                               physics::FrictionRegularization::Regularized,
                               physics::FrictionLaw::Coulomb, true}),
    [](const auto& info) { return info.param.name; });

} // namespace
} // namespace formflow::testing
