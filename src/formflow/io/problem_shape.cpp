// SPDX-License-Identifier: MIT
// The case seen by the capability table, and the defaults of friction.stick and
// contact.normals that depend on it.
#include "formflow/io/problem_shape.hpp"

#include <fmt/format.h>

namespace formflow::io {

namespace {

/// The shape without the friction enforcement keys (stick_choice resolves those from it).
solvers::ProblemShape base_shape(const Case& case_) {
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
  shape.axisymmetric = case_.symmetry == physics::Symmetry::Axisymmetric;
  shape.method = case_.solver.method;
  shape.linear = case_.solver.linear;
  shape.linear_given = case_.key_locations.count("solver.linear") > 0;
  return shape;
}

} // namespace

StickChoice stick_choice(const Case& case_) {
  StickChoice choice;
  choice.stick_given = case_.friction_stick != StickEnforcement::Auto;
  // Programmatic cases (tests, studies built in code) have no key_locations: their
  // normals count as not given, and friction_stick = Augmented keeps face points.
  choice.normals_given = case_.key_locations.count("contact.normals") > 0;
  const bool given_faces =
      choice.normals_given && case_.contact.normals == assembly::ContactNormals::Faces;
  if (choice.stick_given)
    choice.stick = case_.friction_stick;
  else
    choice.stick = solvers::exact_stick_serves(base_shape(case_)) && !given_faces
                       ? StickEnforcement::Exact
                       : StickEnforcement::Augmented;
  choice.normals = !choice.normals_given && choice.stick == StickEnforcement::Exact
                       ? assembly::ContactNormals::Nodes
                       : case_.contact.normals;
  return choice;
}

std::optional<std::string> face_points_note(const Case& case_) {
  const StickChoice choice = stick_choice(case_);
  if (choice.stick_given || !choice.normals_given ||
      choice.normals != assembly::ContactNormals::Faces ||
      !solvers::exact_stick_serves(base_shape(case_)))
    return std::nullopt;
  const Case::KeyLocation& where = case_.key_locations.at("contact.normals");
  return fmt::format(
      "{}{}: contact.normals = \"faces\" with exact friction under Newton: the stuck points are "
      "held by the augmented loop's penalty (friction.stick = \"augmented\"), not by the "
      "semismooth Newton, which needs one multiplier per node (contact.normals = \"nodes\"; "
      "docs/friction.md)",
      where.file, where.line > 0 ? fmt::format(":{}", where.line) : "");
}

assembly::ContactSettings contact_settings(const Case& case_) {
  assembly::ContactSettings settings = case_.contact;
  settings.normals = stick_choice(case_).normals;
  return settings;
}

solvers::ProblemShape problem_shape(const Case& case_) {
  solvers::ProblemShape shape = base_shape(case_);
  const StickChoice choice = stick_choice(case_);
  shape.exact_stick = choice.stick == StickEnforcement::Exact;
  shape.nodal_contact = choice.normals == assembly::ContactNormals::Nodes;
  return shape;
}

} // namespace formflow::io
