// SPDX-License-Identifier: MIT
// Case keys of the [formulation] section (Penalty or mixed form): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

using physics::ViscousStrain;

std::vector<CaseKey> formulation_keys() {
  return {
      enum_key(
          "formulation.viscous_strain", "full",
          {{"full", ViscousStrain::Full}, {"deviatoric", ViscousStrain::Deviatoric}},
          [](auto& c) -> auto& { return c.viscous_strain; })
          .doc("strain rate in the viscous a-form: the full ε̇ (paper eq. 3.3) or its deviator "
               "ė (the same as d → 0)"),
      enum_key(
          "formulation.type", "penalty",
          {{"penalty", assembly::FormulationType::Penalty},
           {"mixed", assembly::FormulationType::Mixed}},
          [](auto& c) -> auto& { return c.formulation.type; })
          .constraint("unset on triangles and tetrahedra: mixed (their penalty method is the "
                      "mixed formulation with penalty.d > 0)")
          .doc("penalty: problem (3.9), σ_H = ε̇_V/d at the volumetric points; mixed: problem "
               "(3.7), σ_H in formulation.pressure, condensed cell by cell (docs/mixed.md)"),
      enum_key(
          "formulation.pressure", "P1disc",
          {{"P0", fem::PressureSpace::P0},
           {"P1disc", fem::PressureSpace::P1disc},
           {"Q1", fem::PressureSpace::Q1},
           {"P1", fem::PressureSpace::P1}},
          [](auto& c) -> auto& { return c.formulation.pressure; })
          .constraint("mixed with Q1 velocity: P0 only; Q1 (Taylor–Hood) needs Q2 velocity and "
                      "regularized friction; P1 only on simplices, the only one for P1b; unset "
                      "with P1b: P1")
          .doc("pressure space of the mixed formulation: P0 (cell constant), P1disc (cell linear, "
               "discontinuous), both condensed cell by cell, or Q1 (continuous bilinear on the "
               "vertices, Taylor–Hood: global saddle-point solve with UMFPACK), or on triangles "
               "and tetrahedra P1 (continuous linear: Taylor–Hood with P2, MINI with P1b)"),
      enum_key(
          "formulation.discontinuous_pressure", "condensed",
          {{"condensed", assembly::DiscontinuousPressure::Condensed},
           {"saddle_point", assembly::DiscontinuousPressure::SaddlePoint}},
          [](auto& c) -> auto& { return c.formulation.discontinuous; })
          .constraint("saddle_point: mixed with P0 or P1disc; not with cholmod or exact friction")
          .doc("how a discontinuous pressure (P0, P1disc) is solved: condensed cell by cell "
               "(velocity-only SPD systems), or kept as global unknowns of a saddle point "
               "(UMFPACK, or solver.linear = \"petsc\": FGMRES with a fieldsplit Schur "
               "preconditioner by default, docs/petsc.md)"),
      real_key(
          "formulation.augmentation", 1e3,
          [](auto& c) -> auto& { return c.formulation.augmentation; })
          .within(1e-6, 1e8)
          .why(factor_range)
          .doc("ρ of the augmented-Lagrangian term for d = 0: r = ρ × the cell's mean secant "
               "viscosity; larger = fewer Uzawa steps, worse conditioning"),
      real_key(
          "formulation.contact_augmentation", 1e6,
          [](auto& c) -> auto& { return c.formulation.contact_augmentation; })
          .within(1e-6, 1e12)
          .why(penalty_range)
          .unit("stress·time/length")
          .doc("r_N of the augmented-Lagrangian contact term for dN = 0 (plays the role of 1/d_N)"),
      real_key(
          "formulation.uzawa_tolerance", 1e-8,
          [](auto& c) -> auto& { return c.formulation.uzawa_tolerance; })
          .at_least(1e-15)
          .below(1)
          .why(tolerance_range)
          .doc("Uzawa steps (d = 0 or dN = 0) end when the multipliers change by less than "
               "this, relative, or stop changing at a round-off floor below its square root"),
      integer_key(
          "formulation.uzawa_max_steps", 50,
          [](auto& c) -> auto& { return c.formulation.uzawa_max_steps; })
          .at_least(1)
          .at_most(10000)
          .doc("Uzawa steps per secant iteration at most (each is one solve with the same "
               "factorisation)"),
  };
}

} // namespace formflow::io::keys
