// SPDX-License-Identifier: MIT
// Writes the STEP file of cases/cad-conical-die.toml with Gmsh's OpenCASCADE API: the
// material region of a round billet through a conical die, as one solid.
//
//   build/formflow_make_cad_die cases/meshes/conical-die.step
//
// The solid (x the extrusion direction, the axis y = z = 0): the container x ∈ [0, 2] of
// radius 1, a 30° cone down to radius 1/√2 (half the area) and the exit x ∈ [.., +1].
// Its boundary surfaces, by the tags Gmsh gives them on import (the case maps them):
// the container's wall, the die's cone, the exit's wall, and the three discs.
#include <gmsh.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT.step\n", argv[0]);
    return 2;
  }
  const double container = 2.0, radius = 1.0, exit_radius = 1.0 / std::sqrt(2.0);
  const double cone = (radius - exit_radius) / std::tan(30.0 * std::numbers::pi / 180.0);
  const double exit_length = 1.0;
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("conical die");
  namespace occ = gmsh::model::occ;
  const int billet = occ::addCylinder(0, 0, 0, container, 0, 0, radius);
  const int die = occ::addCone(container, 0, 0, cone, 0, 0, radius, exit_radius);
  const int exit = occ::addCylinder(container + cone, 0, 0, exit_length, 0, 0, exit_radius);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> map;
  occ::fuse({{3, billet}}, {{3, die}, {3, exit}}, fused, map);
  occ::synchronize();
  gmsh::write(argv[1]);
  gmsh::finalize();
  return 0;
}
