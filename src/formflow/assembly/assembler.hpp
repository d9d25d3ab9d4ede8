// SPDX-License-Identifier: MIT
// The one assembly loop: over the cells (and their Γ3 faces), every weak-form term of
// the problem's TermSet, into a sink. The secant system, Newton's residual and
// tangent, the powers and σ_H are passes of this loop, not loops of their own.
#pragma once

#include "formflow/assembly/assembly_sink.hpp"
#include "formflow/assembly/cell_schedule.hpp"
#include "formflow/assembly/discretisation.hpp"
#include "formflow/assembly/terms/term_set.hpp"

#include <span>

namespace formflow::assembly {

enum class AssemblyPass {
  Secant,  ///< K(w) and F (add_matrix, add_load)
  Force,   ///< f(u) = K(u) u − F only (add_force): one pass over the points, no matrix
  Tangent, ///< f(u) and the symmetric Jacobian part (add_force, add_matrix) + the coupling
  Power,   ///< the terms' powers at u (no sink)
};

template <int dim> struct AssemblyRequest {
  AssemblyPass pass = AssemblyPass::Secant;
  /// Full dof vector; null only for Secant: the constant viscosity `initial_viscosity`.
  const VectorX* velocity = nullptr;
  Real initial_viscosity = 0.0;
  /// Γ3 points in contact_state() order; empty: none (the face terms that need them skip).
  std::span<const ContactPoint<dim>> contact;
  const NewtonDuals<dim>* duals = nullptr;     ///< Tangent: null or empty is the primal choice
  UnsymmetricTangent<dim>* coupling = nullptr; ///< Tangent: the unsymmetric rest, if wanted
  /// A distributed run's Secant, Force and Tangent passes visit the rank's own cells
  /// only (the caller adds the ranks' results up); true: every cell, as on one rank
  /// (a per-cell quantity wanted whole on every rank).
  bool every_cell = false;
};

/// One thread's working memory of the cell loop (assembler.cpp).
template <int dim> struct CellScratch;

template <int dim> class Assembler {
public:
  /// `temperatures`: hot forming's T per full-rule point (cell-major), read at every pass;
  /// empty: the isothermal law (the path of every isothermal run, unchanged).
  Assembler(const Discretisation<dim>& discretisation, const physics::FlowLaw& law,
            const TermSet<dim>& terms, const std::vector<Real>& temperatures);

  /// Runs `request.pass` over every cell into `sink` (null for Power) and, for Power,
  /// adds the terms' powers to `powers`. The cells go in the order of a CellSchedule
  /// (assembly/cell_schedule.hpp), its blocks on compute_threads() threads when the sink
  /// takes concurrent cells: the same results, bit for bit, on any number of threads.
  /// The Power pass (a sum over the cells) and a distributed run's every-cell pass go
  /// one cell after the other in mesh order.
  void run(const AssemblyRequest<dim>& request, AssemblySink* sink,
           PowerTerms* powers = nullptr) const;
  /// σ_H of every cell at the velocity `u`, from the pressure term.
  std::vector<CellPressure> pressures(const VectorX& u) const;
  /// The plastic dissipation density σ_p(ε̄̇) ε̄̇ at every full-rule point (cell-major) at
  /// `u`: the integrand of PowerTerms::plastic_dissipation, point by point (hot forming's
  /// heat source).
  std::vector<Real> dissipation_density(const VectorX& u) const;

private:
  void assemble_cell(CellScratch<dim>& scratch, Index cell, const AssemblyRequest<dim>& request,
                     AssemblySink* sink, PowerTerms* powers,
                     UnsymmetricTangent<dim>* coupling) const;

  const Discretisation<dim>& discretisation_;
  const physics::FlowLaw& law_;
  const TermSet<dim>& terms_;
  const std::vector<Real>& temperatures_;
  CellSchedule schedule_; ///< of the assembled cells
};

} // namespace formflow::assembly
