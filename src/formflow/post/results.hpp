// SPDX-License-Identifier: MIT
// Everything a solve produces: iteration outcome, load measures and fields.
#pragma once

#include "formflow/assembly/terms/term.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/core/types.hpp"
#include "formflow/post/adaptivity.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace formflow::post {

/// Process load measured in several honest ways (SPEC §4), all divided by the
/// measure of the end the speed is imposed on (ram, or exit for drawing): per unit
/// depth of the half model over its height in 2D (per radian over ∫ r dr in
/// axisymmetry), over the end's area of the modelled part in 3D.
struct Pressures {
  Real ram_reaction = 0.0;  ///< reaction force on the driven end / its height
  Real power_balance = 0.0; ///< (plastic dissipation + friction power) / (u⁰·height)
  Real total_power = 0.0;   ///< all discrete terms of b and j_dT / (u⁰·height)
  /// Mean of −σ_H (compression positive) over the column of cells touching the ram.
  Real mean_hydrostatic_near_ram = 0.0;
};

/// Powers (per unit depth of the half model in 2D, of the whole model in 3D) of each
/// discrete term at the final velocity:
/// the sum over the weak-form terms (assembly/terms/term.hpp).
using PowerTerms = assembly::PowerTerms;

/// One sample of the contact boundary Γ3 (a facet quadrature point): ordered by
/// arc length in a plane run; in a solid run Γ3 is a surface, which has none
/// (post/contact_profile.cpp says the order then).
struct ContactSample {
  Real arc_length = 0.0; ///< s, measured along Γ3 from the ram end of the container wall; 0 in 3D
  Real x = 0.0, y = 0.0;
  Real z = 0.0;                ///< 0 in a plane run
  Real contact_pressure = 0.0; ///< −σ_N = u_N/d_N (local, not mollified)
  Real friction_stress = 0.0;  ///< |σ_T| = |λ_T|, the friction traction magnitude
  Real slip_velocity = 0.0;    ///< |u_T|
  bool sticking = false;       ///< ContactPoint::sticking (regularised: |u_T| < 7 d_T)
  int part = 0;                ///< 0 container, 1 die (mesh::BoundaryLabel order)
};

/// The flow through the exit section (the "front" facets) against the entry (the "rear"
/// facets): what extrusion engineers read (post/exit_flow.hpp). In axisymmetry the
/// integrals are per radian, like every other one.
/// One edge of a profile's outline at the exit: the mean axial velocity over the part of
/// the exit section nearer to this edge than to any other (its leg, in a profile of legs).
struct ExitEdge {
  std::array<Real, 2> from{}, to{}; ///< the edge's ends (y, z)
  Real bearing_length = 0.0;        ///< its bearing
  Real area = 0.0;                  ///< the exit section nearest to it (whole section)
  Real velocity_mean = 0.0;         ///< ∫ u_x dA / ∫ dA over that part
};

struct ExitFlow {
  bool present = false; ///< the mesh has both an exit and an entry section
  /// Axial velocity u_x over the exit: the smallest and largest at the exit's nodes, and
  /// the mean ∫ u_x dA / ∫ dA.
  Real velocity_min = 0.0, velocity_mean = 0.0, velocity_max = 0.0;
  /// (max − min) / mean; none where the mean speed is not positive (a field that moves no
  /// metal out, e.g. the prescribed values alone after a failed first solve).
  std::optional<Real> nonuniformity;
  Real area = 0.0;         ///< ∫ dA of the exit section
  Real exit_flux = 0.0;    ///< ∫ u·n dA over the exit (outflow > 0)
  Real entry_flux = 0.0;   ///< −∫ u·n dA over the entry (inflow > 0)
  Real flux_balance = 0.0; ///< exit_flux / entry_flux − 1
  /// ∫ u·n dA (outward) through the free surfaces and through the contact walls: with
  /// the exit and entry fluxes they add up to ∫ div u dV, which the penalty makes
  /// d ∫ σ_H dV (the material's compressibility), so flux_balance is that and the leaks.
  Real free_surface_flux = 0.0, wall_flux = 0.0;
  /// Plane and axisymmetric runs: (y, u_x) at the exit's nodes, y ascending, each node
  /// once (the exit_velocity picture). Empty in 3D.
  std::vector<std::array<Real, 2>> profile;
  /// A profile's outline edges in order (post/exit_flow.hpp profile_exit_edges); empty
  /// for the other channels.
  std::vector<ExitEdge> edges;
};

/// Stick and slip zones of one contact part, measured with the Γ3 quadrature weights
/// (each point stands for its share JxW of the boundary).
struct ContactZones {
  Real length = 0.0;       ///< measure of the part: a length in 2D, an area in 3D
  Real stick_length = 0.0; ///< where ContactPoint::sticking
  Real slip_length() const { return length - stick_length; }
};

/// Outcome of the augmented-Lagrangian loop of exact friction (zero when regularised).
struct Augmentation {
  int outer_iterations = 0;     ///< multiplier updates
  Real multiplier_change = 0.0; ///< last ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖ in L²(Γ3)
  /// Last residual of the Coulomb conditions, ‖λ − proj(λ + r̄ u_T)‖/‖λ‖ in L²(Γ3) at
  /// the problem's scale r̄ = ‖λ‖/‖u_T‖ (solvers/friction_residual.hpp).
  Real friction_residual = 0.0;
  /// Newton: last power of the residual relative to the ram's, |u_f·R_f|/|u·f|_driven,
  /// = |reaction − total power|/reaction (solvers/power_residual.hpp); 0 for secant.
  Real power_residual = 0.0;
};

/// Hot forming (thermal.enabled): the temperature and where the heat went, per unit
/// depth (per radian in axisymmetry), at the final velocity (assembly/heat_problem.hpp).
struct ThermalResults {
  bool enabled = false;
  VectorX temperature;                                  ///< n_nodes
  Real exit_min = 0.0, exit_mean = 0.0, exit_max = 0.0; ///< on Γ5; mean flux-weighted
  Real max_temperature = 0.0;                           ///< max nodal T
  Real min_temperature = 0.0;                           ///< min nodal T
  Real deformation = 0.0;                               ///< β ∫ σ_p ε̄̇ dx
  Real friction = 0.0;                                  ///< share ∫_Γ3 τ_f|u_T| dΓ
  Real tools = 0.0;            ///< ∫_Γ3 h (T − T_tool) dΓ, positive out of the workpiece
  Real free_surfaces = 0.0;    ///< ∫_Γ2∪Γ4 h_free (T − T_ambient) dΓ
  Real convected = 0.0;        ///< ∫ ρc u·∇T dx (convected out − in)
  Real conducted = 0.0;        ///< conducted out through the rear end
  int coupling_iterations = 0; ///< staggered steps (a flow solve and a heat solve each)
  bool coupling_converged = false;
  Real temperature_change = 0.0; ///< last coupling step's max|ΔT| / max|T − T_billet|
  /// last coupling step's |Δp|/|p|; none before a second flow solve
  std::optional<Real> force_change;
  std::vector<int> flow_iterations; ///< nonlinear iterations of each flow solve
};

/// Fields on the mesh nodes (averaged from integration points) and cell means.
struct Fields {
  /// Velocity, shape (dim · n_nodes), node-major: (u_x, u_y) of node 0, node 1, ...
  VectorX velocity;
  VectorX equivalent_strain_rate;      ///< n_nodes, ε̄̇
  VectorX hydrostatic_stress;          ///< n_nodes, σ_H (tension positive)
  VectorX contact_pressure;            ///< n_nodes, 0 away from Γ3
  VectorX friction_stress;             ///< n_nodes, 0 away from Γ3
  VectorX cell_equivalent_strain_rate; ///< n_cells, cell mean
  VectorX cell_hydrostatic_stress;     ///< n_cells, cell mean
  VectorX temperature;                 ///< n_nodes (hot forming); empty: isothermal
  /// n_cells, each cell's share of the load's error estimate (LoadErrorEstimate::
  /// cell_indicators, pressure units, signed); empty when it was not computed.
  VectorX cell_load_error;
};

/// Which linear back-end ran and what it did (summary.json linear_algebra).
struct LinearAlgebra {
  std::string solver = "cholmod"; ///< solver.linear's spelling
  /// Krylov iterations of the fine-mesh loop's solves (per step in history's
  /// linear_iterations); −1 for a direct back-end that has no such count.
  long iterations = -1;
  int ranks = 1; ///< MPI ranks of the run
  /// How the cells were split among the ranks (a PETSc partitioner's type, or "slabs");
  /// empty on one rank.
  std::string partition;
  /// A distributed run: per rank, the dofs it owns and its ghosts (the velocity each
  /// rank holds is their sum, not the whole: assembly::OwnedDofs); empty on one rank.
  std::vector<std::pair<Index, Index>> rank_dofs;
  /// Matrix and factor nonzeros (and flops) of the fine mesh's last analysis
  /// (solvers::FactorSize: −1 when the back-end does not report them).
  double matrix_nonzeros = -1;
  double factor_nonzeros = -1;
  double factor_flops = -1;
};

/// The goal-oriented estimate of the load's discretisation error
/// (post/load_error_estimate.hpp; pressure units: force / driven height).
struct LoadErrorEstimate {
  /// Estimate of |p_h − p| for p the load of the continuous problem with the
  /// constraint penalties removed (d, d_N, d_T → 0): discretisation_error +
  /// |penalty_change| (post::load_error_bound); std::nullopt when it was not
  /// computed (`unavailable` says why).
  std::optional<Real> error;
  std::string unavailable;
  /// The method that ran: "coarser", "refined" or "linearized" (solver.load_error
  /// "auto" resolved); empty when none did.
  std::string method;
  /// p_{h/2} − p_h linearised at the prolonged solution (signed): the DWR sum.
  Real enriched_change = 0.0;
  Index enriched_dofs = 0;
  int settle_iterations = 0; ///< Newton iterations on the refined mesh before the adjoint
  /// p_h − p_{2h} from a solve on the mesh coarsened once (structured channels whose
  /// lengths admit 2h), and the contraction ratio (p_{h/2} − p_h)/(p_h − p_{2h}) it
  /// gives; std::nullopt without that level.
  std::optional<Real> coarser_change;
  /// Where the channel admits no 2h: p_{h/4} − p_{h/2} from a solve on the mesh
  /// refined twice, and observed_ratio = (p_{h/4} − p_{h/2})/(p_{h/2} − p_h).
  std::optional<Real> finer_change;
  /// "coarser" only: p_{2h} − p_{4h} from a solve on the mesh coarsened twice, and
  /// observed_ratio = (p_h − p_{2h})/(p_{2h} − p_{4h}); the Newton iterations on 2h
  /// and 4h together.
  std::optional<Real> coarsest_change;
  Index coarser_newton_iterations = 0;
  std::optional<Real> observed_ratio;
  /// The ratio q used for the tail: max(2^{-r_max}, observed ratio) (post::tail_ratio).
  Real ratio = 0.5;
  /// F_s |p_{h/2} − p_h| / (1 − q) (post::discretisation_tail): the discretisation
  /// part of `error`.
  Real discretisation_error = 0.0;
  /// p_h(2ε) − p_h(ε), every regularisation (d, d_N, d_T and the paper's power law's
  /// α) doubled on the same mesh: by the first-order expansion in ε, the estimate of
  /// p(ε) − p(0); its magnitude is the model part of `error`. std::nullopt when
  /// skipped: an adaptive cycle whose tail beyond its refined mesh alone is above the
  /// target (the stop needs no more).
  std::optional<Real> penalty_change;
  Index penalty_newton_iterations = 0;
  /// The settled solution on the refined mesh ("refined" only; empty otherwise): an
  /// adaptive run's last step starts there (app/adaptive_run.cpp).
  VectorX refined_velocity;
  /// True when this estimate is of the refined mesh's load p_{h/2} (an adaptive run
  /// that ended on it): error = F_s |p_{h/2} − p_h| q/(1 − q) + |penalty_change|.
  bool of_refined_mesh = false;
  /// Per cell of the mesh that ran, its share of `enriched_change` (signed; the
  /// entries sum to it): the local error indicator. Empty when not computed.
  VectorX cell_indicators;
};

struct Results {
  solvers::StopReason stop_reason = solvers::StopReason::MaxIterations;
  bool converged() const { return stop_reason == solvers::StopReason::Converged; }
  /// The nonlinear loop that actually ran: solver.method does not reach every
  /// formulation yet (Newton covers the plane and axisymmetric penalty problems).
  std::string method = "secant";
  int iterations = 0;
  std::vector<solvers::IterationRecord> history;
  /// Mesh sequencing (solver.coarse_levels): Newton iterations and mesh size per
  /// coarse level, coarsest first; not counted in `iterations`. Empty: none.
  std::vector<int> coarse_iterations;
  std::vector<Real> coarse_mesh_sizes;
  /// Adaptive refinement ([adapt]): one record per cycle; empty without it.
  AdaptRecord adapt;

  int dimension = 2; ///< of the mesh: 2 (quadrilaterals) or 3 (hexahedra)
  Index n_cells = 0, n_nodes = 0, n_dofs = 0;
  /// Smallest and largest cell diameter (mesh/cell_diameter.hpp): the mesh's h,
  /// also when it was read from a file and no mesh.size made it.
  Real min_cell_diameter = 0.0, max_cell_diameter = 0.0;
  Pressures pressure;
  PowerTerms power;
  Real max_equivalent_strain_rate = 0.0;
  Fields fields;
  std::vector<ContactSample> contact;
  ContactZones container_zones, die_zones;
  ExitFlow exit; ///< the exit section's velocities and the flux balance
  Augmentation augmentation;
  ThermalResults thermal;
  LoadErrorEstimate load_error;
  PhaseTimes timing; ///< seconds per phase: total, mesh, assembly, factorization, solve, post
  LinearAlgebra linear_algebra;
  std::vector<int> cell_ranks; ///< a distributed run: each cell's rank (the pvtu's pieces)
};

} // namespace formflow::post
