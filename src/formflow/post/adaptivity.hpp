// SPDX-License-Identifier: MIT
// Adaptive refinement driven by the load's error indicators: settings, marking, sizes.
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/mesh/mesh.hpp"

#include <optional>
#include <string>
#include <vector>

namespace formflow::post {

/// The [adapt] section (docs/error-estimation.md, "Adaptivity").
struct AdaptSettings {
  /// Stop when the load's error estimate is at most this fraction of |load|;
  /// 0 (the default): no adaptivity, the run is one solve on the case's mesh.
  Real target_error = 0.0;
  int max_cycles = 8;      ///< solves, the first (on the case's mesh) included
  Index max_dofs = 400000; ///< no cycle on a mesh expected to have more dofs
  Real fraction = 0.5;     ///< Dörfler's θ: refine the cells holding this share of Σ|η_K|
  /// Coarsen (double the size of, up to the case's mesh.size) the most cells, smallest
  /// |η_K| first, that hold at most this share of Σ|η_K|; 0: never coarsen.
  Real coarsen_fraction = 0.05;
  /// Not a key: inside an adaptive run, the target its cycles' estimates are held to
  /// (the estimate skips its penalty run while its discretisation part alone exceeds it).
  Real cycle_target = 0.0;
  /// Not a key: an intermediate cycle's estimate is its indicators and linearised
  /// change only ("linearized", no third level, no regularisations' solve): what the
  /// marking needs, one factorisation on the refined mesh (app/adaptive_run.cpp).
  bool indicators_only = false;
  bool enabled() const { return target_error > 0; }
};

/// One solve of an adaptive run, as summary.json `adapt.cycles` records it.
struct AdaptCycle {
  Index cells = 0, dofs = 0;
  Real load = 0.0;              ///< the ram pressure (drawing: the drawing stress) p_h
  std::optional<Real> estimate; ///< of |p_h − p|; none: not computed (it ends the run)
  /// True when `estimate` is a prediction, not the bound: the linearised change scaled
  /// by the ratio settled/linearised of the last full estimate (an intermediate cycle
  /// that only marked; app/adaptive_run.cpp).
  bool estimate_predicted = false;
  int newton_iterations = 0;
  Index marked = 0;   ///< cells marked for refinement after this cycle (0 for the last)
  Real seconds = 0.0; ///< wall time of the cycle: solve, estimate, marking, remeshing
  /// CPU time of the process over the cycle (std::clock: every thread's; with one BLAS
  /// thread, the cycle's own work however loaded the machine is).
  Real cpu_seconds = 0.0;
  Real estimate_seconds = 0.0; ///< wall time of its "error estimate" phase
  /// The previous cycle's mesh split uniformly (the estimate's refined mesh), solved
  /// from the estimate's settled solution: the run ended on it.
  bool refined_mesh = false;
};

/// The record of an adaptive run: empty `cycles` when there was none.
struct AdaptRecord {
  std::vector<AdaptCycle> cycles;
  std::string stop; ///< why the cycles ended: target reached, max_cycles, max_dofs, ...
  bool reached_target = false;
};

/// Dörfler (bulk) marking: the fewest cells, largest |η_K| first, whose |η_K| sum to
/// at least `fraction` of Σ|η_K|. Signed indicators are marked by magnitude: a
/// cell whose refinement raises the load needs it as much as one that lowers it.
/// Returns one flag per cell.
std::vector<bool> dorfler_marking(const VectorX& indicators, Real fraction);

/// Coarsening's counterpart of dorfler_marking: the most cells, smallest |η_K| first,
/// whose |η_K| sum to at most `fraction` of Σ|η_K| (none for fraction 0). Coarsening
/// them at most doubles their share at first order, so the estimate grows by at most
/// `fraction` of itself while the marked cells remove θ of it.
std::vector<bool> coarsening_marking(const VectorX& indicators, Real fraction);

/// The side of a square of the cell's area (corner nodes; Q2's curved edges
/// ignored), the size Gmsh's target sizes mean.
Real cell_side(const mesh::Mesh<2>& mesh, Index cell);

/// The target size at each node of `mesh` for the next mesh: marked cells halve
/// their side, `coarsened` ones double it up to `largest_size` (the case's mesh.size),
/// the others keep it; a node takes the smallest of its cells' (so a refined cell is
/// not widened by its neighbours' interpolation). Then no node of a cell may be more
/// than twice the cell's smallest node size (swept until it holds): without that
/// grading a coarsened cell beside a refined one asked Gmsh for a jump it could not
/// recombine into quadrilaterals (Hill's 15° wedge: triangles left, the remesh refused).
VectorX target_node_sizes(const mesh::Mesh<2>& mesh, const std::vector<bool>& marked,
                          const std::vector<bool>& coarsened, Real largest_size);

} // namespace formflow::post
