// SPDX-License-Identifier: MIT
// Small meshes written to .msh through the Gmsh API, to test reading them back.
#pragma once

#include "formflow/mesh/gmsh_mesh.hpp"

#include <gmsh.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace formflow::testing {

/// A mesh given element by element: node tags start at 1; elements list Gmsh
/// node tags in Gmsh order; each named curve group lists its line elements.
struct TestMesh {
  std::vector<std::array<double, 2>> nodes;
  int element_type = 3; ///< Gmsh type: 3 quad-4, 10 quad-9, 16 quad-8, 2 triangle
  std::vector<std::vector<std::size_t>> elements;
  std::vector<std::pair<std::string, std::vector<std::array<std::size_t, 2>>>> curves;
};

/// Two unit squares side by side, [0, 2] × [0, 1], quad-4, with the curve groups
/// ram (x = 0), axis (y = 0), front (x = 2) and wall (y = 1).
inline TestMesh two_squares() {
  TestMesh mesh;
  mesh.nodes = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
  mesh.elements = {{1, 2, 5, 4}, {2, 3, 6, 5}};
  mesh.curves = {{"ram", {{{4, 1}}}},
                 {"axis", {{{1, 2}}, {{2, 3}}}},
                 {"front", {{{3, 6}}}},
                 {"wall", {{{6, 5}}, {{5, 4}}}}};
  return mesh;
}

/// Writes `mesh` as .msh 4.1 (discrete entities: one surface, one curve per group).
inline void write_test_mesh(const TestMesh& mesh, const std::string& path, bool binary = false) {
  mesh::GmshSession session;
  session.call([&] {
    gmsh::model::add("test");
    const int surface = gmsh::model::addDiscreteEntity(2);
    std::vector<std::size_t> tags;
    std::vector<double> coordinates;
    for (std::size_t k = 0; k < mesh.nodes.size(); ++k) {
      tags.push_back(k + 1);
      coordinates.insert(coordinates.end(), {mesh.nodes[k][0], mesh.nodes[k][1], 0.0});
    }
    gmsh::model::mesh::addNodes(2, surface, tags, coordinates);
    std::vector<std::size_t> element_tags, element_nodes;
    std::size_t next_element = 1;
    for (const auto& element : mesh.elements) {
      element_tags.push_back(next_element++);
      element_nodes.insert(element_nodes.end(), element.begin(), element.end());
    }
    gmsh::model::mesh::addElementsByType(surface, mesh.element_type, element_tags, element_nodes);
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "domain");
    for (const auto& [name, lines] : mesh.curves) {
      const int curve = gmsh::model::addDiscreteEntity(1);
      std::vector<std::size_t> line_tags, line_nodes;
      for (const auto& line : lines) {
        line_tags.push_back(next_element++);
        line_nodes.insert(line_nodes.end(), line.begin(), line.end());
      }
      gmsh::model::mesh::addElementsByType(curve, 1, line_tags, line_nodes);
      gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {curve}), name);
    }
  });
  mesh::write_gmsh_mesh(session, path, binary);
}

} // namespace formflow::testing
