// SPDX-License-Identifier: MIT
// The steady heat equation with SUPG (Brooks & Hughes 1982) on the workpiece mesh.
#include "formflow/assembly/heat_problem.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/fem/reference_element.hpp"

#include <Eigen/LU> // inverse() of the Jacobian

#include <algorithm>
#include <array>
#include <cmath>

namespace formflow::assembly {

template <int dim>
HeatProblem<dim>::HeatProblem(const Discretisation<dim>& discretisation,
                              const physics::Thermal& thermal,
                              const BoundaryTemperature& boundary_temperature)
    : discretisation_(discretisation), thermal_(thermal) {
  const mesh::Mesh<dim>& mesh = discretisation.mesh();
  prescribed_.assign(mesh.n_nodes(), false);
  prescribed_value_ = VectorX::Constant(mesh.n_nodes(), thermal.billet_temperature);
  for (Index f = 0; f < static_cast<Index>(mesh.facets.size()); ++f) {
    const mesh::BoundaryFacet& facet = mesh.facets[f];
    if (boundary_temperature) {
      for (const int local : mesh.face_nodes(facet.local_face)) {
        const Index node = mesh.cells(local, facet.cell);
        prescribed_[node] = true;
        prescribed_value_[node] = boundary_temperature(mesh.nodes.col(node));
      }
      if (facet.label == mesh::BoundaryLabel::Front) outflow_.push_back(f);
      continue;
    }
    switch (facet.label) {
    case mesh::BoundaryLabel::Rear:
      for (const int local : mesh.face_nodes(facet.local_face))
        prescribed_[mesh.cells(local, facet.cell)] = true;
      break;
    case mesh::BoundaryLabel::FreeEntry:
    case mesh::BoundaryLabel::FreeExit: free_surface_.push_back(f); break;
    case mesh::BoundaryLabel::Front: outflow_.push_back(f); break;
    default: break;
    }
  }
  const fem::QuadratureRule<dim>& rule = discretisation.full_rule();
  for (int q = 0; q < rule.size(); ++q) {
    VectorX unused;
    reference_gradients_.emplace_back();
    fem::tabulate_shape<dim>(mesh.cell_type(), rule.points[q], unused, reference_gradients_.back());
    reference_hessians_.push_back(fem::tabulate_hessians<dim>(mesh.cell_type(), rule.points[q]));
  }
  free_index_.assign(mesh.n_nodes(), -1);
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    if (!prescribed_[node]) free_index_[node] = n_free_++;
}

template <int dim> Real HeatProblem<dim>::supg_tau(Real speed, Real length, Real conductivity) {
  if (!(speed > 0) || !(length > 0)) return 0.0;
  const Real peclet = speed * length / (2.0 * conductivity);
  // coth Pe − 1/Pe loses its digits to cancellation for small Pe: its series there.
  const Real xi = peclet < 1e-3 ? peclet / 3.0 - peclet * peclet * peclet / 45.0
                                : 1.0 / std::tanh(peclet) - 1.0 / peclet;
  return length / (2.0 * speed) * xi;
}

template <int dim>
VectorX
HeatProblem<dim>::minus_laplacian(const typename fem::CellValues<dim>::Gradients& coordinates,
                                  const typename fem::CellValues<dim>::Gradients& gradients, int q,
                                  const Point<dim>& point) const {
  // ∂²N/∂ξ∂ξ = Jᵀ (∂²N/∂x∂x) J + Σ_k ∂N/∂x_k ∂²x_k/∂ξ∂ξ, so ∂²N/∂x∂x = J⁻ᵀ (H_ξ − Σ_k
  // ∂N/∂x_k G_k) J⁻¹ with G_k = Σ_b X_kb H_ξ(N_b) (zero on affine cells).
  const auto& hessians = reference_hessians_[q];
  const int n = static_cast<int>(hessians.size());
  const Tensor2<dim> jacobian = coordinates * reference_gradients_[q].transpose();
  const Tensor2<dim> inverse = jacobian.inverse();
  std::array<Tensor2<dim>, dim> geometry;
  for (int k = 0; k < dim; ++k) {
    geometry[k].setZero();
    for (int b = 0; b < n; ++b) geometry[k] += coordinates(k, b) * hessians[b];
  }
  VectorX result(n);
  for (int a = 0; a < n; ++a) {
    Tensor2<dim> reference = hessians[a];
    for (int k = 0; k < dim; ++k) reference -= gradients(k, a) * geometry[k];
    result[a] = -(inverse.transpose() * reference * inverse).trace();
    // Axisymmetry (y = r): ∇·∇T = T_rr + T_r/r + T_zz.
    if (discretisation_.axisymmetric()) result[a] -= gradients(1, a) / point[1];
  }
  return result;
}

template <int dim>
void HeatProblem<dim>::cell_system(Index cell, const VectorX& u, std::span<const Real> deformation,
                                   MatrixX& matrix, VectorX& load) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  fem::CellValues<dim> values(mesh.cell_type(), discretisation_.full_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  discretisation_.gather(cell, &u, coordinates, velocities);
  discretisation_.load_cell(cell, values, nullptr);
  const int n = values.n_nodes();
  const Real rho_c = thermal_.volumetric_heat(), kappa = thermal_.conductivity;
  matrix.setZero(n, n);
  load.setZero(n);
  for (int q = 0; q < values.n_points(); ++q) {
    const VectorX& shape = values.shape(q);
    const auto& grad = values.gradients(q); // dim × n
    const Point<dim> velocity = velocities * shape;
    const VectorX streamline = grad.transpose() * velocity; // u·∇N_a
    // The streamline length h = 2|u|/Σ|u·∇N_a| (Tezduyar), over the node spacing for Q2.
    const Real speed = velocity.norm(), sum = streamline.cwiseAbs().sum();
    const Real length = sum > 0 ? 2.0 * speed / sum / mesh.order : 0.0;
    const Real tau = supg_tau(rho_c * speed, length, kappa);
    const Real source = deformation.empty() ? 0.0 : deformation[q];
    const Real jxw = values.JxW(q);
    // (1) Galerkin convection N_a ρc u·∇N_b, (2) diffusion κ ∇N_a·∇N_b, (3) SUPG
    // τ (ρc u·∇N_a)(ρc u·∇N_b − κ ΔN_b − q), the whole residual: without its −κΔT part
    // (zero only for Q1 on affine plane cells) the method is inconsistent by τκ → h²/12,
    // which capped Q2's L² rate at 2 (docs/thermal.md).
    const VectorX test = shape + tau * rho_c * streamline;
    matrix.noalias() += (rho_c * jxw) * test * streamline.transpose();
    matrix.noalias() += (kappa * jxw) * grad.transpose() * grad;
    if (tau > 0)
      matrix.noalias() += (tau * rho_c * kappa * jxw) * streamline *
                          minus_laplacian(coordinates, grad, q, values.point(q)).transpose();
    load.noalias() += (source * jxw) * test;
  }
}

template <int dim>
template <class Values>
void HeatProblem<dim>::add_face_terms(const Values& values, Real transfer, Real reference,
                                      std::span<const Real> friction, MatrixX& matrix,
                                      VectorX& load) const {
  for (int q = 0; q < values.n_points(); ++q) {
    const VectorX& shape = values.shape(q);
    const Real jxw = values.JxW(q);
    // −κ ∂T/∂n = h (T − T_ref) − q_friction: h N_a N_b into A, (h T_ref + q_f) N_a into b.
    if (transfer > 0) matrix.noalias() += (transfer * jxw) * shape * shape.transpose();
    const Real flux = transfer * reference + (friction.empty() ? 0.0 : friction[q]);
    load.noalias() += (flux * jxw) * shape;
  }
}

namespace {

/// Calls `f(cell, matrix, load)` with the local system of every cell and then of every
/// boundary face with a heat term (Γ3, the free surfaces), each on its cell's nodes.
template <int dim, class CellSystem, class FaceTerms, class F>
void for_each_block(const Discretisation<dim>& discretisation,
                    const std::vector<Index>& free_surface, CellSystem&& cell_system,
                    FaceTerms&& face_terms, F&& f) {
  const mesh::Mesh<dim>& mesh = discretisation.mesh();
  MatrixX matrix;
  VectorX load;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    cell_system(cell, matrix, load);
    f(cell, matrix, load);
  }
  fem::FacetValues<dim> contact(mesh.cell_type(), discretisation.facet_rule());
  fem::FacetValues<dim> face(mesh.cell_type(), fem::face_rule<dim>(mesh.cell_type()));
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  const int n = mesh.nodes_per_cell();
  const auto& contact_facets = discretisation.contact_facets();
  for (Index position = 0; position < static_cast<Index>(contact_facets.size()); ++position) {
    const Index cell = mesh.facets[contact_facets[position]].cell;
    discretisation.gather(cell, nullptr, coordinates, unused);
    discretisation.reinit_contact(contact, coordinates, position);
    matrix.setZero(n, n);
    load.setZero(n);
    face_terms(contact, true, position, matrix, load);
    f(cell, matrix, load);
  }
  for (const Index index : free_surface) {
    const mesh::BoundaryFacet& facet = mesh.facets[index];
    discretisation.gather(facet.cell, nullptr, coordinates, unused);
    discretisation.reinit(face, coordinates, facet.local_face);
    matrix.setZero(n, n);
    load.setZero(n);
    face_terms(face, false, 0, matrix, load);
    f(facet.cell, matrix, load);
  }
}

} // namespace

template <int dim>
HeatSystem HeatProblem<dim>::assemble(const VectorX& u, const HeatSources& sources) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  const int n_q = discretisation_.full_rule().size();
  const int n_face_q = discretisation_.facet_rule().size();
  std::vector<Eigen::Triplet<Real, Index>> entries;
  entries.reserve(static_cast<std::size_t>(mesh.n_cells()) * mesh.nodes_per_cell() *
                  mesh.nodes_per_cell());
  HeatSystem system;
  system.rhs.setZero(n_free_);
  const auto cell_part = [&](Index cell, MatrixX& matrix, VectorX& load) {
    const std::span<const Real> deformation =
        sources.deformation.empty()
            ? std::span<const Real>()
            : std::span<const Real>(sources.deformation).subspan(cell * n_q, n_q);
    cell_system(cell, u, deformation, matrix, load);
  };
  const auto face_part = [&](const auto& values, bool contact, Index position, MatrixX& matrix,
                             VectorX& load) {
    if (contact) {
      const std::span<const Real> friction =
          sources.friction.empty()
              ? std::span<const Real>()
              : std::span<const Real>(sources.friction).subspan(position * n_face_q, n_face_q);
      add_face_terms(values, thermal_.heat_transfer, thermal_.tool_temperature, friction, matrix,
                     load);
    } else {
      add_face_terms(values, thermal_.free_surface_transfer, thermal_.ambient_temperature, {},
                     matrix, load);
    }
  };
  for_each_block<dim>(discretisation_, free_surface_, cell_part, face_part,
                      [&](Index cell, const MatrixX& matrix, const VectorX& load) {
                        const auto nodes = mesh.cells.col(cell);
                        for (int a = 0; a < matrix.rows(); ++a) {
                          const Index row = free_index_[nodes[a]];
                          if (row < 0) continue;
                          system.rhs[row] += load[a];
                          for (int b = 0; b < matrix.cols(); ++b) {
                            const Index column = free_index_[nodes[b]];
                            if (column >= 0)
                              entries.emplace_back(row, column, matrix(a, b));
                            else
                              system.rhs[row] -= matrix(a, b) * prescribed_value_[nodes[b]];
                          }
                        }
                      });
  system.matrix.resize(n_free_, n_free_);
  system.matrix.setFromTriplets(entries.begin(), entries.end());
  return system;
}

template <int dim> VectorX HeatProblem<dim>::expand(const VectorX& free_temperatures) const {
  VectorX T(n_nodes());
  for (Index node = 0; node < n_nodes(); ++node)
    T[node] =
        free_index_[node] < 0 ? prescribed_value_[node] : free_temperatures[free_index_[node]];
  return T;
}

template <int dim>
HeatBalance HeatProblem<dim>::balance(const VectorX& u, const HeatSources& sources,
                                      const VectorX& T) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  const int n_q = discretisation_.full_rule().size();
  const int n_face_q = discretisation_.facet_rule().size();
  HeatBalance balance;
  // Each part from its own integral; the rear end's conduction from the residual of
  // its (eliminated) rows, R_a = (A T − b)_a: the heat the Dirichlet end takes in.
  VectorX residual = VectorX::Zero(n_nodes());
  fem::CellValues<dim> values(mesh.cell_type(), discretisation_.full_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation_.gather(cell, &u, coordinates, velocities);
    discretisation_.load_cell(cell, values, nullptr);
    const auto nodes = mesh.cells.col(cell);
    VectorX local(nodes.size());
    for (Index a = 0; a < nodes.size(); ++a) local[a] = T[nodes[a]];
    for (int q = 0; q < n_q; ++q) {
      const Point<dim> velocity = velocities * values.shape(q);
      const Point<dim> gradient = values.gradients(q) * local;
      balance.convected += thermal_.volumetric_heat() * velocity.dot(gradient) * values.JxW(q);
      if (!sources.deformation.empty())
        balance.deformation += sources.deformation[cell * n_q + q] * values.JxW(q);
    }
  }
  const auto face_part = [&](const auto& face, bool contact, Index position, MatrixX& matrix,
                             VectorX& load) {
    const Real transfer = contact ? thermal_.heat_transfer : thermal_.free_surface_transfer;
    const Real reference = contact ? thermal_.tool_temperature : thermal_.ambient_temperature;
    std::span<const Real> friction;
    if (contact && !sources.friction.empty())
      friction = std::span<const Real>(sources.friction).subspan(position * n_face_q, n_face_q);
    add_face_terms(face, transfer, reference, friction, matrix, load);
  };
  for_each_block<dim>(
      discretisation_, free_surface_,
      [&](Index cell, MatrixX& matrix, VectorX& load) {
        const std::span<const Real> deformation =
            sources.deformation.empty()
                ? std::span<const Real>()
                : std::span<const Real>(sources.deformation).subspan(cell * n_q, n_q);
        cell_system(cell, u, deformation, matrix, load);
      },
      face_part,
      [&](Index cell, const MatrixX& matrix, const VectorX& load) {
        const auto nodes = mesh.cells.col(cell);
        VectorX local(nodes.size());
        for (Index a = 0; a < nodes.size(); ++a) local[a] = T[nodes[a]];
        const VectorX r = matrix * local - load;
        for (Index a = 0; a < nodes.size(); ++a) residual[nodes[a]] += r[a];
      });
  for (Index node = 0; node < n_nodes(); ++node)
    if (prescribed_[node]) balance.conducted -= residual[node];
  // The boundary parts from the face integrals themselves.
  fem::FacetValues<dim> contact(mesh.cell_type(), discretisation_.facet_rule());
  fem::FacetValues<dim> face(mesh.cell_type(), fem::face_rule<dim>(mesh.cell_type()));
  typename fem::CellValues<dim>::Gradients unused;
  const auto face_temperature = [&](const fem::FacetValues<dim>& values, Index cell, int q) {
    Real value = 0.0;
    for (int a = 0; a < values.n_nodes(); ++a) value += values.shape(q)[a] * T[mesh.cells(a, cell)];
    return value;
  };
  const auto& contact_facets = discretisation_.contact_facets();
  for (Index position = 0; position < static_cast<Index>(contact_facets.size()); ++position) {
    const Index cell = mesh.facets[contact_facets[position]].cell;
    discretisation_.gather(cell, nullptr, coordinates, unused);
    discretisation_.reinit_contact(contact, coordinates, position);
    for (int q = 0; q < contact.n_points(); ++q) {
      balance.tools += thermal_.heat_transfer *
                       (face_temperature(contact, cell, q) - thermal_.tool_temperature) *
                       contact.JxW(q);
      if (!sources.friction.empty())
        balance.friction += sources.friction[position * n_face_q + q] * contact.JxW(q);
    }
  }
  for (const Index index : free_surface_) {
    const mesh::BoundaryFacet& facet = mesh.facets[index];
    discretisation_.gather(facet.cell, nullptr, coordinates, unused);
    discretisation_.reinit(face, coordinates, facet.local_face);
    for (int q = 0; q < face.n_points(); ++q)
      balance.free_surfaces +=
          thermal_.free_surface_transfer *
          (face_temperature(face, facet.cell, q) - thermal_.ambient_temperature) * face.JxW(q);
  }
  return balance;
}

template <int dim> std::vector<Real> HeatProblem<dim>::point_values(const VectorX& T) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  fem::CellValues<dim> values(mesh.cell_type(), discretisation_.full_rule());
  std::vector<Real> result;
  result.reserve(static_cast<std::size_t>(mesh.n_cells()) * values.n_points());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation_.load_cell(cell, values, nullptr); // shape values only: no geometry needed
    for (int q = 0; q < values.n_points(); ++q) {
      Real value = 0.0;
      for (int a = 0; a < values.n_nodes(); ++a)
        value += values.shape(q)[a] * T[mesh.cells(a, cell)];
      result.push_back(value);
    }
  }
  return result;
}

template <int dim> std::vector<Real> HeatProblem<dim>::contact_values(const VectorX& T) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  fem::FacetValues<dim> contact(mesh.cell_type(), discretisation_.facet_rule());
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  std::vector<Real> result;
  const auto& contact_facets = discretisation_.contact_facets();
  for (Index position = 0; position < static_cast<Index>(contact_facets.size()); ++position) {
    const Index cell = mesh.facets[contact_facets[position]].cell;
    discretisation_.gather(cell, nullptr, coordinates, unused);
    discretisation_.reinit_contact(contact, coordinates, position);
    for (int q = 0; q < contact.n_points(); ++q) {
      Real value = 0.0;
      for (int a = 0; a < contact.n_nodes(); ++a)
        value += contact.shape(q)[a] * T[mesh.cells(a, cell)];
      result.push_back(value);
    }
  }
  return result;
}

template <int dim>
typename HeatProblem<dim>::ExitTemperature
HeatProblem<dim>::exit_temperature(const VectorX& u, const VectorX& T) const {
  const mesh::Mesh<dim>& mesh = discretisation_.mesh();
  fem::FacetValues<dim> face(mesh.cell_type(), fem::face_rule<dim>(mesh.cell_type()));
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  ExitTemperature exit{INFINITY, 0.0, -INFINITY};
  Real heat_flux = 0.0, flux = 0.0;
  for (const Index index : outflow_) {
    const mesh::BoundaryFacet& facet = mesh.facets[index];
    discretisation_.gather(facet.cell, &u, coordinates, velocities);
    discretisation_.reinit(face, coordinates, facet.local_face);
    for (int q = 0; q < face.n_points(); ++q) {
      Real value = 0.0;
      for (int a = 0; a < face.n_nodes(); ++a)
        value += face.shape(q)[a] * T[mesh.cells(a, facet.cell)];
      const Real normal_speed = (velocities * face.shape(q)).dot(face.normal(q));
      exit.min = std::min(exit.min, value);
      exit.max = std::max(exit.max, value);
      heat_flux += value * normal_speed * face.JxW(q);
      flux += normal_speed * face.JxW(q);
    }
  }
  if (outflow_.empty()) return {};
  exit.mean = flux != 0 ? heat_flux / flux : 0.5 * (exit.min + exit.max);
  return exit;
}

template class HeatProblem<2>;
template class HeatProblem<3>;

} // namespace formflow::assembly
