// SPDX-License-Identifier: MIT
// The cell loop shared by every pass: gather, map (from the geometry cache), evaluate
// the flow law once per point, then ask each term.
#include "formflow/assembly/assembler.hpp"

#include "formflow/core/error.hpp"
#include "formflow/core/parallel_tasks.hpp"
#include "formflow/physics/kinematics.hpp"

#include <algorithm>

namespace formflow::assembly {

/// One thread's working memory of the cell loop: the mapped values, the gathered
/// fields, the local matrix and vectors, the points' law values, and the CellState
/// the terms read (it refers to the members above).
template <int dim> struct CellScratch {
  CellScratch(const Discretisation<dim>& discretisation, int n_local, int n_q)
      : full(discretisation.mesh().cell_type(), discretisation.full_rule()),
        volumetric(discretisation.mesh().cell_type(), discretisation.volumetric_rule()),
        face_values(discretisation.mesh().cell_type(), discretisation.facet_rule()),
        matrix(n_local, n_local), load(n_local), force(n_local), viscosity(n_q), a(n_q), b(n_q),
        rates(n_q), deviators(n_q),
        duals(n_q), cell_state{0,          full,      volumetric, coordinates,
                               velocities, viscosity, rates,      {deviators, duals, a, b}} {}
  CellScratch(const CellScratch&) = delete;
  CellScratch& operator=(const CellScratch&) = delete;

  fem::CellValues<dim> full, volumetric;
  fem::FacetValues<dim> face_values;
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  MatrixX matrix;
  VectorX load;
  CellVector force;
  std::vector<Real> viscosity, a, b;
  std::vector<Tensor3> rates, deviators, duals;
  CellState<dim> cell_state;
};

namespace {

/// Cells per block of the schedule: blocks of about this many cells (at most 16), so a
/// mesh of fewer than twice as many is one block and assembled by one thread (a thread
/// costs more to start than such a loop takes). Mesh-dependent only: the results do not
/// depend on the machine's threads (assembly/cell_schedule.hpp).
constexpr Index cells_per_block = 512;
constexpr int max_blocks = 16;

} // namespace

template <int dim>
Assembler<dim>::Assembler(const Discretisation<dim>& discretisation, const physics::FlowLaw& law,
                          const TermSet<dim>& terms, const std::vector<Real>& temperatures)
    : discretisation_(discretisation), law_(law), terms_(terms), temperatures_(temperatures) {
  const std::vector<Index>& assembled = discretisation_.assembled_cells();
  const int n_blocks = static_cast<int>(
      std::clamp<Index>(static_cast<Index>(assembled.size()) / cells_per_block, 1, max_blocks));
  schedule_ =
      make_cell_schedule(discretisation_.mesh(), std::span<const Index>(assembled), n_blocks);
}

template <int dim>
void Assembler<dim>::run(const AssemblyRequest<dim>& request, AssemblySink* sink,
                         PowerTerms* powers) const {
  const AssemblyPass pass = request.pass;
  FF_ASSERT(!terms_.awaits_pressure, "simplices are assembled with their pressure space");
  FF_ASSERT(request.velocity || pass == AssemblyPass::Secant, "only the start has no velocity");
  FF_ASSERT((pass == AssemblyPass::Power) == (sink == nullptr), "a sink for every pass but Power");
  const bool with_force = pass == AssemblyPass::Force || pass == AssemblyPass::Tangent;
  FF_ASSERT(!with_force || terms_.newton_ready(), "Newton covers these terms only");
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  const int n_q = discretisation_.full_rule().size();
  const int n_local = mesh.nodes_per_cell() * dim;
  const auto assemble = [&](CellScratch<dim>& scratch, Index cell,
                            UnsymmetricTangent<dim>* coupling) {
    assemble_cell(scratch, cell, request, sink, powers, coupling);
  };

  // A distributed run (issue 20) assembles the matrices, loads, internal forces and powers
  // of its own cells only: the ranks' systems add up in the distributed matrix, their
  // forces in FormingProblem::assemble_newton, their powers in FormingProblem::powers.
  // The powers (a sum over the cells) and a distributed run's every-cell pass go cell by
  // cell in mesh order.
  const bool own_cells_only = !request.every_cell;
  if (pass == AssemblyPass::Power ||
      (!own_cells_only && discretisation_.owned_dofs().distributed())) {
    CellScratch<dim> scratch(discretisation_, n_local, n_q);
    const std::vector<Index>& assembled = discretisation_.assembled_cells();
    const Index n_loop = own_cells_only ? static_cast<Index>(assembled.size()) : mesh.n_cells();
    for (Index k = 0; k < n_loop; ++k)
      assemble(scratch, own_cells_only ? assembled[k] : k, request.coupling);
    return;
  }
  // Phase after phase, each phase's blocks on the machine's threads where the sink allows
  // it. The coupling's points go in the same order: each block's own list, appended in
  // block order.
  // A distributed run's ranks already take the machine's cores: one thread each.
  const bool own_threads = sink->concurrent() && !discretisation_.owned_dofs().distributed();
  const std::size_t threads = own_threads ? compute_threads() : 1;
  // Where each block's coupling points start (UnsymmetricTangent::phase_starts).
  const auto point_count = [&] { return request.coupling ? request.coupling->cells.size() : 0; };
  for (const std::vector<std::vector<Index>>& blocks : schedule_.phases) {
    const std::size_t n_blocks = blocks.size();
    std::vector<std::size_t> starts{point_count()};
    if (threads == 1 || n_blocks == 1) { // one thread: the points straight into the coupling
      CellScratch<dim> scratch(discretisation_, n_local, n_q);
      for (const std::vector<Index>& block : blocks) {
        for (const Index cell : block) assemble(scratch, cell, request.coupling);
        starts.push_back(point_count());
      }
      if (request.coupling) request.coupling->phase_starts.push_back(std::move(starts));
      continue;
    }
    std::vector<UnsymmetricTangent<dim>> block_coupling(request.coupling ? n_blocks : 0);
    run_tasks(n_blocks, threads, [&](std::size_t block) {
      CellScratch<dim> scratch(discretisation_, n_local, n_q);
      UnsymmetricTangent<dim>* coupling = request.coupling ? &block_coupling[block] : nullptr;
      for (const Index cell : blocks[block]) assemble(scratch, cell, coupling);
    });
    if (!request.coupling) continue;
    UnsymmetricTangent<dim>& whole = *request.coupling;
    for (const UnsymmetricTangent<dim>& part : block_coupling) {
      whole.cells.insert(whole.cells.end(), part.cells.begin(), part.cells.end());
      whole.coefficients.insert(whole.coefficients.end(), part.coefficients.begin(),
                                part.coefficients.end());
      whole.rows.insert(whole.rows.end(), part.rows.begin(), part.rows.end());
      starts.push_back(point_count());
    }
    whole.phase_starts.push_back(std::move(starts));
  }
}

template <int dim>
void Assembler<dim>::assemble_cell(CellScratch<dim>& scratch, Index cell,
                                   const AssemblyRequest<dim>& request, AssemblySink* sink,
                                   PowerTerms* powers, UnsymmetricTangent<dim>* coupling) const {
  const AssemblyPass pass = request.pass;
  const int n_q = discretisation_.full_rule().size();
  const int n_face_q = discretisation_.facet_rule().size();
  const int n_local = discretisation_.mesh().nodes_per_cell() * dim;
  const bool tangent = pass == AssemblyPass::Tangent;
  const bool with_loads = terms_.has_loads();
  const bool primal = !request.duals || request.duals->empty();
  fem::CellValues<dim>& full = scratch.full;
  fem::CellValues<dim>& volumetric = scratch.volumetric;
  fem::FacetValues<dim>& face_values = scratch.face_values;
  typename fem::CellValues<dim>::Gradients& coordinates = scratch.coordinates;
  typename fem::CellValues<dim>::Gradients& velocities = scratch.velocities;
  MatrixX& matrix = scratch.matrix;
  VectorX& load = scratch.load;
  CellVector& force = scratch.force;
  std::vector<Real>& viscosity = scratch.viscosity;
  std::vector<Real>& a = scratch.a;
  std::vector<Real>& b = scratch.b;
  std::vector<Tensor3>& rates = scratch.rates;
  std::vector<Tensor3>& deviators = scratch.deviators;
  std::vector<Tensor3>& duals = scratch.duals;
  CellState<dim>& cell_state = scratch.cell_state;

  // Each face term's view of face `position` (values mapped by the caller).
  auto face_state = [&](Index position) {
    std::span<const ContactPoint<dim>> points;
    if (!request.contact.empty()) points = request.contact.subspan(position * n_face_q, n_face_q);
    std::span<const Point<dim>> slip;
    if (tangent && !primal)
      slip =
          std::span<const Point<dim>>(request.duals->slip).subspan(position * n_face_q, n_face_q);
    return FaceState<dim>{cell, position, face_values, velocities, points, slip};
  };

  discretisation_.gather(cell, request.velocity, coordinates, velocities);
  discretisation_.load_cell(cell, full, &volumetric);
  cell_state.cell = cell;
  cell_state.temperatures = {};
  // The flow law of point q: the isothermal law itself, or (hot forming) the law at
  // the point's temperature. One body for both, so the isothermal path is unchanged.
  const auto evaluate_points = [&](const auto& law_at) {
    for (int q = 0; q < n_q; ++q) {
      if (!request.velocity) {
        viscosity[q] = request.initial_viscosity;
        continue;
      }
      const Tensor3 rate = discretisation_.strain_rate_at(full, velocities, q);
      const Real equivalent = physics::equivalent_strain_rate(rate);
      if (pass == AssemblyPass::Secant) {
        viscosity[q] = law_at(q).secant_viscosity(equivalent);
        continue;
      }
      rates[q] = rate;
      if (!tangent) {
        viscosity[q] = law_at(q).secant_viscosity(equivalent);
        continue;
      }
      const auto [secant, derivative] = law_at(q).secant_viscosity_and_derivative(equivalent);
      viscosity[q] = secant;
      deviators[q] = physics::deviator(rate);
      duals[q] = primal ? Tensor3(secant * deviators[q]) : request.duals->stress[cell * n_q + q];
      // a = (4/9) σ_p′/ε̄̇², b = −(4/9)/ε̄̇² (kernels/tangent_kernels.hpp); at ε̄̇ = 0 the
      // law is on its linear branch and the secant matrix is already the tangent.
      const Real scale = equivalent > 0 ? 4.0 / 9.0 / (equivalent * equivalent) : 0.0;
      a[q] = scale * derivative;
      b[q] = -scale;
    }
  };
  if (temperatures_.empty()) {
    evaluate_points([&](int) -> const physics::FlowLaw& { return law_; });
  } else {
    const Real* cell_temperatures = temperatures_.data() + cell * n_q;
    cell_state.temperatures = std::span<const Real>(cell_temperatures, n_q);
    evaluate_points([&](int q) { return physics::FlowLawAt(law_, cell_temperatures[q]); });
  }
  const auto faces = discretisation_.cell_contact_faces(cell);

  if (pass == AssemblyPass::Power) {
    for (const auto& term : terms_.cell) term->add_power(cell_state, *powers);
    for (const Index position : faces) {
      discretisation_.reinit_contact(face_values, coordinates, position);
      for (const auto& term : terms_.face) term->add_power(face_state(position), *powers);
    }
    return;
  }
  if (pass == AssemblyPass::Force) {
    force.setZero(n_local);
    for (const auto& term : terms_.cell) term->add_force(cell_state, force);
    for (const Index position : faces) {
      discretisation_.reinit_contact(face_values, coordinates, position);
      for (const auto& term : terms_.face) term->add_force(face_state(position), force);
    }
    sink->add_force(cell, force);
    return;
  }

  // Secant and tangent: the secant matrix K_e and loads F_e first.
  matrix.setZero();
  load.setZero();
  for (const auto& term : terms_.cell) term->add_secant(cell_state, matrix, load);
  for (const Index position : faces) {
    discretisation_.reinit_contact(face_values, coordinates, position);
    for (const auto& term : terms_.face) term->add_secant(face_state(position), matrix, load);
  }
  if (!tangent) {
    sink->add_matrix(cell, matrix);
    if (with_loads) sink->add_load(cell, load);
    return;
  }
  // The secant matrix at u gives the force K_e(u) u_e − F_e; the tangent adds to it.
  force.noalias() = matrix * cell_state.local_velocity() - load;
  for (const auto& term : terms_.cell) term->add_tangent(cell_state, matrix);
  for (const Index position : faces) {
    discretisation_.reinit_contact(face_values, coordinates, position);
    for (const auto& term : terms_.face) term->add_tangent(face_state(position), matrix);
  }
  sink->add_matrix(cell, matrix);
  sink->add_force(cell, force);
  if (coupling)
    for (const auto& term : terms_.cell) term->add_coupling(cell_state, *coupling);
}

template <int dim> std::vector<CellPressure> Assembler<dim>::pressures(const VectorX& u) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  fem::CellValues<dim> full(mesh.cell_type(), discretisation_.full_rule());
  fem::CellValues<dim> volumetric(mesh.cell_type(), discretisation_.volumetric_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  std::vector<CellPressure> result;
  result.reserve(mesh.n_cells());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation_.gather(cell, &u, coordinates, velocities);
    discretisation_.load_cell(cell, full, &volumetric);
    const CellState<dim> state{cell, full, volumetric, coordinates, velocities, {}, {}, {}};
    result.push_back(terms_.pressure().pressure(state));
  }
  return result;
}

template <int dim> std::vector<Real> Assembler<dim>::dissipation_density(const VectorX& u) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  fem::CellValues<dim> full(mesh.cell_type(), discretisation_.full_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  const int n_q = full.n_points();
  std::vector<Real> result(static_cast<std::size_t>(mesh.n_cells()) * n_q);
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation_.gather(cell, &u, coordinates, velocities);
    discretisation_.load_cell(cell, full, nullptr);
    for (int q = 0; q < n_q; ++q) {
      const Real equivalent =
          physics::equivalent_strain_rate(discretisation_.strain_rate_at(full, velocities, q));
      const Index k = cell * n_q + q;
      // The expression of the viscous term's add_power, so that Σ density·JxW is the
      // plastic power of the Power pass.
      result[k] = temperatures_.empty()
                      ? law_.dissipation(equivalent)
                      : physics::FlowLawAt(law_, temperatures_[k]).dissipation(equivalent);
    }
  }
  return result;
}

template class Assembler<2>;
template class Assembler<3>;

} // namespace formflow::assembly
