// SPDX-License-Identifier: MIT
// Everything of a discrete problem that never changes during a solve: the mesh,
// the scatter plan, the Dirichlet constraints, the quadrature rules and their
// geometry caches, the contact boundary Γ3 with its normals and mollifier, the
// driven end and the plane/axisymmetric kinematics (issue 13).
#pragma once

#include "formflow/assembly/constraints.hpp"
#include "formflow/assembly/contact_normals.hpp"
#include "formflow/assembly/distribution.hpp"
#include "formflow/assembly/owned_dofs.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/values_cache.hpp"
#include "formflow/physics/friction.hpp"
#include "formflow/physics/process.hpp"

#include <algorithm>
#include <memory>
#include <span>
#include <vector>

namespace formflow::assembly {

/// What fixes the discretisation besides the mesh and the constraints.
struct DiscretisationSettings {
  physics::Symmetry symmetry = physics::Symmetry::Plane; ///< axisymmetric: dim = 2 only
  int volumetric_points = 2;   ///< Gauss points per direction of the volumetric rule
  ContactSettings contact;     ///< face or nodal contact normals
  Real mollifier_radius = 0.0; ///< radius h of σ̄_N (friction.radius); 0: local
  Distribution distribution;   ///< distributed run: this rank's part of the cells (issue 20)
};

/// The fixed part of a forming problem. Built once; every cell loop, the drivers'
/// reactions and the post-processing read it, none changes it.
template <int dim> class Discretisation {
public:
  using Gradients = typename fem::CellValues<dim>::Gradients;

  Discretisation(const mesh::Mesh<dim>& mesh, const DiscretisationSettings& settings,
                 DirichletConstraints constraints);

  const mesh::Mesh<dim>& mesh() const { return mesh_; }
  const DiscretisationSettings& settings() const { return settings_; }
  /// The scatter plan of the cells this rank assembles (all of them in a serial run;
  /// in a distributed run its pattern holds only the own cells' entries).
  const ScatterPlan& plan() const { return *plan_; }
  /// The cells whose matrices and loads this rank assembles (ascending): all cells, or
  /// in a distributed run its part (mesh/cell_partition.hpp).
  const std::vector<Index>& assembled_cells() const { return assembled_cells_; }
  /// A distributed run: every cell's rank (the same on every rank); empty on one rank.
  const std::vector<int>& cell_ranks() const { return cell_ranks_; }
  /// How cell_ranks() was made (mesh::CellPartition::method); empty on one rank.
  const std::string& partition_method() const { return partition_method_; }
  /// Whether `cell` is one of assembled_cells() (always, on one rank).
  bool assembles(Index cell) const {
    return !settings_.distribution.distributed() ||
           std::binary_search(assembled_cells_.begin(), assembled_cells_.end(), cell);
  }
  const Distribution& distribution() const { return settings_.distribution; }
  /// The dofs this rank owns: dot products and whole vectors of a distributed run's
  /// ghosted vectors (every dof on one rank).
  const OwnedDofs& owned_dofs() const { return owned_dofs_; }
  const DirichletConstraints& constraints() const { return constraints_; }
  Index n_dofs() const { return mesh_.n_nodes() * dim; }
  bool axisymmetric() const { return settings_.symmetry == physics::Symmetry::Axisymmetric; }

  /// Quadrature rules: full (a-term), volumetric, and faces (Gauss, or the nodal rule
  /// when contact_points_at_nodes()).
  const fem::QuadratureRule<dim>& full_rule() const { return full_rule_; }
  const fem::QuadratureRule<dim>& volumetric_rule() const { return volumetric_rule_; }
  const fem::QuadratureRule<dim - 1>& facet_rule() const { return facet_rule_; }
  /// True with nodal contact normals: the face rule is fem::nodal_rule, its points are
  /// the face nodes (in face_local_nodes order).
  bool contact_points_at_nodes() const {
    return settings_.contact.normals == ContactNormals::Nodes;
  }

  /// Γ3: Mesh::facets indices of the contact faces, in mesh order ("positions").
  const std::vector<Index>& contact_facets() const { return contact_facets_; }
  /// Positions (in contact_facets()) of the contact faces of `cell`.
  std::span<const Index> cell_contact_faces(Index cell) const {
    return {
        cell_contact_.data() + cell_contact_offsets_[cell],
        static_cast<std::size_t>(cell_contact_offsets_[cell + 1] - cell_contact_offsets_[cell])};
  }
  /// Number of Γ3 quadrature points (positions × face rule, position-major).
  Index n_contact_points() const {
    return static_cast<Index>(contact_facets_.size()) * facet_rule_.size();
  }
  /// The mollifier of the contact pressure over Γ3 (radius settings().mollifier_radius).
  const physics::NonlocalAverage& mollifier() const { return *mollifier_; }
  /// Measure of the driven end (ram height, or exit half height for drawing): a
  /// length in 2D (per unit depth; per radian ∫ r dr in axisymmetry), an area in 3D.
  Real driven_height() const { return driven_height_; }

  /// Maps `values` to a cell or face and, in axisymmetry, weights them by r (all
  /// integrals are per radian: forces per radian, "heights" ∫ r dr).
  template <class Values, class... Face>
  void reinit(Values& values, const Gradients& coordinates, Face... local_face) const {
    values.reinit(coordinates, local_face...);
    if (axisymmetric()) values.weight_by_radius();
  }
  /// Maps `values` to the Γ3 face at `position` (from the cache), with the nodal
  /// normals in place of the face normals when contact_points_at_nodes().
  void reinit_contact(fem::FacetValues<dim>& values, const Gradients& coordinates,
                      Index position) const;
  /// Puts cell `cell`'s mapped values at the full and the volumetric rule into the
  /// given values (from the geometry cache: the mesh never moves; a cell another rank
  /// assembles is mapped here).
  void load_cell(Index cell, fem::CellValues<dim>& full_values,
                 fem::CellValues<dim>* volumetric_values) const {
    if (!full_cache_->holds(cell)) {
      map_cell(cell, full_values, volumetric_values);
      return;
    }
    full_cache_->load(cell, full_values);
    if (volumetric_values) volumetric_cache_->load(cell, *volumetric_values);
  }
  /// Memory held by the geometry caches (cells at both rules, contact faces).
  std::size_t geometry_cache_bytes() const {
    return full_cache_->bytes() + volumetric_cache_->bytes() +
           (contact_cache_ ? contact_cache_->bytes() : 0);
  }
  /// load_cell without the cache: gathers the cell's nodes and maps the values.
  void map_cell(Index cell, fem::CellValues<dim>& full_values,
                fem::CellValues<dim>* volumetric_values) const;
  /// Node coordinates (dim × n) and nodal velocities (dim × n; zero without `u`) of one cell.
  void gather(Index cell, const VectorX* u, Gradients& coordinates, Gradients& velocities) const;

  /// ε̇ at point q of cell or face `values` for the cell's nodal `velocities`; in
  /// axisymmetry with the hoop rate u_r/r in the θθ (third) slot.
  Tensor3 strain_rate_at(const fem::CellValues<dim>& values, const Gradients& velocities,
                         int q) const;
  Tensor3 strain_rate_at(const fem::FacetValues<dim>& values, const Gradients& velocities,
                         int q) const;
  /// The hoop rate u_r/r at point q (exactly 0 in plane strain), the part of ε̇_V = tr ε̇
  /// beyond the in-plane divergence.
  Real hoop_rate_at(const fem::CellValues<dim>& values, const Gradients& velocities, int q) const;

private:
  const mesh::Mesh<dim>& mesh_;
  DiscretisationSettings settings_;
  DirichletConstraints constraints_;
  std::unique_ptr<ScatterPlan> plan_;
  OwnedDofs owned_dofs_;
  std::vector<Index> assembled_cells_;
  std::vector<int> cell_ranks_;
  std::string partition_method_;
  fem::QuadratureRule<dim> full_rule_, volumetric_rule_;
  fem::QuadratureRule<dim - 1> facet_rule_;
  std::vector<Index> contact_facets_;       ///< Mesh::facets indices of Γ3, in mesh order
  std::vector<Index> cell_contact_offsets_; ///< per cell, range in cell_contact_
  std::vector<Index> cell_contact_;         ///< positions in contact_facets_
  std::vector<Point<dim>> contact_normals_; ///< nodal normals per Γ3 point; empty: face normals
  std::unique_ptr<physics::NonlocalAverage> mollifier_;
  /// Mapped values of every cell (full and volumetric rule) and Γ3 face, built once.
  std::unique_ptr<fem::CellValuesCache<dim>> full_cache_, volumetric_cache_;
  std::unique_ptr<fem::FacetValuesCache<dim>> contact_cache_;
  Real driven_height_ = 0.0;
};

} // namespace formflow::assembly
