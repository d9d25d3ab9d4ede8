// SPDX-License-Identifier: MIT
// The run plan: the case translated once into what each loop of a run consumes
// (issue 43). Nothing below the front ends reads the case itself.
#pragma once

#include "formflow/app/solve_plan.hpp"
#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/problem_settings.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/mesh/any_mesh.hpp"
#include "formflow/mesh/mesh_spec.hpp"
#include "formflow/physics/manufactured.hpp"
#include "formflow/physics/thermal.hpp"
#include "formflow/post/adaptivity.hpp"
#include "formflow/solvers/stage_table.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <functional>
#include <map>
#include <string>

namespace formflow::app {

/// Where the keys got their values, for errors found after the translation (a PETSc
/// option nothing read, a composition refused on several ranks): the case file or
/// "--set" and the line, by dotted key name; keys left at their defaults are absent.
struct KeyPlaces {
  struct Place {
    std::string file;
    int line = 0;
  };
  std::string source; ///< the case file path, or "<default>"
  std::map<std::string, Place> places;

  bool given(const std::string& key) const { return places.count(key) > 0; }
  /// An InputError for `key` at its place (the case's source, line 0, if defaulted).
  InputError error(const std::string& key, const std::string& message,
                   const std::string& hint) const;
};

/// The mesh source: makes or reads the cells of a spec (the plan's, or a coarse level's
/// or an estimate level's, which vary its size). Bound by the front end to io's reader,
/// which checks the cells and blames the case's keys for a bad file.
using MeshMaker = std::function<mesh::AnyMesh(const mesh::MeshSpec&)>;

/// Everything a run reads, each layer's own parameter struct, from one translation of
/// the case (app/case_translation.cpp, make_run_plan). Stages that run an inner solve
/// differently (a coarse level, a coupling step's tolerance, an adaptive cycle's
/// estimate) hand it a changed copy, never the case.
struct RunPlan {
  // The mesh.
  mesh::MeshSpec mesh; ///< source, size, geometry, file, boundary map, box distortion
  MeshMaker make_mesh; ///< the cells of a spec (never empty in a translated plan)
  fem::ElementKind element = fem::ElementKind::Q2;
  // The discrete problem.
  /// Process, flow law (at the billet's temperature when hot), penalties, friction (with
  /// the loop's augmentation), rules, symmetry, contact points, this rank's distribution.
  assembly::ProblemSettings problem;
  assembly::Formulation formulation; ///< penalty or mixed, the pressure and its treatment
  // The solve.
  SolvePlan solve;                  ///< loop, linear back-end, coarse levels, augmentation
  solvers::IterationControl solver; ///< δ, limits, the estimate's method, PETSc options
  // The outer loops' settings (app/stages/).
  physics::Thermal thermal;
  post::AdaptSettings adapt;
  physics::ManufacturedSolution manufactured = physics::ManufacturedSolution::None;
  /// Which stages the run composes (solvers/stage_table.hpp refuses what does not).
  solvers::StageSet stages;
  // Errors.
  KeyPlaces keys;

  bool is_manufactured() const { return manufactured != physics::ManufacturedSolution::None; }
};

} // namespace formflow::app
