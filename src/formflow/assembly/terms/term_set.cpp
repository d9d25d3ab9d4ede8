// SPDX-License-Identifier: MIT
// Which weak-form terms a problem has.
#include "formflow/assembly/terms/term_set.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>

namespace formflow::assembly {

template <int dim> bool TermSet<dim>::has_loads() const {
  return std::any_of(cell.begin(), cell.end(), [](const auto& t) { return t->has_loads(); }) ||
         std::any_of(face.begin(), face.end(), [](const auto& t) { return t->has_loads(); });
}

template <int dim> bool TermSet<dim>::newton_ready() const {
  return std::all_of(cell.begin(), cell.end(), [](const auto& t) { return t->newton_ready(); }) &&
         std::all_of(face.begin(), face.end(), [](const auto& t) { return t->newton_ready(); });
}

template <int dim> const CellTerm<dim>& TermSet<dim>::pressure() const {
  const auto term =
      std::find_if(cell.begin(), cell.end(), [](const auto& t) { return t->carries_pressure(); });
  FF_ASSERT(term != cell.end(), "every problem has a pressure term");
  return **term;
}

template <int dim>
TermSet<dim> make_terms(const ProblemSettings& settings, const Discretisation<dim>& discretisation,
                        ConstraintMultipliers<dim>* multipliers, const BodyForce<dim>& body_force,
                        Real friction_augmentation) {
  const mesh::Mesh<dim>& mesh = discretisation.mesh();
  const bool axisymmetric = discretisation.axisymmetric();
  TermSet<dim> terms;
  terms.cell.push_back(make_viscous_term<dim>(settings.law, settings.viscous_strain, axisymmetric));
  if (multipliers && multipliers->has_pressure_space()) {
    // Axisymmetry is in the multipliers' cell matrices (the hoop rate in B).
    if (multipliers->has_global_pressure())
      terms.cell.push_back(make_global_pressure_term<dim>(*multipliers, mesh.cell_type()));
    else if (multipliers->is_exact_pressure())
      terms.cell.push_back(make_augmented_pressure_term<dim>(*multipliers, mesh.cell_type()));
    else
      terms.cell.push_back(make_condensed_pressure_term<dim>(*multipliers, mesh.cell_type()));
  } else if (mesh.is_simplex()) {
    // Simplices take σ_H in a pressure space (no reduced rule of the penalty term
    // spares them locking): until it is attached, this set is not assembled.
    terms.awaits_pressure = true;
  } else {
    terms.cell.push_back(make_volumetric_penalty_term<dim>(settings.penalty.d, axisymmetric,
                                                           mesh.order, settings.volumetric_points));
  }
  if (body_force) terms.cell.push_back(make_body_force_term<dim>(body_force));
  if (multipliers && multipliers->is_exact_contact())
    terms.face.push_back(make_augmented_contact_term<dim>(*multipliers));
  else
    terms.face.push_back(make_contact_penalty_term<dim>(settings.penalty.d_n));
  if (!physics::friction_vanishes(settings.friction))
    terms.face.push_back(make_friction_term<dim>(settings.friction, friction_augmentation));
  return terms;
}

template struct TermSet<2>;
template struct TermSet<3>;
template TermSet<2> make_terms<2>(const ProblemSettings&, const Discretisation<2>&,
                                  ConstraintMultipliers<2>*, const BodyForce<2>&, Real);
template TermSet<3> make_terms<3>(const ProblemSettings&, const Discretisation<3>&,
                                  ConstraintMultipliers<3>*, const BodyForce<3>&, Real);

} // namespace formflow::assembly
