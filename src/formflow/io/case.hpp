// SPDX-License-Identifier: MIT
// A fully resolved, validated case: every parameter the solver consumes.
#pragma once

#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/contact_normals.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/mesh/mesh_spec.hpp"
#include "formflow/physics/flow_law.hpp"
#include "formflow/physics/manufactured.hpp"
#include "formflow/physics/process.hpp"
#include "formflow/physics/thermal.hpp"
#include "formflow/post/adaptivity.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace formflow::io {

/// Aggregates each layer's own parameter struct. Built only by `load_case`
/// (io/case_file.cpp), which checks every key against io/case_keys.cpp; the
/// defaults here are the paper's benchmark (SPEC §4): Q2, 2×2 volumetric
/// rule, mesh II, μ = 0, d = 1e-3, d_N = 1e-6, d_T = 1e-6, δ = 1e-4.
/// How exact friction's Newton loop holds stuck points (friction.stick): u_T = 0 imposed
/// exactly in every Newton step at the stuck Γ3 nodes, their traction the constraint's
/// reaction (a semismooth Newton, issue 16; on nodal contact points), or the stick
/// penalty r with a multiplier update per iteration (augmented). Auto (the default) is
/// Exact wherever the semismooth Newton serves the case and Augmented elsewhere
/// (io/problem_shape.hpp stick_choice says which).
enum class StickEnforcement { Auto, Augmented, Exact };

struct Case {
  physics::Process process;
  /// Where the cells come from: source, size, channel geometry, file and its
  /// boundary map, the verification box's distortion (mesh/mesh_spec.hpp).
  mesh::MeshSpec mesh;
  physics::Symmetry symmetry = physics::Symmetry::Plane;
  fem::ElementKind element =
      fem::ElementKind::Q2;        ///< the velocity element; its order is the cells'
  int volumetric_points = 2;       ///< Gauss points per direction of the volumetric (penalty) term
  physics::FlowLawChoice material; ///< the law by name, its range and every law's parameters
  physics::ViscousStrain viscous_strain = physics::ViscousStrain::Full;
  assembly::Formulation formulation; ///< penalty or mixed; exact-constraint (Uzawa) settings
  physics::Friction friction;
  StickEnforcement friction_stick = StickEnforcement::Auto; ///< friction.stick, as given
  /// Face or nodal contact points, as given: stick_choice says which the run uses.
  assembly::ContactSettings contact;
  physics::Penalty penalty;
  solvers::IterationControl solver;
  post::AdaptSettings adapt; ///< adaptive refinement by the load's error indicators
  physics::Thermal thermal;  ///< hot forming: the heat problem and its coupling (docs/thermal.md)
  /// Verification: a manufactured solution on the unit square replaces the
  /// process (None: the forming case), on a box mesh with mesh.distortion.
  physics::ManufacturedSolution manufactured = physics::ManufacturedSolution::None;

  std::string source; ///< the case file path, or "<default>" for the embedded benchmark
  /// geometry.profile_file as written (relative: to the case file's directory); its
  /// points are read into mesh.solid.profile.outline when the case is loaded.
  std::string profile_file;

  /// Where a key got its value, for errors found after loading (e.g. in the mesh file).
  struct KeyLocation {
    std::string file; ///< case file path or "--set"
    int line = 0;
  };
  /// By dotted key name; entries of a table key as "key.entry" ("mesh.boundaries.ram").
  /// Keys left at their defaults are absent.
  std::map<std::string, KeyLocation> key_locations;

  /// Lines for stderr about valid but doubtful choices ("file:line: ..."),
  /// e.g. a locking complete volumetric rule with Q1.
  std::vector<std::string> warnings;
};

/// One `--set key=value` override, in command-line order.
using Override = std::pair<std::string, std::string>;

/// Reads and validates `path` (empty: the embedded default case), then applies
/// `overrides`. Throws InputError naming file, line, key and what would be valid.
/// `defaults` replace the key table's defaults before anything is read (a run on
/// several ranks: solver.linear = "petsc"); a key they set still counts as not given.
Case load_case(const std::string& path, const std::vector<Override>& overrides,
               const std::vector<Override>& defaults = {});

/// As load_case, for a case file's `text` already in memory (the fuzz targets,
/// tests); `source` stands for its path in errors and relative mesh paths.
Case load_case_text(const std::string& text, const std::string& source,
                    const std::vector<Override>& overrides);

} // namespace formflow::io
