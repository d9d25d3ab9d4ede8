// SPDX-License-Identifier: MIT
// Physical groups of a Gmsh solid model (mesh/gmsh_solid_groups.hpp).
#include "formflow/mesh/gmsh_solid_groups.hpp"

#include <gmsh.h>

#include <string>

namespace formflow::mesh {

std::vector<int> boundary_surfaces() {
  std::vector<int> boundary;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    std::vector<int> up, down;
    gmsh::model::getAdjacencies(dim, tag, up, down);
    if (up.size() == 1) boundary.push_back(tag);
  }
  return boundary;
}

void add_solid_groups(const std::map<BoundaryLabel, std::vector<int>>& parts) {
  for (const auto& [label, tags] : parts)
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, tags),
                                 std::string(label_name(label)));
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  std::vector<int> volume_tags;
  for (const auto& [dim, tag] : volumes) volume_tags.push_back(tag);
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, volume_tags), "domain");
}

} // namespace formflow::mesh
