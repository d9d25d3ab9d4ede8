// SPDX-License-Identifier: MIT
// The steady heat equation of hot forming on the workpiece mesh (issue 18, SPEC §6):
// ρc u·∇T = ∇·(κ∇T) + q, SUPG-stabilised, in the velocity components' Lagrange space.
#pragma once

#include "formflow/assembly/discretisation.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/physics/thermal.hpp"

#include <functional>
#include <span>
#include <vector>

namespace formflow::assembly {

/// The heat released in the workpiece at one velocity.
struct HeatSources {
  /// q = β σ_p ε̄̇ at every full-rule point, cell-major (power per volume).
  std::vector<Real> deformation;
  /// The friction heat entering the workpiece, share·λ_T·u_T, at every Γ3 point in
  /// contact_state() order (power per area); empty: none.
  std::vector<Real> friction;
};

/// Where the heat goes, per unit depth (per radian in axisymmetry): deformation +
/// friction = tools + free_surfaces + convected + conducted, exactly for the discrete
/// solution (the test function 1: SUPG's and diffusion's sums vanish, Σ_a ∇N_a = 0).
struct HeatBalance {
  Real deformation = 0.0;   ///< ∫ q dx = β × the plastic power of the same rule
  Real friction = 0.0;      ///< ∫_Γ3 share τ_f|u_T| dΓ (the friction power's own points)
  Real tools = 0.0;         ///< ∫_Γ3 h (T − T_tool) dΓ, positive out of the workpiece
  Real free_surfaces = 0.0; ///< ∫_Γ2∪Γ4 h_free (T − T_ambient) dΓ
  Real convected = 0.0;     ///< ∫ ρc u·∇T dx: the convected heat out − in (∇·u = 0)
  Real conducted = 0.0;     ///< conducted out through the rear end (its Dirichlet reaction)
};

/// The linear heat system for one velocity: A_ff T_f = b_f (full storage, unsymmetric).
struct HeatSystem {
  SparseMatrix matrix; ///< A_ff, both triangles
  VectorX rhs;         ///< b_f − A_fD T_D
};

/// The heat problem on the mesh of a forming problem. T lives on the mesh's nodes in the
/// Lagrange space of one velocity component (Q1 or Q2): the velocity needs no
/// interpolation, the cached geometry of the full rule serves both problems, and the
/// heat source at the full-rule points is the viscous term's integrand itself, so its
/// integral is β times the discrete plastic power exactly.
template <int dim> class HeatProblem {
public:
  /// T of the nodes where it is prescribed: `boundary_temperature` at the nodes of every
  /// boundary facet when given (a manufactured solution, all of ∂Ω Dirichlet), else
  /// thermal.billet_temperature on the rear end Γ1.
  using BoundaryTemperature = std::function<Real(const Point<dim>&)>;
  HeatProblem(const Discretisation<dim>& discretisation, const physics::Thermal& thermal,
              const BoundaryTemperature& boundary_temperature = {});

  Index n_nodes() const { return discretisation_.mesh().n_nodes(); }
  /// The system for the velocity `u` (full dof vector) and the heat sources.
  HeatSystem assemble(const VectorX& u, const HeatSources& sources) const;
  /// Nodal temperatures from the free solution (prescribed ones: the billet's).
  VectorX expand(const VectorX& free_temperatures) const;
  /// Where the heat goes for the nodal temperatures `T` at `u` (HeatBalance).
  HeatBalance balance(const VectorX& u, const HeatSources& sources, const VectorX& T) const;
  /// T at every full-rule point, cell-major (what the flow law is taken at).
  std::vector<Real> point_values(const VectorX& T) const;
  /// T at every Γ3 point, in contact_state() order (what the Tresca and hybrid shear
  /// yield is taken at).
  std::vector<Real> contact_values(const VectorX& T) const;

  /// The outflow end Γ5: min, flux-weighted mean ∫T u·n/∫u·n and max of T at its
  /// quadrature points.
  struct ExitTemperature {
    Real min = 0.0, mean = 0.0, max = 0.0;
  };
  ExitTemperature exit_temperature(const VectorX& u, const VectorX& T) const;

  /// The SUPG parameter τ at one point for ρc|u|, the streamline length h and κ:
  /// τ = h/(2ρc|u|) (coth Pe − 1/Pe), Pe = ρc|u| h/(2κ) (nodally exact in 1D for Q1).
  static Real supg_tau(Real convective_speed, Real length, Real conductivity);

private:
  /// The cell matrix A_e and load b_e (n_nodes × n_nodes, n_nodes).
  void cell_system(Index cell, const VectorX& u, std::span<const Real> deformation, MatrixX& matrix,
                   VectorX& load) const;
  /// Robin terms h (T − T_ref) and the friction heat on one boundary face; `add` gets
  /// (matrix, load) of the face's cell.
  template <class Values>
  void add_face_terms(const Values& values, Real transfer, Real reference,
                      std::span<const Real> friction, MatrixX& matrix, VectorX& load) const;

  /// −ΔN_a (plus −(1/r) ∂N_a/∂r in axisymmetry) at full-rule point q of a cell with node
  /// coordinates `coordinates` and physical gradients `gradients`: the diffusion part of
  /// the SUPG residual, by the isoparametric map's second derivatives.
  VectorX minus_laplacian(const typename fem::CellValues<dim>::Gradients& coordinates,
                          const typename fem::CellValues<dim>::Gradients& gradients, int q,
                          const Point<dim>& point) const;

  const Discretisation<dim>& discretisation_;
  physics::Thermal thermal_;
  /// Reference gradients and second derivatives of the shape functions at the full rule.
  std::vector<typename fem::CellValues<dim>::Gradients> reference_gradients_;
  std::vector<std::vector<Eigen::Matrix<Real, dim, dim>>> reference_hessians_;
  std::vector<bool> prescribed_;  ///< per node: on the rear end (T = T_billet)
  VectorX prescribed_value_;      ///< per node: T where prescribed_ (else unused)
  std::vector<Index> free_index_; ///< per node: index in T_f, or −1
  Index n_free_ = 0;
  std::vector<Index> free_surface_; ///< Mesh::facets indices of Γ2, Γ4
  std::vector<Index> outflow_;      ///< Mesh::facets indices of Γ5
};

} // namespace formflow::assembly
