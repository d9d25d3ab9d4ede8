// SPDX-License-Identifier: MIT
// The Γ3 nodes' free velocity dofs in their nodal normal–tangent frame: where the
// contact penalty and the regularised friction act on one unknown each (issue 20).
#pragma once

#include "formflow/assembly/discretisation.hpp"
#include "formflow/assembly/local_frame.hpp"

#include <map>
#include <vector>

namespace formflow::assembly {

/// One frame per Γ3 node whose normal n has a nonzero part on two or more of the node's
/// free velocity dofs: rows = those free dofs (component order), the basis' first column
/// n restricted to them and normalised, the others completing it orthonormally. n is
/// the nodal normal (assembly::nodal_contact_normals, the mean at a real corner, where
/// each face keeps its own). With nodal contact normals
/// (Discretisation::contact_points_at_nodes) the contact penalty (1/d_N) w u_N v_N at
/// the node is then exactly one diagonal entry (the frame's first unknown) and the
/// regularised friction's τ_f/√(|u_T|² + d_T²) w u_T·v_T sits on the others, instead
/// of a rank-one coupling of the Cartesian components along an inclined normal, which
/// pointwise smoothers and algebraic multigrid cannot resolve. With face normals the
/// same holds on flat faces away from their junctions (the penalty couples the nodes'
/// normal unknowns only, through the face mass), and approximately on curved faces. A
/// node whose normal has one free component is already in its frame and gets none.
template <int dim>
std::vector<LocalFrame> contact_frames(const Discretisation<dim>& discretisation);

/// Every Γ3 node with its nodal normal, unnormalised: the sum of the normals its faces
/// give it (assembly::nodal_contact_normals; a real corner's faces keep their own, so
/// there the sum is their bisector). Ordered by node.
template <int dim>
std::map<Index, Point<dim>> contact_node_normals(const Discretisation<dim>& discretisation);

} // namespace formflow::assembly
