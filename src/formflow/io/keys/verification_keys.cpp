// SPDX-License-Identifier: MIT
// Case keys of the [verification] section (Manufactured solutions): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

std::vector<CaseKey> verification_keys() {
  using physics::ManufacturedSolution;
  return {
      enum_key(
          "verification.solution", "none",
          {{"none", ManufacturedSolution::None},
           {"smooth", ManufacturedSolution::Smooth},
           {"extension", ManufacturedSolution::Extension}},
          [](auto& c) -> auto& { return c.manufactured; })
          .constraint("not none: mesh.size divides 1")
          .doc("manufactured solution on the unit square with all-Dirichlet boundary and a body "
               "force (process and geometry, also geometry.symmetry, are then ignored): smooth = "
               "extension + vortex, "
               "extension = u = (x, −y) (patch test); none = the forming case"),
      enum_key(
          "verification.distortion", "none",
          {{"none", mesh::Distortion::None},
           {"smooth", mesh::Distortion::Smooth},
           {"random", mesh::Distortion::Random}},
          [](auto& c) -> auto& { return c.mesh.distortion.kind; })
          .doc("interior nodes of the verification box mesh: uniform squares, a fixed smooth map, "
               "or random offsets (non-affine cells)"),
      real_key(
          "verification.amplitude", 0.1,
          [](auto& c) -> auto& { return c.mesh.distortion.amplitude; })
          .at_least(0)
          .below(0.25)
          .constraint("≤ 0.1 with distortion = \"smooth\" (the map stays one-to-one)")
          .doc("distortion size: smooth = displacement amplitude / box side; random = "
               "largest offset / cell side"),
      integer_key(
          "verification.seed", 1, [](auto& c) -> auto& { return c.mesh.distortion.seed; })
          .at_least(0)
          .at_most(2147483647)
          .doc("seed of the random distortion (each mesh of a ladder draws its own offsets)"),
  };
}

} // namespace formflow::io::keys
