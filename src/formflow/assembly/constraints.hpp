// SPDX-License-Identifier: MIT
// Prescribed velocities of the forming process (SPEC §1 table, §4 ram conditions).
#pragma once

#include "formflow/mesh/mesh.hpp"
#include "formflow/physics/process.hpp"

#include <vector>

namespace formflow::assembly {

/// Dirichlet data on the full dof vector. The process moves material in +x.
struct DirichletConstraints {
  std::vector<bool> prescribed; ///< per dof
  VectorX values;               ///< per dof; meaningful where prescribed
  /// The dofs carrying the process speed (u_x on Γ1 for extrusion, on Γ5 for
  /// drawing): their summed reaction is the process force.
  std::vector<Index> driven_dofs;
  mesh::BoundaryLabel driven_label = mesh::BoundaryLabel::Rear;
};

/// Extrusion: u_x = u⁰ on rear (and the tangential components u_y, u_z = 0 there
/// for a sticking ram); drawing: u_x = u⁰ on front; both: u_N = 0 on symmetry,
/// i.e. the component along the normal axis of each symmetry facet's coordinate
/// plane (u_y on y = 0; u_z on z = 0 and on the slab's z faces). Γ3's u_N = 0 is a
/// penalty term, not a constraint (eq. 3.8).
/// Precondition: every symmetry facet lies in a coordinate plane
/// (mesh::facet_normal_axis; the generators make them so, io checks a file's).
template <int dim>
DirichletConstraints make_process_constraints(const mesh::Mesh<dim>& mesh,
                                              const physics::Process& process);

/// Nodes lying on facets with `label`, each once, ascending.
template <int dim>
std::vector<Index> nodes_on(const mesh::Mesh<dim>& mesh, mesh::BoundaryLabel label);

} // namespace formflow::assembly
