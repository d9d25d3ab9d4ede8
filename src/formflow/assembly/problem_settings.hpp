// SPDX-License-Identifier: MIT
// Everything the discrete forming problem depends on besides the mesh.
#pragma once

#include "formflow/assembly/contact_normals.hpp"
#include "formflow/assembly/distribution.hpp"
#include "formflow/physics/flow_law.hpp"
#include "formflow/physics/friction.hpp"
#include "formflow/physics/process.hpp"

namespace formflow::assembly {

/// Everything the discrete problem depends on besides the mesh.
struct ProblemSettings {
  physics::Process process;
  physics::FlowLaw law;
  physics::ViscousStrain viscous_strain = physics::ViscousStrain::Full;
  physics::Penalty penalty;
  physics::Friction friction;
  int volumetric_points = 2; ///< Gauss points per direction of the (1/d) term
  Real initial_rate = 1.0;   ///< ε̄̇ of the constant viscosity that starts the iteration
  physics::Symmetry symmetry = physics::Symmetry::Plane; ///< axisymmetric: dim = 2 only
  ContactSettings contact;   ///< face or nodal contact normals (assembly/contact_normals.hpp)
  Distribution distribution; ///< a distributed run: the rank assembles its own cells only
};

} // namespace formflow::assembly
