// SPDX-License-Identifier: MIT
// Process, penalty and friction parameters of the forming problem (SPEC §1–2).
#pragma once

#include "formflow/core/types.hpp"

namespace formflow::physics {

enum class ProcessType { Extrusion, Drawing };
/// Ram condition on Γ1 for extrusion (SPEC §4): sliding = the paper's σ_T = 0
/// (u_y free); sticking = u_y = 0 as well.
enum class RamCondition { Sliding, Sticking };
/// Strain rate used in the a-form: the full ε̇ (paper eq. 3.3, default) or its deviator ė.
enum class ViscousStrain { Full, Deviatoric };
/// Plane strain, or axial symmetry about the x axis (y = r): hoop rate u_r/r and
/// r-weighted integrals (per radian, so forces are per radian and areas ∫ r dr).
enum class Symmetry { Plane, Axisymmetric };

struct Process {
  ProcessType type = ProcessType::Extrusion;
  Real speed = 1.0; ///< u⁰, the prescribed normal speed on Γ1 (extrusion) or Γ5 (drawing)
  RamCondition ram = RamCondition::Sliding;
};

/// Penalty parameters of eq. (3.8): σ_H = ε̇_V/d, σ_N = −u_N/d_N.
struct Penalty {
  Real d = 1e-3;
  Real d_n = 1e-6;
};

/// How the Coulomb law is imposed: the paper's regularisation |u_T| → √(|u_T|² + d_T²)
/// (eq. 3.14), or exactly, by an augmented Lagrangian on the friction traction.
enum class FrictionRegularization { Regularized, None };

/// Which threshold τ_f the friction law has (physics/friction_laws/*.hpp, registered in
/// physics/friction.hpp visit_threshold): Coulomb μ max(σ̄_N, 0), Tresca m k, or the
/// hybrid min of the two.
enum class FrictionLaw { Coulomb, Tresca, Hybrid };

/// Friction on the chosen parts of Γ3: a threshold (friction.law) times an enforcement
/// (friction.regularization): the paper's regularised law (eq. 3.14–3.15) or the exact one.
struct Friction {
  FrictionLaw law = FrictionLaw::Coulomb;
  Real mu = 0.0;     ///< Coulomb coefficient μ_f ≥ 0
  Real m = 0.0;      ///< Tresca friction factor, 0 ≤ m ≤ 1
  Real radius = 0.0; ///< mollifier radius h of σ̄_N; 0 = local pressure
  Real d_t = 1e-6;   ///< regularisation d_T > 0
  bool on_container = true;
  bool on_die = true;
  FrictionRegularization regularization = FrictionRegularization::Regularized;
  /// Exact friction only: augmentation r of λ_T = proj(λ_T + r u_T), in units of
  /// 1/d_N (r = augmentation / d_N), so the stick penalty is as stiff as the normal one.
  Real augmentation = 1.0;
  /// The same when exact friction is solved by Newton (solvers/augmented_newton.hpp):
  /// its tangent has the stick penalty r in it, so r can be stiffer at no cost.
  Real newton_augmentation = 100.0;
};

} // namespace formflow::physics
