// SPDX-License-Identifier: MIT
// The weak-form terms of one problem, chosen once from its settings: the one place
// that decides which terms a formulation, a contact treatment and a friction law add.
#pragma once

#include "formflow/assembly/discretisation.hpp"
#include "formflow/assembly/problem_settings.hpp"
#include "formflow/assembly/terms/terms.hpp"

#include <memory>
#include <vector>

namespace formflow::assembly {

template <int dim> struct TermSet {
  std::vector<std::unique_ptr<CellTerm<dim>>> cell;
  std::vector<std::unique_ptr<FaceTerm<dim>>> face;
  /// Simplices before their pressure space is attached (FormingProblem builds its terms
  /// in its constructor, then again in attach_multipliers): no pressure term yet, and
  /// nothing may be assembled with this set.
  bool awaits_pressure = false;

  /// Some term puts loads into F (then the assembler scatters the local loads).
  bool has_loads() const;
  /// Every term can be linearised by Newton.
  bool newton_ready() const;
  /// The term whose multiplier is σ_H (exactly one in every problem).
  const CellTerm<dim>& pressure() const;
};

/// Registration: the viscous term; one pressure term (the volumetric penalty, or the
/// mixed formulation's condensed, augmented or global pressure from `multipliers`); a
/// body force when given; the contact penalty or, for d_N = 0, the augmented contact;
/// friction where some part has a law that does not vanish.
template <int dim>
TermSet<dim> make_terms(const ProblemSettings& settings, const Discretisation<dim>& discretisation,
                        ConstraintMultipliers<dim>* multipliers, const BodyForce<dim>& body_force,
                        Real friction_augmentation);

} // namespace formflow::assembly
