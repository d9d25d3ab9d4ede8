// SPDX-License-Identifier: MIT
// The discrete inf-sup (LBB) constant β_h of a velocity/pressure pair (Remark 4.3), by a
// dense generalised eigenproblem, and the 2×2 macro-element filter: verification
// tooling (docs/mixed.md), not part of a solve, so it lives with the tests.
#pragma once

#include "formflow/core/error.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/fem/pressure_space.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/mesh/mesh.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <cmath>
#include <map>

namespace formflow::testing {

/// β_h = min_q max_v (q, div v) / (|v|_1 ‖q‖_0) over the mesh's velocity space
/// (all boundary nodes fixed: H¹₀) and the pressure space, q ⊥ the null modes.
struct InfSupEstimate {
  Real beta = 0.0;      ///< √ of the smallest eigenvalue of S q = λ M q above the null modes
  int n_null_modes = 0; ///< pressures with (q, div v) = 0 ∀v: the constant and spurious modes
  Index n_velocity_dofs = 0; ///< free velocity dofs
  Index n_pressure_dofs = 0; ///< pressure dofs (after the filter)
};

/// Dense generalised eigenproblem S q = λ M q with S = B A⁻¹ Bᵀ (A: vector
/// Laplacian, B_ia = (ψ_i, div φ_a), M: pressure mass): meant for small
/// meshes (a few thousand dofs). With `macro_filter` (P0 only), the local
/// checkerboard (+1 −1 / −1 +1) of every complete 2×2 macro-element of a
/// uniform mesh is removed from the pressure space (the macro-element filter of
/// Remark 4.3). Eigenvalues below 1e-10 × the largest count as null modes.
template <int dim>
InfSupEstimate inf_sup_constant(const mesh::Mesh<dim>& mesh, fem::PressureSpace space,
                                bool macro_filter = false);

/// Projects the local checkerboard mode out of every complete 2×2 macro-element
/// of a uniform square mesh of side `size` (cells grouped by their centres);
/// cells of incomplete macro-elements keep their values. `cell_values` is a P0 field.
inline VectorX filter_checkerboard(const mesh::Mesh<2>& mesh, Real size,
                                   const VectorX& cell_values);

namespace inf_sup_detail {

/// Pressure dof of basis function i on `cell`: cell-wise for discontinuous
/// spaces, the cell's vertices (numbered on first sight) for continuous Q1.
struct PressureNumbering {
  Eigen::Matrix<Index, Eigen::Dynamic, Eigen::Dynamic> dofs; // (per cell, n_cells)
  Index n_dofs = 0;
};

template <int dim>
PressureNumbering number_pressures(const mesh::Mesh<dim>& mesh, fem::PressureSpace space) {
  FF_ASSERT(dim == 2 || mesh.is_simplex() || fem::is_discontinuous(space),
            "the continuous Q1 numbering here is the quadrilateral's");
  const int n_p = fem::pressure_functions_per_cell<dim>(space);
  PressureNumbering numbering;
  numbering.dofs.resize(n_p, mesh.n_cells());
  std::map<Index, Index> vertex_dof;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int i = 0; i < n_p; ++i) {
      if (fem::is_discontinuous(space)) {
        numbering.dofs(i, cell) = numbering.n_dofs++;
        continue;
      }
      // Q1: vertex i = (bit 0: ξ side, bit 1: η side) in the lexicographic lattice;
      // P1: simplex vertex i, local node i.
      const int local = mesh.is_simplex()
                            ? i
                            : (i & 1) * mesh.order + ((i >> 1) & 1) * mesh.order * (mesh.order + 1);
      const auto [entry, inserted] = vertex_dof.emplace(mesh.cells(local, cell), numbering.n_dofs);
      if (inserted) ++numbering.n_dofs;
      numbering.dofs(i, cell) = entry->second;
    }
  return numbering;
}

/// Free (interior) velocity dof index per dof, −1 on the boundary.
template <int dim> std::vector<Index> interior_dofs(const mesh::Mesh<dim>& mesh, Index& n_free) {
  std::vector<bool> on_boundary(mesh.n_nodes(), false);
  for (const mesh::BoundaryFacet& facet : mesh.facets)
    for (int local : mesh.face_nodes(facet.local_face))
      on_boundary[mesh.cells(local, facet.cell)] = true;
  std::vector<Index> free(mesh.n_nodes() * dim, -1);
  n_free = 0;
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    if (!on_boundary[node])
      for (int i = 0; i < dim; ++i) free[fem::dof_of<dim>(node, i)] = n_free++;
  return free;
}

/// The complete 2×2 macro-elements of a uniform mesh of side `size`, each as
/// its four cells and the checkerboard signs (±½, a unit vector).
struct Macro {
  std::vector<Index> cells;
  std::vector<Real> signs;
};

inline std::vector<Macro> macro_elements(const mesh::Mesh<2>& mesh, Real size) {
  std::map<std::pair<long, long>, Macro> macros;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Point<2> centre = Point<2>::Zero();
    for (int a = 0; a < mesh.nodes_per_cell(); ++a) centre += mesh.nodes.col(mesh.cells(a, cell));
    centre /= mesh.nodes_per_cell();
    const long i = std::lround(centre[0] / size - 0.5), j = std::lround(centre[1] / size - 0.5);
    Macro& macro = macros[{i / 2, j / 2}];
    macro.cells.push_back(cell);
    macro.signs.push_back(((i + j) & 1) ? -0.5 : 0.5);
  }
  std::vector<Macro> complete;
  for (auto& [key, macro] : macros)
    if (macro.cells.size() == 4) complete.push_back(std::move(macro));
  return complete;
}

/// Orthonormal basis (columns) of the complement of the macro checkerboards.
inline MatrixX checkerboard_complement(const mesh::Mesh<2>& mesh, Real size) {
  const std::vector<Macro> macros = macro_elements(mesh, size);
  MatrixX checkerboards = MatrixX::Zero(mesh.n_cells(), static_cast<Index>(macros.size()));
  for (std::size_t m = 0; m < macros.size(); ++m)
    for (int k = 0; k < 4; ++k)
      checkerboards(macros[m].cells[k], static_cast<Index>(m)) = macros[m].signs[k];
  const Eigen::HouseholderQR<MatrixX> qr(checkerboards);
  const MatrixX q = qr.householderQ();
  return q.rightCols(mesh.n_cells() - checkerboards.cols());
}

} // namespace inf_sup_detail

using namespace inf_sup_detail;

template <int dim>
InfSupEstimate inf_sup_constant(const mesh::Mesh<dim>& mesh, fem::PressureSpace space,
                                bool macro_filter) {
  FF_ASSERT(!macro_filter || space == fem::PressureSpace::P0, "the macro filter acts on P0");
  Index n_free = 0;
  const std::vector<Index> free = interior_dofs(mesh, n_free);
  const PressureNumbering pressure = number_pressures(mesh, space);
  const int n_p = fem::pressure_functions_per_cell<dim>(space);
  const int n_local = mesh.nodes_per_cell() * dim;
  const fem::QuadratureRule<dim> rule = fem::full_rule<dim>(mesh.cell_type());
  fem::CellValues<dim> values(mesh.cell_type(), rule);
  typename fem::CellValues<dim>::Gradients coordinates(dim, mesh.nodes_per_cell());

  MatrixX laplacian = MatrixX::Zero(n_free, n_free);
  MatrixX divergence = MatrixX::Zero(pressure.n_dofs, n_free);
  MatrixX mass = MatrixX::Zero(pressure.n_dofs, pressure.n_dofs);
  std::vector<Index> dofs;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    values.reinit(coordinates);
    dofs = fem::dofs_of_nodes<dim>(mesh.cells.col(cell));
    for (int q = 0; q < values.n_points(); ++q) {
      const auto& grad = values.gradients(q);
      const Eigen::Map<const VectorX> divergence_row(grad.data(), n_local);
      const VectorX psi = fem::tabulate_pressure<dim>(space, rule.points[q]);
      const MatrixX grad_grad = grad.transpose() * grad; // ∇φ_a·∇φ_b
      for (int r = 0; r < n_local; ++r) {
        const Index row = free[dofs[r]];
        if (row < 0) continue;
        for (int c = 0; c < n_local; ++c) {
          const Index column = free[dofs[c]];
          if (column >= 0 && r % dim == c % dim)
            laplacian(row, column) += values.JxW(q) * grad_grad(r / dim, c / dim);
        }
        for (int i = 0; i < n_p; ++i)
          divergence(pressure.dofs(i, cell), row) += values.JxW(q) * psi[i] * divergence_row[r];
      }
      for (int i = 0; i < n_p; ++i)
        for (int j = 0; j < n_p; ++j)
          mass(pressure.dofs(i, cell), pressure.dofs(j, cell)) += values.JxW(q) * psi[i] * psi[j];
    }
  }
  FF_ASSERT(dim == 2 || !macro_filter, "the macro filter is the square mesh's");
  if constexpr (dim == 2)
    if (macro_filter) {
      Real size = (mesh.nodes.col(mesh.cells(mesh.nodes_per_cell() - 1, 0)) -
                   mesh.nodes.col(mesh.cells(0, 0)))[0];
      const MatrixX basis = checkerboard_complement(mesh, size);
      divergence = basis.transpose() * divergence;
      mass = basis.transpose() * mass * basis;
    }
  const Eigen::LLT<MatrixX> factor(laplacian);
  const MatrixX schur = divergence * factor.solve(divergence.transpose()); // B A⁻¹ Bᵀ
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixX> eigen(schur, mass,
                                                                Eigen::EigenvaluesOnly);
  const VectorX& lambda = eigen.eigenvalues();
  InfSupEstimate estimate;
  estimate.n_velocity_dofs = n_free;
  estimate.n_pressure_dofs = static_cast<Index>(mass.rows());
  const Real threshold = 1e-10 * lambda.maxCoeff();
  for (Index k = 0; k < lambda.size(); ++k) {
    if (lambda[k] < threshold) {
      ++estimate.n_null_modes;
      continue;
    }
    estimate.beta = std::sqrt(lambda[k]);
    break;
  }
  return estimate;
}

inline VectorX filter_checkerboard(const mesh::Mesh<2>& mesh, Real size,
                                   const VectorX& cell_values) {
  VectorX filtered = cell_values;
  for (const Macro& macro : macro_elements(mesh, size)) {
    Real amplitude = 0.0; // the macro's checkerboard component (cells of equal area)
    for (int k = 0; k < 4; ++k) amplitude += macro.signs[k] * cell_values[macro.cells[k]];
    for (int k = 0; k < 4; ++k) filtered[macro.cells[k]] -= amplitude * macro.signs[k];
  }
  return filtered;
}

} // namespace formflow::testing
