// SPDX-License-Identifier: MIT
// The case seen by the capability table.
#include "formflow/io/problem_shape.hpp"

namespace formflow::io {

solvers::ProblemShape problem_shape(const Case& case_) {
  solvers::ProblemShape shape;
  shape.mixed = case_.formulation.type == assembly::FormulationType::Mixed;
  shape.discontinuous_saddle_point =
      shape.mixed && fem::is_discontinuous(case_.formulation.pressure) &&
      case_.formulation.discontinuous == assembly::DiscontinuousPressure::SaddlePoint;
  shape.global_pressure = shape.mixed && (!fem::is_discontinuous(case_.formulation.pressure) ||
                                          shape.discontinuous_saddle_point);
  shape.exact_incompressibility = case_.penalty.d == 0;
  shape.exact_contact = case_.penalty.d_n == 0;
  shape.exact_friction = case_.friction.regularization == physics::FrictionRegularization::None;
  shape.exact_stick = case_.friction_stick == StickEnforcement::Exact;
  shape.nodal_contact = case_.contact.normals == assembly::ContactNormals::Nodes;
  shape.axisymmetric = case_.symmetry == physics::Symmetry::Axisymmetric;
  shape.method = case_.solver.method;
  shape.linear = case_.solver.linear;
  shape.linear_given = case_.key_locations.count("solver.linear") > 0;
  return shape;
}

} // namespace formflow::io
