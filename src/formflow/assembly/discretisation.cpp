// SPDX-License-Identifier: MIT
// The fixed part of a forming problem: pattern, rules, caches, Γ3 and its mollifier.
#include "formflow/assembly/discretisation.hpp"

#include "formflow/assembly/kernels/fixed_size.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/mesh/cell_partition.hpp"
#include "formflow/physics/kinematics.hpp"

namespace formflow::assembly {

template <int dim>
Discretisation<dim>::Discretisation(const mesh::Mesh<dim>& mesh,
                                    const DiscretisationSettings& settings,
                                    DirichletConstraints constraints)
    : mesh_(mesh), settings_(settings), constraints_(std::move(constraints)),
      full_rule_(fem::full_rule<dim>(mesh.cell_type())),
      // Simplices take σ_H in a pressure space on the full rule (reduced integration would
      // lock them): their volumetric rule is the centroid, kept only for the caches' shape.
      volumetric_rule_(mesh.is_simplex() ? fem::rule_of_points<dim>(mesh.cell_type(), 1)
                                         : fem::gauss_rule<dim>(settings.volumetric_points)),
      facet_rule_(settings.contact.normals == ContactNormals::Nodes
                      ? fem::face_nodal_rule<dim>(mesh.cell_type())
                      : fem::face_rule<dim>(mesh.cell_type())) {
  FF_ASSERT(dim == 2 || !axisymmetric(), "axisymmetry is a two-dimensional formulation");
  // A distributed run scatters only its own cells: the others are empty blocks, so the
  // pattern (and the memory of the rank's system) holds only the own cells' entries.
  const Distribution& distribution = settings.distribution;
  if (distribution.distributed()) {
    mesh::CellPartition split =
        mesh::cell_partition(mesh, distribution.size, distribution.partition_cells);
    cell_ranks_ = std::move(split.part);
    partition_method_ = std::move(split.method);
  }
  BlockDofs blocks;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    if (!cell_ranks_.empty() && cell_ranks_[cell] != distribution.rank) {
      blocks.add({});
      continue;
    }
    assembled_cells_.push_back(cell);
    blocks.add(fem::dofs_of_nodes<dim>(mesh.cells.col(cell)));
  }
  plan_ = std::make_unique<ScatterPlan>(n_dofs(), constraints_.prescribed, blocks);
  if (distribution.distributed()) owned_dofs_ = OwnedDofs(mesh, cell_ranks_, *plan_, distribution);

  // Contact faces, grouped by cell so that the cell loop adds them to the
  // cell's own local matrix (no extra blocks in the pattern).
  std::vector<std::vector<Index>> per_cell(mesh.n_cells());
  for (Index f = 0; f < static_cast<Index>(mesh.facets.size()); ++f)
    if (mesh::is_contact(mesh.facets[f].label)) {
      per_cell[mesh.facets[f].cell].push_back(static_cast<Index>(contact_facets_.size()));
      contact_facets_.push_back(f);
    }
  cell_contact_offsets_.push_back(0);
  for (const auto& list : per_cell) {
    cell_contact_.insert(cell_contact_.end(), list.begin(), list.end());
    cell_contact_offsets_.push_back(static_cast<Index>(cell_contact_.size()));
  }
  if (contact_points_at_nodes())
    contact_normals_ =
        nodal_contact_normals<dim>(mesh, contact_facets_, settings.contact.corner_angle);

  // The mesh never moves: map every cell and Γ3 face once (fem/values_cache.hpp);
  // the loops below run every iteration on this geometry. A distributed run's rank
  // keeps its own cells' (those its iterations loop over); the others' are mapped
  // again when a loop over all cells (the fields at the end) needs them.
  {
    const std::span<const Index> cached = distribution.distributed()
                                              ? std::span<const Index>(assembled_cells_)
                                              : std::span<const Index>();
    typename fem::CellValues<dim>::Gradients nodes, no_velocity;
    const auto map_cell = [&](Index cell, fem::CellValues<dim>& values) {
      gather(cell, nullptr, nodes, no_velocity);
      reinit(values, nodes);
    };
    full_cache_ = std::make_unique<fem::CellValuesCache<dim>>(
        mesh.n_cells(), fem::CellValues<dim>(mesh.cell_type(), full_rule_), map_cell, cached);
    volumetric_cache_ = std::make_unique<fem::CellValuesCache<dim>>(
        mesh.n_cells(), fem::CellValues<dim>(mesh.cell_type(), volumetric_rule_), map_cell, cached);
    contact_cache_ = std::make_unique<fem::FacetValuesCache<dim>>(
        static_cast<Index>(contact_facets_.size()),
        fem::FacetValues<dim>(mesh.cell_type(), facet_rule_),
        [&](Index position, fem::FacetValues<dim>& values) {
          gather(mesh.facets[contact_facets_[position]].cell, nullptr, nodes, no_velocity);
          reinit_contact(values, nodes, position);
        });
  }

  // The mollifier works on the fixed geometry of Γ3: build it once.
  {
    fem::FacetValues<dim> values(mesh.cell_type(), facet_rule_);
    Gradients coordinates, unused;
    MatrixX points(dim, n_contact_points());
    std::vector<Real> weights;
    for (Index position = 0; position < static_cast<Index>(contact_facets_.size()); ++position) {
      gather(mesh.facets[contact_facets_[position]].cell, nullptr, coordinates, unused);
      reinit_contact(values, coordinates, position);
      for (int q = 0; q < values.n_points(); ++q) {
        points.col(static_cast<Index>(weights.size())) = values.point(q);
        weights.push_back(values.JxW(q));
      }
    }
    mollifier_ =
        std::make_unique<physics::NonlocalAverage>(points, weights, settings.mollifier_radius);
  }

  fem::FacetValues<dim> facet_values(mesh.cell_type(), facet_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != constraints_.driven_label) continue;
    gather(facet.cell, nullptr, coordinates, unused);
    reinit(facet_values, coordinates, facet.local_face);
    for (int q = 0; q < facet_values.n_points(); ++q) driven_height_ += facet_values.JxW(q);
  }
}

template <int dim>
void Discretisation<dim>::map_cell(Index cell, fem::CellValues<dim>& full_values,
                                   fem::CellValues<dim>* volumetric_values) const {
  Gradients coordinates, no_velocity;
  gather(cell, nullptr, coordinates, no_velocity);
  reinit(full_values, coordinates);
  if (volumetric_values) reinit(*volumetric_values, coordinates);
}

template <int dim>
void Discretisation<dim>::gather(Index cell, const VectorX* u,
                                 typename fem::CellValues<dim>::Gradients& coordinates,
                                 typename fem::CellValues<dim>::Gradients& velocities) const {
  const int n = mesh_.nodes_per_cell();
  coordinates.resize(dim, n);
  velocities.setZero(dim, n);
  for (int a = 0; a < n; ++a) {
    const Index node = mesh_.cells(a, cell);
    coordinates.col(a) = mesh_.nodes.col(node);
    if (u) velocities.col(a) = u->template segment<dim>(fem::dof_of<dim>(node, 0));
  }
}

template <int dim>
void Discretisation<dim>::reinit_contact(
    fem::FacetValues<dim>& values, const typename fem::CellValues<dim>::Gradients& coordinates,
    Index position) const {
  if (contact_cache_) return contact_cache_->load(position, values);
  reinit(values, coordinates, mesh_.facets[contact_facets_[position]].local_face);
  if (contact_normals_.empty()) return;
  // Penalty, σ_N, u_T and the friction projector all read these normals: the
  // power balance needs one normal per point throughout.
  for (int q = 0; q < values.n_points(); ++q)
    values.set_normal(q, contact_normals_[position * values.n_points() + q]);
}

namespace {

/// ε̇ at point q of cell or face `values` for the cell's nodal `velocities`; in
/// axisymmetry with the hoop rate u_r/r in the θθ (third) slot.
template <int dim, class Values>
Tensor3 strain_rate_of(const Values& values,
                       const typename fem::CellValues<dim>::Gradients& velocities, int q,
                       bool axisymmetric) {
  Tensor2<dim> gradient;
  with_node_count<dim>(values.n_nodes(), [&](auto n_nodes) { // fixed sizes: runs at every point
    using NodeValues = Eigen::Matrix<Real, dim, decltype(n_nodes)::value>;
    gradient = physics::velocity_gradient<dim>(
        Eigen::Map<const NodeValues>(velocities.data(), dim, values.n_nodes()),
        Eigen::Map<const NodeValues>(values.gradients(q).data(), dim, values.n_nodes()));
  });
  Tensor3 rate = physics::strain_rate<dim>(gradient);
  if constexpr (dim == 2)
    if (axisymmetric)
      physics::add_hoop_rate<dim>(rate, gradient, (velocities * values.shape(q))[1],
                                  values.point(q)[1]);
  return rate;
}

} // namespace

template <int dim>
Tensor3
Discretisation<dim>::strain_rate_at(const fem::CellValues<dim>& values,
                                    const typename fem::CellValues<dim>::Gradients& velocities,
                                    int q) const {
  return strain_rate_of<dim>(values, velocities, q, axisymmetric());
}

template <int dim>
Tensor3
Discretisation<dim>::strain_rate_at(const fem::FacetValues<dim>& values,
                                    const typename fem::CellValues<dim>::Gradients& velocities,
                                    int q) const {
  return strain_rate_of<dim>(values, velocities, q, axisymmetric());
}

template <int dim>
Real Discretisation<dim>::hoop_rate_at(const fem::CellValues<dim>& values,
                                       const typename fem::CellValues<dim>::Gradients& velocities,
                                       int q) const {
  if (!axisymmetric()) return 0.0;
  return strain_rate_at(values, velocities, q)(2, 2);
}

template class Discretisation<2>;
template class Discretisation<3>;

} // namespace formflow::assembly
