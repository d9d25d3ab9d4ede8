// SPDX-License-Identifier: MIT
// Where the assembler's local matrices, loads and forces go. Today's sink is the
// precomputed slot scatter into a LinearSystem (assembly/sparsity.hpp); a
// distributed matrix is another sink behind the same three calls.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/mesh.hpp"

namespace formflow::assembly {

/// Receives one cell's contributions (local dof a·dim + i: component i at local node a).
class AssemblySink {
public:
  virtual ~AssemblySink() = default;
  /// The symmetric local matrix of `cell` (secant or tangent).
  virtual void add_matrix(Index cell, const MatrixX& local) = 0;
  /// The local loads F_e of `cell` (right-hand side; on prescribed dofs part of the reaction).
  virtual void add_load(Index cell, const VectorX& local) = 0;
  /// The local internal force K_e(u) u_e − F_e of `cell`.
  virtual void add_force(Index cell, const CellVector& local) = 0;
  /// Whether cells that share no node may be added from several threads at once (the
  /// sink writes only entries of the cell's own dofs, or of the cell itself).
  virtual bool concurrent() const { return false; }
};

/// The serial sink: matrices into the free system (prescribed columns to the rhs,
/// prescribed rows to the reaction rows) by the scatter plan's slots, loads into the rhs
/// or the prescribed loads, forces into a full dof vector.
template <int dim> class ScatterSink final : public AssemblySink {
public:
  /// `system` may be null (forces only), `internal_force` may be null (no forces).
  ScatterSink(const mesh::Mesh<dim>& mesh, const ScatterPlan& plan,
              const VectorX& prescribed_values, LinearSystem* system, VectorX* internal_force)
      : mesh_(mesh), plan_(plan), prescribed_values_(prescribed_values), system_(system),
        internal_force_(internal_force) {}

  void add_matrix(Index cell, const MatrixX& local) override {
    plan_.scatter(cell, local, prescribed_values_, *system_);
  }
  void add_load(Index cell, const VectorX& local) override {
    for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
      for (int i = 0; i < dim; ++i) {
        const Index dof = fem::dof_of<dim>(mesh_.cells(a, cell), i);
        const Real load = local[a * dim + i];
        if (const Index free = plan_.free_index(dof); free >= 0)
          system_->rhs[free] += load;
        else
          system_->prescribed_loads[plan_.prescribed_index(dof)] += load;
      }
  }
  void add_force(Index cell, const CellVector& local) override {
    for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
      internal_force_->template segment<dim>(fem::dof_of<dim>(mesh_.cells(a, cell), 0)) +=
          local.template segment<dim>(a * dim);
  }
  /// A cell's matrix entries, right-hand side, prescribed loads, reaction rows and forces
  /// are all at its own dofs (ScatterPlan::scatter).
  bool concurrent() const override { return true; }

private:
  const mesh::Mesh<dim>& mesh_;
  const ScatterPlan& plan_;
  const VectorX& prescribed_values_;
  LinearSystem* system_;
  VectorX* internal_force_;
};

} // namespace formflow::assembly
